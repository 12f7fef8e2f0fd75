// The code histogram statistic; see code_density.hpp.
#include "host/gap/code_density.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace driftlab::host::gap {

namespace {

// Levels are pooled in bins of 1/8 count: the expected histogram moves by far less than its noise within one.
constexpr double kLevelBin = 0.125;

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

struct Histograms {
    long first_code = 0;
    std::vector<double> observed;                    ///< per code from first_code
    std::vector<std::pair<double, double>> levels;   ///< (level bin centre, rows)
};

// G2 of the observed codes against the ideal quantiser at noise deviation s.
double deviance(const Histograms& h, double s) {
    const std::size_t codes = h.observed.size();
    std::vector<double> expected(codes, 0.0);
    for (const auto& [level, rows] : h.levels) {
        double below = 0.0;  // P(code < c): the open lower end belongs to the first code
        for (std::size_t k = 0; k < codes; ++k) {
            const double edge = static_cast<double>(h.first_code + static_cast<long>(k)) + 0.5;
            const double upto = k + 1 == codes ? 1.0 : normal_cdf((edge - level) / s);
            expected[k] += rows * (upto - below);
            below = upto;
        }
    }
    double g2 = 0.0;
    for (std::size_t k = 0; k < codes; ++k)
        if (h.observed[k] > 0.0) g2 += 2.0 * h.observed[k] * std::log(h.observed[k] / std::max(expected[k], 1e-300));
    return g2;
}

}  // namespace

double code_density_excess(const std::vector<double>& raw, const std::vector<double>& level) {
    if (raw.size() != level.size() || raw.size() < 2) throw std::invalid_argument("code_density_excess: raw and level differ or are short");
    Histograms h;
    const auto [lo, hi] = std::minmax_element(raw.begin(), raw.end());
    h.first_code = std::lround(*lo);
    h.observed.assign(static_cast<std::size_t>(std::lround(*hi) - h.first_code + 1), 0.0);
    std::map<long, double> bins;
    double spread = 0.0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        h.observed[static_cast<std::size_t>(std::lround(raw[i]) - h.first_code)] += 1.0;
        bins[std::lround(level[i] / kLevelBin)] += 1.0;
        spread += (raw[i] - level[i]) * (raw[i] - level[i]);
    }
    const std::size_t codes = h.observed.size();
    if (codes < 3) return 0.0;  // one or two codes: nothing to compare the widths with
    for (const auto& [bin, rows] : bins) h.levels.emplace_back(static_cast<double>(bin) * kLevelBin, rows);
    // Golden-section search of ln s around the rows' own spread: G2 is smooth and single-dipped in s.
    const double s0 = std::max(0.1, std::sqrt(spread / static_cast<double>(raw.size())));
    double a = std::log(s0 / 4.0), b = std::log(s0 * 4.0);
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = deviance(h, std::exp(x1)), f2 = deviance(h, std::exp(x2));
    for (int it = 0; it < 30; ++it) {
        if (f1 < f2) {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - g * (b - a);
            f1 = deviance(h, std::exp(x1));
        } else {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + g * (b - a);
            f2 = deviance(h, std::exp(x2));
        }
    }
    return std::log1p(std::max(0.0, std::min(f1, f2)) / static_cast<double>(codes - 2));
}

}  // namespace driftlab::host::gap
