// The real single-axis MEMS gyro recording (shared/data/real/gyro2_x.txt, PROVENANCE.md): the diagnosis runs
// and says what it finds, and an injected sinusoid is recovered at about its size on top of the unknown real
// effects. The 8.75 mdps/LSB values become counts around mid-scale; blocks of 40 samples are the order-0
// smoother of the log (window = conversions per output = 40), at an assumed 100 Hz raw rate.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "host/gap/diagnose.hpp"
#include "host/log/log_window.hpp"
#include "host/view/gap_view.hpp"

#include "gap_fixtures.hpp"

namespace driftlab::host::gap {
namespace {

// The log, and the unit it reads as (one count is 8.75 mdps: the parameters come out in the gyro's own deg/s).
bool load_gyro2_x(LogData& log, sim::SimModel& unit) {
    return testing::load_shared_recording("gyro2_x.txt", {"gyro=col1:0.00875"}, 0.01, 40, log, unit);
}

GapOptions options() { return testing::real_data_options(2); }

TEST(RealData, Gyro2xRunsAndReportsItsGap) {
    LogData log;
    sim::SimModel unit;
    if (!load_gyro2_x(log, unit))
        GTEST_SKIP() << "shared/data/real/gyro2_x.txt not found under " << DRIFTLAB_SHARED_DIR;
    const GapResult r = diagnose(log, unit, options());
    std::printf("gyro2_x: verdict %s, gap fit %.2f heldout %.2f -> fit %.2f heldout %.2f, %zu located\n",
                r.verdict.c_str(), r.gap_before_fit, r.gap_before_heldout, r.gap_after_fit, r.gap_after_heldout,
                r.located.size());
    for (const auto& e : r.accepted) {
        std::printf("  accepted %s:", e.effect.c_str());
        for (const auto& [k, v] : e.params) std::printf(" %s=%.4g", k.c_str(), v);
        std::printf(" heldout shrink %.2f\n", e.heldout_shrink);
    }
    for (const auto& s : r.level_steps)
        std::printf(
            "  level steps %.2f counts at %.1f s, %.2f at %.1f s: rival %.1f (price %.1f, p %.3f), impulse %.2f (p "
            "%.3f), "
            "p %.3f; processes beside them %.1f (price %.1f)%s\n",
            s.steps[0].size_counts, s.steps[0].t_s, s.steps[1].size_counts, s.steps[1].t_s, s.statistic, s.margin,
            s.rival_p, s.impulse, s.impulse_p, s.p_value, s.process_gain, s.process_margin,
            s.outsized ? ": outsized increments" : "");
    EXPECT_TRUE(std::isfinite(r.gap_before_fit));
    // What follows, up to the warm-up's sign, is a regression snapshot of what the diagnosis found on this recording
    // (docs/gap-results.md, Real recordings), not an independent truth: no one knows this unit's effects. The 155 s
    // excursion at 983-1139 s is beyond the two processes' own replicates, but they remain beside it: it is reported as
    // their outsized increments (JSON level_steps[]) and does not leave the log unexplained.
    const auto j = view::gap_to_json(r, options());
    ASSERT_EQ(j["level_steps"].size(), 1u);  // the gyro, with two processes and no mean shape
    for (const auto& s : j["level_steps"]) {
        EXPECT_LE(s["p"].get<double>(), 0.05);
        EXPECT_GT(s["process_gain"].get<double>(), s["process_margin"].get<double>());
        EXPECT_TRUE(s["outsized_increments"].get<bool>());
        EXPECT_FALSE(s["significant"].get<bool>());
    }
    EXPECT_NE(r.verdict, "unexplained");
    // The warm-up is falling (1.10 -> 0.64 deg/s, PROVENANCE.md): eq. 1 calibrates a negative C1.
    EXPECT_LT(r.base.base[0].drift.c1_counts, 0.0);
    EXPECT_GT(r.base.base[0].sigma_n_counts, 5.0);  // 0.465 deg/s spread is about 53 LSB raw
    if (!r.accepted.empty()) {
        EXPECT_LE(r.gap_after_heldout, r.gap_before_heldout);
    } else {
        EXPECT_TRUE(r.verdict == "none" || r.verdict == "unexplained");
    }
}

// Is the Gauss-Markov reading the excursion's? Left out (--exclude 975:1150, rows_outside()), the excursion takes
// most of the fitting part's gap with it (it lies in tenth 4, a fitting tenth), while the held-out part, which never
// held it, still needs the process: the verdict does not rest on the excursion.
TEST(RealData, TheGaussMarkovReadingDoesNotRestOnTheExcursion) {
    LogData whole;
    sim::SimModel unit;
    if (!load_gyro2_x(whole, unit))
        GTEST_SKIP() << "shared/data/real/gyro2_x.txt not found under " << DRIFTLAB_SHARED_DIR;
    const GapResult all = diagnose(whole, unit, options());
    const LogData log = rows_outside(whole, {{975.0, 1150.0, "--exclude"}});
    const GapResult r = diagnose(log, unit, options());
    std::printf(
        "gyro2_x without 975-1150 s: verdict %s, gap fit %.2f heldout %.2f (whole log %.2f, %.2f) -> fit %.2f heldout "
        "%.2f\n",
        r.verdict.c_str(), r.gap_before_fit, r.gap_before_heldout, all.gap_before_fit, all.gap_before_heldout,
        r.gap_after_fit, r.gap_after_heldout);
    ASSERT_EQ(r.left_out.size(), 1u);
    EXPECT_NEAR(static_cast<double>(r.left_out[0].rows), 175.0 / 0.4, 2.0);  // an output every 0.4 s
    EXPECT_EQ(r.timing.sequence_jumps, 0u);
    EXPECT_LT(r.gap_before_fit, 0.5 * all.gap_before_fit);
    EXPECT_GT(r.gap_before_heldout,
              0.5 * all.gap_before_heldout);  // the tenths shift by the rows left out; the gap stays
    EXPECT_EQ(r.verdict, "gauss_markov");
    ASSERT_FALSE(r.accepted.empty());
    EXPECT_GT(r.accepted[0].heldout_shrink, 0.7);
}

// Injection-recovery with the default (interleaved) design and every candidate: the real log's own coloured noise
// is explained first (step 1, a Gauss-Markov process); the injected sinusoid must then be accepted as
// ambient_cycle at its period and about its size. This needs the stepwise refit: the Gauss-Markov process sized
// on the log with the sinusoid in it swallows part of the line until it is fitted again beside it. The line is
// 8 counts at 120 s, about 100 times the log's own noise power in its frequency bin; at 300 s, where that noise is
// six times stronger, a 4-count line is not separable from it (docs/gap-results.md, Real recordings).
TEST(RealData, InjectedSinusoidIsRecoveredAtItsSize) {
    LogData log;
    sim::SimModel unit;
    if (!load_gyro2_x(log, unit))
        GTEST_SKIP() << "shared/data/real/gyro2_x.txt not found under " << DRIFTLAB_SHARED_DIR;
    const double amplitude = 8.0, period_s = 120.0, phase = 0.5;
    for (std::size_t k = 0; k < log.size(); ++k)
        log.counts[0][k] += amplitude * std::sin(2.0 * std::numbers::pi * log.t_s[k] / period_s + phase);
    const GapResult r = diagnose(log, unit, options());
    const Explanation* found = nullptr;
    for (const auto& e : r.accepted)
        if (e.effect == "ambient_cycle") found = &e;
    ASSERT_NE(found, nullptr) << "verdict " << r.verdict;
    const double counts_per_dps = 1.0 / 0.00875;  // the recording's own scale
    std::printf("injected 8 counts at 120 s: recovered %.2f counts at %.1f s (step %d)\n",
                found->params[0].second * counts_per_dps, found->params[1].second, found->step);
    EXPECT_NEAR(found->params[0].second * counts_per_dps / amplitude, 1.0, 0.2);
    EXPECT_NEAR(found->params[1].second / period_s, 1.0, 0.02);
}

}  // namespace
}  // namespace driftlab::host::gap
