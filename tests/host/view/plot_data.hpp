// Reads back the data a plot was drawn from (host/view/gnuplot writes one block per series, separated by two
// blank lines), so that tests check the numbers behind a figure.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace driftlab::host::gap::testing {

/// The rows of data block `index` of a gnuplot .dat file.
inline std::vector<std::vector<double>> plot_block(const std::filesystem::path& path, int index) {
    std::ifstream in(path);
    std::vector<std::vector<double>> rows;
    std::string line;
    int at = 0, blank = 0;
    while (std::getline(in, line)) {
        if (line.empty()) {
            if (++blank == 2) ++at;
            continue;
        }
        blank = 0;
        if (at != index) continue;
        std::istringstream row(line);
        std::vector<double> v;
        for (double x; row >> x;) v.push_back(x);
        rows.push_back(v);
    }
    return rows;
}

}  // namespace driftlab::host::gap::testing
