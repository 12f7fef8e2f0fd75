// The raw-code statistic and transition fit; see code_density.hpp.
#include "host/gap/code_density.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

namespace driftlab::host::gap {

namespace {

// Levels are pooled in bins of 1/8 count: the expected histogram moves by far less than its noise within one.
constexpr double kLevelBin = 0.125;

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// Minimum of a function single-dipped on [a, b], by golden section.
double golden_minimum(const std::function<double(double)>& f, double a, double b, int iterations) {
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < iterations; ++it) {
        if (f1 < f2) {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
    }
    return f1 < f2 ? x1 : x2;
}

struct Histograms {
    long first_code = 0;
    std::vector<double> observed;                   ///< per code from first_code
    std::vector<std::pair<double, double>> levels;  ///< (level bin centre, rows)
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

void check_rows(const std::vector<double>& raw, const std::vector<double>& level) {
    if (raw.size() != level.size() || raw.size() < 2)
        throw std::invalid_argument("raw codes and levels differ in length or are too short");
}

// The rows that hold a code: a negative one marks a row whose RAW frame was lost (the recorder writes -1), which no
// converter makes and which would stretch the histogram over hundreds of empty codes.
std::pair<std::vector<double>, std::vector<double>> coded_rows(const std::vector<double>& raw,
                                                               const std::vector<double>& level) {
    check_rows(raw, level);
    std::pair<std::vector<double>, std::vector<double>> out;
    for (std::size_t i = 0; i < raw.size(); ++i)
        if (raw[i] >= 0.0) out.first.push_back(raw[i]), out.second.push_back(level[i]);
    check_rows(out.first, out.second);
    return out;
}

// code_density() of rows that all hold a code.
CodeDensity density_of_coded(const std::vector<double>& raw, const std::vector<double>& level) {
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
    CodeDensity out;
    out.codes = static_cast<int>(h.observed.size());
    out.s = std::max(0.1, std::sqrt(spread / static_cast<double>(raw.size())));
    if (out.codes < 3) return out;  // one or two codes: nothing to compare the widths with
    for (const auto& [bin, rows] : bins) h.levels.emplace_back(static_cast<double>(bin) * kLevelBin, rows);
    // ln s around the rows' own spread: G2 is smooth and single-dipped in s.
    const double ln_s = golden_minimum([&](double x) { return deviance(h, std::exp(x)); }, std::log(out.s / 4.0),
                                       std::log(out.s * 4.0), 30);
    out.s = std::exp(ln_s);
    out.g2 = std::max(0.0, deviance(h, out.s));
    return out;
}

}  // namespace

CodeDensity code_density(const std::vector<double>& raw, const std::vector<double>& level) {
    const auto [coded_raw, coded_level] = coded_rows(raw, level);
    return density_of_coded(coded_raw, coded_level);
}

std::vector<double> neighbour_level(const std::vector<double>& codes, std::size_t half_width) {
    std::vector<double> out(codes.size(), 0.0);
    for (std::size_t i = 0; i < codes.size(); ++i) {
        const std::size_t lo = i >= half_width ? i - half_width : 0;
        const std::size_t hi = std::min(codes.size(), i + half_width + 1);
        double sum = 0.0;
        std::size_t n = 0;
        for (std::size_t k = lo; k < hi; ++k)
            if (k != i && codes[k] >= 0.0) sum += codes[k], ++n;
        out[i] = n > 0 ? sum / static_cast<double>(n) : codes[i];
    }
    return out;
}

double code_density_excess(const std::vector<double>& raw, const std::vector<double>& level) {
    const CodeDensity d = code_density(raw, level);
    return d.codes < 3 ? 0.0 : std::log1p(d.g2 / static_cast<double>(d.codes - 2));
}

TransitionFit fit_transitions(const std::vector<double>& all_raw, const std::vector<double>& all_level,
                              int min_each_side) {
    const auto [raw, level] = coded_rows(all_raw, all_level);
    const double s0 = density_of_coded(raw, level).s;
    // Per crossed transition, the rows within 4 s0 of its ideal place, pooled by level bin: (at or above j, below j).
    struct Crossing {
        long code;
        std::map<long, std::pair<double, double>> bins;
    };
    std::vector<Crossing> crossings;
    const auto [lo, hi] = std::minmax_element(raw.begin(), raw.end());
    for (long j = std::lround(*lo) + 1; j <= std::lround(*hi); ++j) {
        const double ideal = static_cast<double>(j) - 0.5;
        Crossing c{j, {}};
        int above = 0, below = 0;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (std::abs(level[i] - ideal) > 4.0 * s0) continue;
            const bool up = std::lround(raw[i]) >= j;
            auto& b = c.bins[std::lround(level[i] / kLevelBin)];
            (up ? b.first : b.second) += 1.0;
            (up ? above : below) += 1;
        }
        if (above >= min_each_side && below >= min_each_side) crossings.push_back(std::move(c));
    }
    // The probit of one transition at deviation s: its place and negative log-likelihood.
    const auto place = [](const Crossing& c, double s) {
        const double ideal = static_cast<double>(c.code) - 0.5;
        const auto nll = [&](double t) {
            double sum = 0.0;
            for (const auto& [bin, n] : c.bins) {
                const double z = (static_cast<double>(bin) * kLevelBin - t) / s;
                sum -= n.first * std::log(std::max(normal_cdf(z), 1e-300)) +
                       n.second * std::log(std::max(normal_cdf(-z), 1e-300));
            }
            return sum;
        };
        const double t = golden_minimum(nll, ideal - 0.999, ideal + 0.999, 40);
        return std::make_pair(t, nll(t));
    };
    // s is shared by every transition (the noise does not depend on the code): profile it. Fitted under an ideal
    // quantiser, as code_density() does, it would absorb the very width differences sought.
    TransitionFit out;
    out.s = s0;
    if (!crossings.empty()) {
        const auto total = [&](double ln_s) {
            double sum = 0.0;
            for (const auto& c : crossings) sum += place(c, std::exp(ln_s)).second;
            return sum;
        };
        out.s = std::exp(golden_minimum(total, std::log(s0 / 3.0), std::log(s0 * 3.0), 30));
    }
    for (const auto& c : crossings) {
        double t = place(c, out.s).first;
        // At the end of its range the likelihood was still rising: the rows do not place this transition.
        if (std::abs(t - (static_cast<double>(c.code) - 0.5)) > 0.99) continue;
        if (!out.transitions.empty() && t <= out.transitions.back().counts) t = out.transitions.back().counts + 1e-3;
        out.transitions.push_back({c.code, t});
    }
    return out;
}

}  // namespace driftlab::host::gap
