// Field splitting; see split_fields.hpp.
#include "host/util/split_fields.hpp"

namespace driftlab::host {

void split_fields(std::string_view line, char sep, std::vector<std::string_view>& out) {
    out.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t pos = line.find(sep, start);
        if (pos == std::string_view::npos) {
            out.push_back(line.substr(start));
            return;
        }
        out.push_back(line.substr(start, pos - start));
        start = pos + 1;
    }
}

void split_numeric_fields(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    const auto is_blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    std::size_t i = 0;
    const std::size_t n = line.size();
    while (i < n && is_blank(line[i])) ++i;
    if (i == n) return;
    while (true) {
        const std::size_t start = i;
        while (i < n && !is_blank(line[i]) && line[i] != ',') ++i;
        out.push_back(line.substr(start, i - start));
        while (i < n && is_blank(line[i])) ++i;
        if (i == n) return;
        if (line[i] == ',') {
            ++i;
            while (i < n && is_blank(line[i])) ++i;
            if (i == n) {
                out.push_back(line.substr(n));
                return;
            }
        }
    }
}

}  // namespace driftlab::host
