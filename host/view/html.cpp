// HTML helpers; see html.hpp.
#include "host/view/html.hpp"

#include <cmath>

#include "host/util/format_number.hpp"

namespace driftlab::host::view {

std::string html_escape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string sig(double value, int digits) { return std::isfinite(value) ? significant(value, digits) : "-"; }

std::string fixed(double value, int decimals) { return std::isfinite(value) ? fixed_point(value, decimals) : "-"; }

}  // namespace driftlab::host::view
