// What the terminal and the report show of a diagnosis, apart from the numbers it decides with: the verdict's
// shrink said as the channel's own, the candidate table's order, a located cell's digits, the cells' text, and the
// files a report may write (an input among them is refused).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../gap/gap_fixtures.hpp"
#include "host/gap/statistics.hpp"
#include "host/gap/verdict_stability.hpp"
#include "host/util/units.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"

namespace driftlab::host::gap {
namespace {

Explanation candidate(const std::string& effect, int step, bool accepted, double shrink) {
    Explanation e;
    e.effect = effect;
    e.channel = "gyro";
    e.step = step;
    e.accepted = accepted;
    e.heldout_shrink = shrink;
    return e;
}

// A diagnosis that added one effect on the gyro, with its channel's held-out scores and the whole log's after it.
GapResult one_added(const std::string& effect, double shrink, double heldout_before, double heldout_after,
                    double gap_after, double bound) {
    GapResult r;
    Explanation e = candidate(effect, 1, true, shrink);
    e.heldout_before = heldout_before, e.heldout_after = heldout_after;
    r.accepted.push_back(e);
    r.gap_after_heldout = gap_after, r.gap_bound_after = bound;
    return r;
}

// The reviewer's log: the verdict's "100 % (248.17 -> 2.13)" stood beside the gap table's whole-log 47.82 -> 0.99
// without saying it was the gyro's own score, or what the share is of.
TEST(GapReport, TheVerdictSaysWhoseHeldOutScoreItShrinksAndHow) {
    const GapResult r = one_added("ambient_cycle", 0.9946, 248.17, 2.13, 0.99, 1.24);
    const std::string reason = view::verdict_reason(r, GapOptions{});
    EXPECT_EQ(
        reason.rfind("on gyro it removes 99 % of gyro's own held-out gap excess (gyro's held-out score 248.17 -> 2.13; "
                     "shrink = (before - after) / (before - 1); the whole log's scores are below); the gap closes",
                     0),
        0u)
        << reason;
}

// A gap left open at the step limit: the verdict says the search stopped there, and whether --max-effects or the
// search's own limit did; a gap left open below the limit says nothing of it (no step was refused by the limit).
TEST(GapReport, AGapLeftOpenAtTheStepLimitSaysTheSearchStoppedThere) {
    GapResult r = one_added("rate_random_walk", 0.8, 9.0, 2.6, 2.6, 1.3);
    GapOptions one;
    one.explain_options.max_effects = 1;
    EXPECT_NE(view::verdict_reason(r, one).find(
                  "; the held-out gap stays above its bound after 1 effect, the most --max-effects allows"),
              std::string::npos)
        << view::verdict_reason(r, one);
    const std::string below_limit = view::verdict_reason(r, GapOptions{});
    EXPECT_NE(below_limit.find("; the held-out gap stays above its bound"), std::string::npos) << below_limit;
    EXPECT_EQ(below_limit.find(" the most "), std::string::npos) << below_limit;
    for (int k = 2; k <= 3; ++k) r.accepted.push_back(candidate("flicker", k, true, 0.5));
    EXPECT_NE(
        view::verdict_reason(r, GapOptions{}).find("stays above its bound after 3 effects, the most the search adds"),
        std::string::npos)
        << view::verdict_reason(r, GapOptions{});
    r.gap_after_heldout = 1.1;  // closed: no limit to speak of
    EXPECT_EQ(view::verdict_reason(r, GapOptions{}).find(" the most "), std::string::npos)
        << view::verdict_reason(r, GapOptions{});
}

// A later step taken while the channel's held-out score lay within its bound is said so in the verdict, where the
// first, taken on a score beyond it, is not: a score at the bound counts as within it.
TEST(GapReport, AStepTakenWithTheHeldOutScoreWithinItsBoundIsMarkedSo) {
    GapResult r = one_added("gauss_markov", 0.97, 28.26, 1.70, 1.32, 3.44);
    r.accepted.front().heldout_bound = 2.9;
    Explanation second = candidate("thermal_second_tc", 2, true, 0.54);
    second.heldout_before = 1.70, second.heldout_after = 1.32, second.heldout_bound = 2.80;
    r.accepted.push_back(second);
    const std::string marked =
        "; then thermal_second_tc on gyro (added with the held-out score already within its bound); the gap closes";
    const std::string reason = view::verdict_reason(r, GapOptions{});
    EXPECT_NE(reason.find(marked), std::string::npos) << reason;
    EXPECT_GT(reason.find("within its bound"), reason.find(marked)) << "the first step is not marked: " << reason;
    r.accepted.back().heldout_bound = 1.70;
    EXPECT_NE(view::verdict_reason(r, GapOptions{}).find(marked), std::string::npos) << "at the bound";
    r.accepted.back().heldout_bound = 1.69;
    EXPECT_EQ(view::verdict_reason(r, GapOptions{}).find("within its bound"), std::string::npos)
        << view::verdict_reason(r, GapOptions{});
}

// The diagnosis holds its candidates passed first, then by shrink (a step-3 effect above a step-2 one); the table
// lists the added in step order, then the others by step, each step's as the diagnosis held them.
TEST(GapReport, TheCandidateTableListsTheAddedInStepOrderThenTheOthersByStep) {
    GapResult r;
    r.tried = {candidate("rate_random_walk", 1, true, 1.0),    candidate("ambient_cycle", 1, true, 0.99),
               candidate("thermal_second_tc", 3, true, 0.66),  candidate("rate_random_walk", 2, true, 0.46),
               candidate("thermal_second_tc", 1, false, 0.37), candidate("flicker", 2, false, 0.01),
               candidate("gauss_markov", 1, false, 0.0),       candidate("flicker", 3, false, -0.49)};
    r.accepted = {r.tried[1], r.tried[3], r.tried[2]};  // in the order they were added
    std::vector<std::string> order;
    for (const Explanation* e : view::candidates_in_table_order(r))
        order.push_back(std::to_string(e->step) + " " + e->effect);
    const std::vector<std::string> expected{
        "1 ambient_cycle",     "2 rate_random_walk", "3 thermal_second_tc", "1 rate_random_walk",
        "1 thermal_second_tc", "1 gauss_markov",     "2 flicker",           "3 flicker"};
    EXPECT_EQ(order, expected);
}

// "ratio 173.285 [27.075, 1109.073]": three decimals whatever the interval. The digits now follow the interval.
// A second time constant at five times the log (the search's longest) is no measurement: the text says so and gives
// the slope c3/t2 the log does tell; one within three times the log is shown as it is (the rule fit's T follows).
TEST(GapReport, ASecondTimeConstantBeyondTheRecordIsSaidToBeOneWithItsSlope) {
    Explanation e;
    e.effect = "thermal_second_tc";
    e.params = {{"c3_dps", -0.22}, {"t2_s", 7500.0}};
    e.whole_log_params = {{"c3_dps", -0.075}, {"t2_s", 7500.0}};
    const std::string beyond = view::estimate_text(e, 1500.0);
    EXPECT_NE(beyond.find("c3_dps=-0.075 t2_s=7500 (whole log; fitting part: c3_dps=-0.22 t2_s=7500)"),
              std::string::npos)
        << beyond;
    EXPECT_NE(beyond.find("t2 is beyond 3x the log's 1500 s"), std::string::npos) << beyond;
    EXPECT_NE(beyond.find("initial slope, -0.00001 deg/s per s"), std::string::npos)
        << beyond;  // -0.075 / 7500, no exponent
    e.whole_log_params = {{"c3_dps", -0.075}, {"t2_s", 4000.0}};
    EXPECT_EQ(view::estimate_text(e, 1500.0).find("beyond"), std::string::npos) << view::estimate_text(e, 1500.0);
    e.effect = "gauss_markov";
    e.whole_log_params = {{"sigma_dps", 0.02}, {"tau_s", 9000.0}};
    EXPECT_EQ(view::estimate_text(e, 1500.0).find("beyond"), std::string::npos);
}

// The whole-log estimate can give a process none of the signal beside the others (a walk of 3.8e-10 deg/s/sqrt(s)
// where the fitting part had 4.5e-4): said, since it is no size to copy into a model.
TEST(GapReport, ASizeTheWholeLogSetsToNearlyNothingIsSaidToBeSo) {
    Explanation e;
    e.effect = "rate_random_walk";
    e.params = {{"k_dps_per_sqrt_s", 4.543e-4}};
    e.whole_log_params = {{"k_dps_per_sqrt_s", 3.804e-10}};
    EXPECT_NE(view::estimate_text(e, 1500.0).find("its k_dps_per_sqrt_s is under 1 % of the fitting part's"),
              std::string::npos)
        << view::estimate_text(e, 1500.0);
    e.whole_log_params = {{"k_dps_per_sqrt_s", 2e-4}};
    EXPECT_EQ(view::estimate_text(e, 1500.0).find("under 1 %"), std::string::npos) << view::estimate_text(e, 1500.0);
}

// A `none` verdict on a log shorter than twice eq. 1's T: the drift fit bends across the whole log and could have
// taken a slow effect with it. Said for the analysed channels with T at least half the span, for `none` alone.
TEST(GapReport, ANoneVerdictSaysWhenEq1IsSlowEnoughToAbsorbASlowEffect) {
    GapResult r;
    r.verdict = "none";
    r.channels = {true, true, false, false};
    r.base.base[0].drift.tau_s = 411.0;   // the paper's gyro: settled within 1500 s
    r.base.base[1].drift.tau_s = 953.0;   // the paper's accel_x: over half of 1500 s
    r.base.base[2].drift.tau_s = 5000.0;  // not analysed
    LogData log;
    log.t_s = {0.0, 1.0, 1500.0};
    const std::string slow = view::slow_drift_sentence(r, log);
    EXPECT_EQ(
        slow.rfind(
            "the paper's drift model, eq. 1: C1(1 - e^(-t/T)) + C2, is fitted with T = 953 s on accel_x, at least "
            "half the log's 1500 s, so it still bends at the log's end",
            0),
        0u)
        << slow;
    EXPECT_NE(slow.find("taken up by the drift fit"), std::string::npos) << slow;
    log.t_s = {0.0, 1.0, 4000.0};  // Fig. 3's length: both settle within it
    EXPECT_EQ(view::slow_drift_sentence(r, log), "");
    log.t_s = {0.0, 1.0, 1500.0};
    r.verdict = "gauss_markov";  // an effect was added: the gap was found, not absorbed
    EXPECT_EQ(view::slow_drift_sentence(r, log), "");
}

TEST(GapReport, ALocatedCellShowsTheDigitsItsIntervalWarrants) {
    LocatedCell wide;
    wide.ratio = 173.285, wide.interval_low = 27.075, wide.interval_high = 1109.073;
    EXPECT_EQ(view::located_value_text(wide), "ratio 170 [30, 1110]");  // the half-width 541: a last digit at 10
    LocatedCell narrow;
    narrow.ratio = std::nan(""), narrow.difference = 0.3063, narrow.interval_low = 0.2957,
    narrow.interval_high = 0.3169;
    EXPECT_EQ(view::located_value_text(narrow), "diff 0.306 [0.296, 0.317]");
}

// A mean cell's difference is in counts, which a user reads in the channel's unit: the paper's gyro has 90/512 deg/s
// per count. Other cells (an autocorrelation, a ratio) have no unit.
TEST(GapReport, AMeanCellsDifferenceIsAlsoInTheChannelsUnit) {
    GapResult r;
    r.base = testing::paper_gyro_model(8);
    Cell mean;
    mean.statistic = "mean", mean.channel = "gyro";
    Cell acf = mean;
    acf.statistic = "acf";
    r.layout = {mean, acf};
    LocatedCell l;
    l.index = 0, l.ratio = std::nan(""), l.difference = 0.783, l.interval_low = 0.744, l.interval_high = 0.823;
    EXPECT_NEAR(0.783 * kGyroDpsPerCount, 0.1376, 1e-4);  // to three digits 0.138
    EXPECT_EQ(view::located_cell_text(r, l), "diff 0.783 [0.744, 0.823] counts (0.138 deg/s)");
    l.index = 1;
    EXPECT_EQ(view::located_cell_text(r, l), "diff 0.783 [0.744, 0.823]");
}

// The JSON's cell keys keep their three significant digits; the text shows no exponent and a band of one lag as that
// lag.
TEST(GapReport, ACellsTextHasNoExponentAndALagBandOfOneLagIsThatLag) {
    std::vector<double> t(1500), y(1500);
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = 1.098 + static_cast<double>(k);
        y[k] = 500.0 + 0.25 * static_cast<double>((k * 7919) % 13);
    }
    BatteryOptions o;
    o.channels = {true, false, false, false};
    std::vector<Cell> layout;
    compute_battery(t, {&y, nullptr, nullptr, nullptr}, o, &layout);
    const auto find = [&](const std::string& key) {
        const auto at = std::find_if(layout.begin(), layout.end(), [&](const Cell& c) { return c.cell == key; });
        EXPECT_NE(at, layout.end()) << key;
        return at == layout.end() ? std::string() : at->shown();
    };
    EXPECT_EQ(find("t=1.2e+03s..1.35e+03s"), "t=1201s..1350s");
    EXPECT_EQ(find("t=1.1s..150s"), "t=1s..150s");
    EXPECT_EQ(find("lag=1s..1s"), "lag=1s");
    EXPECT_EQ(find("lag=32s..63s"), "lag=32s..63s");
    EXPECT_EQ(find("tau=64s"), "tau=64s");
    EXPECT_EQ(find("kurtosis"), "kurtosis");  // no number: the key as it is
    for (const Cell& c : layout)
        EXPECT_EQ(c.shown().find("e+"), std::string::npos) << c.cell << " shown as " << c.shown();
}

// A log or model file named as one of the report's files would be written over: view::report_files() lists them all.
TEST(GapReport, TheReportsFilesAreListedWhicheverChannelsItPlots) {
    const std::vector<std::string> files = view::report_files("rep");
    for (const std::string expected : {"rep/gap.md", "rep/gap_mean_gyro.png", "rep/gap_mean_gyro.dat",
                                       "rep/gap_adev_accel_z.png.gp", "rep/gap_codes_accel_x.png"})
        EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected;
    EXPECT_EQ(std::find(files.begin(), files.end(), "rep/h.csv"), files.end());
}

TEST(GapPhrases, StabilityLinesGiveEachAddedEffectOneLineAndSayWhatWasNotFoundAgain) {
    VerdictStability s;
    s.logs = 4;
    s.params = {{"gauss_markov", "gyro", "sigma_dps", 0.02, {0.01, 0.02, 0.03}, 3},
                {"gauss_markov", "gyro", "tau_s", 20.0, {10.0, 20.0, 30.0}, 3},
                {"thermal_second_tc", "gyro", "c3_dps", -0.3, {}, 0},
                {"thermal_second_tc", "gyro", "t2_s", 12000.0, {}, 0},
                // A DNL table's transitions differ from log to log: 507 is not found again, 508 in 2 of the 3 logs.
                {"adc_dnl", "gyro", "t507_counts", 507.4, {}, 3},
                {"adc_dnl", "gyro", "t508_counts", 508.6, {508.5, 508.7}, 3}};
    const std::vector<std::string> lines = view::spread_lines(s);
    ASSERT_EQ(lines.size(), 3u);
    // Each value to the digits half its middle 68 % warrants (%.3g had made 508.532 to 508.668 "509 to 509"): sigma's
    // half-width 0.0068 puts the last digit at 1e-4, tau's 6.8 at 0.1, the transition's 0.068 at 1e-3. Without a
    // spread, four significant digits and no exponent (t2_s had read 1.2e+04).
    EXPECT_EQ(lines[0],
              "gauss_markov on gyro (3 of 4 logs): sigma_dps 0.0200 -> 0.0132 to 0.0268 (median 0.0200); "
              "tau_s 20.0 -> 13.2 to 26.8 (median 20.0)");
    EXPECT_EQ(lines[1], "thermal_second_tc on gyro: added again in none of the 4 logs (c3_dps -0.3, t2_s 12000)");
    EXPECT_EQ(lines[2],
              "adc_dnl on gyro (3 of 4 logs): t507_counts 507.4 -> not found again; t508_counts 508.600 -> 508.532 to "
              "508.668 (median 508.600) in 2");
}

}  // namespace
}  // namespace driftlab::host::gap
