// The raw-code histogram statistic: about ln 2 for an ideal converter (its deviance is about its degrees of
// freedom), far above for a widened code or a missing one, and blind to the drift and the noise level; and the
// transitions it places, on the true level and on the smoothed output's.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/gap/code_density.hpp"
#include "sim/effects/adc_dnl.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {
namespace {

struct Rows {
    std::vector<double> raw, level;
};

// A level drifting over a few codes with Gaussian noise of `sigma` counts, through a quantiser whose transition
// into code `moved_code` sits `shift` LSB above the ideal one (a code below it wider, it narrower).
Rows rows(std::size_t n, double sigma, unsigned seed, long moved_code = 0, double shift = 0.0) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    Rows r;
    for (std::size_t k = 0; k < n; ++k) {
        const double level = 505.0 + 3.0 * (1.0 - std::exp(-static_cast<double>(k) / 400.0));
        const double x = level + noise(rng);
        double code = std::floor(x + 0.5);
        if (code == static_cast<double>(moved_code) && x - (static_cast<double>(moved_code) - 0.5) < shift) code -= 1.0;
        r.raw.push_back(code);
        r.level.push_back(level);
    }
    return r;
}

// The level of outputs that are codes: each row's neighbours' mean without itself, fewer at the ends.
TEST(CodeDensity, TheNeighbourLevelLeavesTheRowItselfOut) {
    const std::vector<double> codes{10, 12, 11, 13, 100};
    const std::vector<double> level = neighbour_level(codes, 2);
    EXPECT_DOUBLE_EQ(level[0], (12.0 + 11.0) / 2.0);
    EXPECT_DOUBLE_EQ(level[2], (10.0 + 12.0 + 13.0 + 100.0) / 4.0);
    EXPECT_DOUBLE_EQ(level[4], (11.0 + 13.0) / 2.0);
    // A lost code (negative) is nobody's neighbour.
    EXPECT_DOUBLE_EQ(neighbour_level({5, -1, 7}, 1)[0], 5.0);
    EXPECT_DOUBLE_EQ(neighbour_level({5, -1, 7}, 1)[1], 6.0);
}

// Against its neighbours' mean, an ideal converter's codes give a deviance near their degrees of freedom as against
// the true level, and a widened code stands out: the codes cell works on outputs that are codes.
TEST(CodeDensity, AgainstTheNeighboursAnIdealConverterIsIdealAndAWideCodeStandsOut) {
    const Rows ideal = rows(6000, 0.8, 21);
    const Rows moved = rows(6000, 0.8, 21, 507, 0.35);
    const double ideal_excess = code_density_excess(ideal.raw, neighbour_level(ideal.raw));
    const double moved_excess = code_density_excess(moved.raw, neighbour_level(moved.raw));
    EXPECT_LT(ideal_excess, std::log(4.0));
    EXPECT_GT(moved_excess, ideal_excess + std::log(4.0));
}

TEST(CodeDensity, AnIdealConverterGivesADevianceNearItsDegreesOfFreedom) {
    double sum = 0.0;
    for (unsigned seed = 1; seed <= 40; ++seed) {
        const Rows r = rows(1500, 1.05, seed);
        sum += std::expm1(code_density_excess(r.raw, r.level));
    }
    // The mean of G2/df over 40 logs: about 1, a little above for the sparse end codes and the fitted deviation (1.12
    // on these seeds). One log's G2/df scatters by 0.57, so the mean by 0.09: 0.6-1.4 is 4 of that either side of 1.
    EXPECT_GT(sum / 40.0, 0.6);
    EXPECT_LT(sum / 40.0, 1.4);
}

// A raw-mode log over a lossy link marks a row whose RAW frame was lost with code -1: those rows hold no code, and
// the statistic and the transitions are those of the other rows exactly (with them, the histogram would run from -1
// over hundreds of empty codes).
TEST(CodeDensity, RowsOfALostRawFrameHoldNoCode) {
    const Rows r = rows(1500, 1.05, 7);
    Rows lossy = r;
    for (std::size_t k : {3u, 400u, 401u, 1200u}) lossy.raw[k] = -1.0;
    Rows kept;
    for (std::size_t k = 0; k < r.raw.size(); ++k)
        if (lossy.raw[k] >= 0.0) kept.raw.push_back(r.raw[k]), kept.level.push_back(r.level[k]);
    EXPECT_EQ(code_density_excess(lossy.raw, lossy.level), code_density_excess(kept.raw, kept.level));
    const CodeDensity d = code_density(lossy.raw, lossy.level);
    EXPECT_EQ(d.codes, code_density(kept.raw, kept.level).codes);
    EXPECT_LT(d.codes, 20);
    const TransitionFit a = fit_transitions(lossy.raw, lossy.level), b = fit_transitions(kept.raw, kept.level);
    ASSERT_EQ(a.transitions.size(), b.transitions.size());
    for (std::size_t k = 0; k < a.transitions.size(); ++k) EXPECT_EQ(a.transitions[k].counts, b.transitions[k].counts);
}

TEST(CodeDensity, AWidenedCodeStandsOut) {
    double ideal = 0.0, moved = 0.0;
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const Rows a = rows(1500, 1.05, seed);
        const Rows b = rows(1500, 1.05, seed, 507, 0.3);  // code 506 0.3 LSB wider, 507 narrower
        ideal += code_density_excess(a.raw, a.level);
        moved += code_density_excess(b.raw, b.level);
    }
    EXPECT_GT(moved / 10.0, ideal / 10.0 + 1.0);  // G2/df about 10 against 1.2 (ln: 2.4 against 0.8)
}

