// Readers for the Allan reference data in DRIFTLAB_SHARED_DIR/reference/allan (see its PROVENANCE.md):
// one-column data files (optionally gzip-compressed) and Stable32 result tables.
#pragma once

#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace driftlab::test {

inline std::filesystem::path allan_reference_dir() {
    return std::filesystem::path(DRIFTLAB_SHARED_DIR) / "reference" / "allan";
}

inline std::string read_text(const std::filesystem::path& path) {
    if (path.extension() == ".gz") {
        gzFile f = gzopen(path.c_str(), "rb");
        if (!f) throw std::runtime_error("cannot open " + path.string());
        std::string text;
        char buf[1 << 16];
        int got = 0;
        while ((got = gzread(f, buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(got));
        gzclose(f);
        if (got < 0) throw std::runtime_error("corrupt gzip stream in " + path.string());
        return text;
    }
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path.string());
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// First number of every non-comment line.
inline std::vector<double> read_column(const std::filesystem::path& path) {
    std::istringstream in(read_text(path));
    std::vector<double> v;
    std::string line;
    while (std::getline(in, line)) {
        const auto p = line.find_first_not_of(" \t\r");
        if (p == std::string::npos || line[p] == '#') continue;
        v.push_back(std::strtod(line.c_str() + p, nullptr));
    }
    return v;
}

/// One row of a Stable32 table: AF, Tau, #, Alpha, Min Sigma, Sigma, Max Sigma.
struct Stable32Row {
    std::int64_t m = 0;
    double tau_s = 0.0;
    std::int64_t n = 0;
    int alpha = 0;
    double dev_min = 0.0;
    double dev = 0.0;
    double dev_max = 0.0;
};

inline std::vector<Stable32Row> read_stable32(const std::filesystem::path& path) {
    std::istringstream in(read_text(path));
    std::vector<Stable32Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        const auto p = line.find_first_not_of(" \t\r");
        if (p == std::string::npos || line[p] == '#') continue;
        std::istringstream ls(line);
        Stable32Row r;
        if (ls >> r.m >> r.tau_s >> r.n >> r.alpha >> r.dev_min >> r.dev >> r.dev_max) rows.push_back(r);
    }
    return rows;
}

}  // namespace driftlab::test