TEST(CodeDensity, AMissingCodeStandsOut) {
    const Rows r = rows(1500, 1.05, 3, 507, 1.0);  // code 507 never occurs
    EXPECT_GT(std::expm1(code_density_excess(r.raw, r.level)), 10.0);
}

// The probit fit puts each crossed transition where the rows say it is: the moved one 0.3 LSB above its ideal
// place, the others at theirs. Transitions with 200 rows a side come within 0.1 LSB; those at the edges of the
// range, which fewer rows reach, within 0.25.
TEST(CodeDensity, TransitionsAreFoundWhereTheConverterHasThem) {
    for (unsigned seed : {7u, 8u, 9u}) {
        const Rows r = rows(3000, 1.05, seed, 507, 0.3);
        const auto truth = [](long code) { return static_cast<double>(code) - 0.5 + (code == 507 ? 0.3 : 0.0); };
        const TransitionFit fit = fit_transitions(r.raw, r.level);
        EXPECT_NEAR(fit.s, 1.05, 0.08) << "the shared deviation, not widened by the moved transition";
        ASSERT_GE(fit.transitions.size(), 5u);
        for (const auto& t : fit.transitions)
            EXPECT_NEAR(t.counts, truth(t.code), 0.25) << "seed " << seed << ", code " << t.code;
        for (std::size_t k = 1; k < fit.transitions.size(); ++k)
            EXPECT_GT(fit.transitions[k].counts, fit.transitions[k - 1].counts);
        const TransitionFit well = fit_transitions(r.raw, r.level, 200);
        ASSERT_LT(well.transitions.size(), fit.transitions.size());
        bool moved_seen = false;
        for (const auto& t : well.transitions) {
            EXPECT_NEAR(t.counts, truth(t.code), 0.1) << "seed " << seed << ", code " << t.code;
            moved_seen |= t.code == 507;
        }
        EXPECT_TRUE(moved_seen);
    }
}

// Against the smoothed output (what a log gives), the transitions sit on the output's scale, which counts codes: the
// codes a log crosses average one count wide there, so each fitted width is the converter's divided by the mean width
// of the codes crossed (where they are narrow the output moves faster than the input). Per log, ln(sum of fitted
// widths / sum of the converter's) against ln(1 / that mean) has slope 1 (0 if the widths were the converter's), and
// dividing the converter's widths by the mean leaves only the noise of the fit.
TEST(CodeDensity, AgainstTheSmoothedOutputTheWidthsAreTheConvertersOverTheirMeanWidth) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, raw_sq = 0, scaled_sum = 0, scaled_sq = 0;
    int logs = 0, widths = 0;
    for (int pattern = 1; pattern <= 40; ++pattern) {
        GapModel m = testing::paper_gyro_model(8);
        const std::string spec = "dnl_rms_lsb = 0.3\npattern_seed = " + std::to_string(pattern);
        m.effects.push_back({"adc_dnl", toml::parse(spec)});
        LogData log = testing::gyro_log(m, 1500, {}, 100 + static_cast<std::uint64_t>(pattern));
        sim::Outputs raw;
        sim::OutputRequest req;
        req.t_s = &log.t_s;
        req.channels = {true, false, false, false};
        req.raw_codes = &raw;
        const std::vector<double> output = sim::simulate_outputs(m, req, 100 + static_cast<std::uint64_t>(pattern))[0];
        const TransitionFit fit = fit_transitions(raw[0], output);
        sim::AdcDnlParams truth;
        truth.dnl_rms_lsb = 0.3;
        truth.pattern_seed = static_cast<std::uint64_t>(pattern);
        const sim::AdcDnl converter(truth);
        const auto at = [&](long code) { return converter.transition_counts(static_cast<int>(code)); };
        ASSERT_GE(fit.transitions.size(), 2u) << "pattern " << pattern;
        const long lo = fit.transitions.front().code, hi = fit.transitions.back().code;
        const double mean_width = (at(hi) - at(lo)) / static_cast<double>(hi - lo);
        double fitted_sum = 0, true_sum = 0;
        for (std::size_t k = 1; k < fit.transitions.size(); ++k) {
            const long code = fit.transitions[k].code;
            if (code != fit.transitions[k - 1].code + 1) continue;
            const double fitted = fit.transitions[k].counts - fit.transitions[k - 1].counts,
                         width = at(code) - at(code - 1);
            fitted_sum += fitted, true_sum += width;
            const double r = std::log(fitted / width);
            raw_sq += r * r;
            scaled_sum += r + std::log(mean_width), scaled_sq += std::pow(r + std::log(mean_width), 2);
            ++widths;
        }
        if (true_sum == 0) continue;
        const double x = -std::log(mean_width), y = std::log(fitted_sum / true_sum);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        ++logs;
    }
    ASSERT_GE(logs, 35);
    const double slope = (sxy - sx * sy / logs) / (sxx - sx * sx / logs);
    EXPECT_NEAR(slope, 1.0, 0.25);
    EXPECT_NEAR(scaled_sum / widths, 0.0, 0.05) << "no bias left once divided by the mean width";
    EXPECT_LT(std::sqrt(scaled_sq / widths), 0.8 * std::sqrt(raw_sq / widths));
}

TEST(CodeDensity, OneOrTwoCodesCarryNoWidthInformation) {
    EXPECT_EQ(code_density_excess({5, 5, 6, 6}, {5.4, 5.4, 5.6, 5.6}), 0.0);
    EXPECT_THROW(code_density_excess({5, 6}, {5.5}), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::gap
