// Grid placement with explicit gaps and the drift-removed pipeline on a simulated turn-on transient.
#include "host/fit/allan_pipeline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "host/stats/uniform_grid.hpp"

namespace driftlab::host::fit {
namespace {

TEST(UniformGrid, MissingTimesBecomeNanSlots) {
    const std::vector<double> t = {10.0, 10.1, 10.2, 10.5, 10.6};
    const std::vector<double> v = {1, 2, 3, 4, 5};
    const stats::UniformSeries g = stats::to_uniform_grid(t, v, 0.1);
    ASSERT_EQ(g.values.size(), 7u);
    EXPECT_EQ(g.missing, 2u);
    EXPECT_TRUE(std::isnan(g.values[3]));
    EXPECT_TRUE(std::isnan(g.values[4]));
    EXPECT_EQ(g.values[5], 4.0);
    EXPECT_DOUBLE_EQ(g.t0_s, 10.0);
}

TEST(UniformGrid, JitterSmallerThanHalfAPeriodKeepsEverySample) {
    std::vector<double> t, v;
    for (int k = 0; k < 1000; ++k) {
        t.push_back(0.01 * k + 0.003 * std::sin(k));
        v.push_back(k);
    }
    const stats::UniformSeries g = stats::to_uniform_grid(t, v, stats::median_spacing_s(t));
    EXPECT_EQ(g.missing, 0u);
    EXPECT_EQ(g.values.size(), 1000u);
}

TEST(UniformGrid, BurstyTimestampsNeverDropASample) {
    // Two samples 1 ms apart, then 19 ms to the next: a logger flushing in pairs at 100 Hz.
    std::vector<double> t, v;
    for (int k = 0; k < 100; ++k) {
        t.push_back(0.02 * (k / 2) + 0.001 * (k % 2));
        v.push_back(k);
    }
    const stats::UniformSeries g = stats::to_uniform_grid(t, v, 0.01);
    EXPECT_EQ(g.missing, 0u);
    ASSERT_EQ(g.values.size(), 100u);
    EXPECT_EQ(g.values[99], 99.0);
}

// A record that changes its rate: 200 rows 0.5 s apart, then 1 s rows, on a 1 s grid. The fast rows are packed onto
// consecutive slots and counted; jitter of less than half a period packs none.
TEST(UniformGrid, RowsFasterThanTau0AreCountedAsPacked) {
    std::vector<double> t, y;
    for (int k = 0; k < 200; ++k) t.push_back(0.5 * k);
    for (int k = 0; k < 100; ++k) t.push_back(100.0 + k);
    y.assign(t.size(), 1.0);
    const stats::UniformSeries packed = stats::to_uniform_grid(t, y, 1.0);
    EXPECT_EQ(packed.packed, 296u);     // fast rows 4..199 (k - k/2 >= 2), then every 1 s row behind them
    EXPECT_EQ(packed.most_late, 100u);  // the 1 s rows sit 100 slots late
    std::vector<double> jittered(300);
    for (std::size_t k = 0; k < jittered.size(); ++k) jittered[k] = static_cast<double>(k) + ((k % 3) - 1.0) * 0.3;
    EXPECT_EQ(stats::to_uniform_grid(jittered, std::vector<double>(300, 1.0), 1.0).packed, 0u);
}

// Without a given period: rows in bursts (5 rows 2 ms apart every 50 ms, as the MPU6050 recording's) take the mean,
// 10 ms, not the median 2 ms that would leave 80 % of the grid empty; rows 1 s apart keep their median through a
// reconnect that lost 30 % of the record (the mean, 1.43 s, would pack them and close the gap up).
TEST(UniformGrid, GridPeriodIsTheMeanOnlyForRowsInBursts) {
    std::vector<double> bursts;
    for (int k = 0; k < 1000; ++k) bursts.push_back(0.05 * (k / 5) + 0.002 * (k % 5));
    EXPECT_NEAR(stats::median_spacing_s(bursts), 0.002, 1e-12);
    EXPECT_NEAR(stats::grid_period_s(bursts), stats::mean_spacing_s(bursts), 1e-15);
    EXPECT_NEAR(stats::grid_period_s(bursts), 0.01, 1e-4);
    std::vector<double> reconnect;
    for (int k = 0; k < 1000; ++k) reconnect.push_back(k < 500 ? k : k + 430.0);
    EXPECT_NEAR(stats::mean_spacing_s(reconnect), 1.43, 1e-3);
    EXPECT_EQ(stats::grid_period_s(reconnect), 1.0);
}

// Packing is worth a caveat once it moves samples by more than 5 % of the averaging time at the curve's minimum,
// from where the curve reads correlated noise; not at 5 % itself, and never without packing.
TEST(AllanPipeline, PackingIsACaveatPastATwentiethOfTheMinimumsTau) {
    stats::AnalysedCurve curve;
    curve.curve.tau_s = {1.0, 10.0, 100.0, 1000.0};
    curve.curve.dev = {4.0, 2.0, 1.0, 3.0};
    AllanResult r;
    r.tau0_s = 1.0;
    r.packed_samples = 10;
    r.packed_most_slots = 5;  // 5 s: 5 % of the minimum's 100 s
    EXPECT_FALSE(packing_caveat(r, curve).has_value());
    r.packed_most_slots = 6;
    const std::optional<std::string> caveat = packing_caveat(r, curve);
    ASSERT_TRUE(caveat.has_value());
    EXPECT_NE(caveat->find("10 samples came faster than tau0"), std::string::npos) << *caveat;
    EXPECT_NE(caveat->find("up to 6 slots (6 s) after their time, 6 % of tau = 100 s at the curve's minimum"),
              std::string::npos)
        << *caveat;
    // A curve that only rises (a random walk) reads correlated noise from tau0 on: 2 slots already bias it.
    curve.curve.dev = {1.0, 2.0, 3.0, 4.0};
    r.packed_most_slots = 2;
    EXPECT_TRUE(packing_caveat(r, curve).has_value());
    r.packed_samples = 0;
    r.packed_most_slots = 0;
    EXPECT_FALSE(packing_caveat(r, curve).has_value());
}

// Through the pipeline: steady bursts (5 rows 2 ms apart every 50 ms, as the MPU6050 recording's) pack samples a
// few slots, which white noise does not mind; a record that changes its rate moves every later row by what the fast
// stretch gained, hundreds of slots, and is told.
TEST(AllanPipeline, SteadyBurstsGetNoPackingCaveatARateChangeDoes) {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<double> t, y;
    for (int k = 0; k < 6000; ++k) {
        t.push_back(0.05 * (k / 5) + 0.002 * (k % 5));
        y.push_back(g(rng));
    }
    AllanRequest req;
    req.remove_drift = false;
    const AllanResult bursts = analyse_allan(t, y, stats::grid_period_s(t), req);
    EXPECT_GT(bursts.packed_samples, 3000u);
    EXPECT_FALSE(packing_caveat(bursts, bursts.primary().curves.front()).has_value());

    t.clear();
    for (int k = 0; k < 2000; ++k) t.push_back(0.5 * k);
    for (int k = 0; k < 4000; ++k) t.push_back(1000.0 + k);
    const AllanResult changed = analyse_allan(t, y, stats::grid_period_s(t), req);
    EXPECT_DOUBLE_EQ(changed.tau0_s, 1.0);
    EXPECT_EQ(changed.packed_most_slots, 1000u);
    const std::optional<std::string> caveat = packing_caveat(changed, changed.primary().curves.front());
    ASSERT_TRUE(caveat.has_value());
    EXPECT_NE(caveat->find("up to 1000 slots (1000 s) after their time"), std::string::npos) << *caveat;
}

TEST(UniformGrid, RejectsAGridFarFinerThanTheSamples) {
    const std::vector<double> t = {0.0, 1000.0};
    const std::vector<double> v = {0.0, 0.0};
    EXPECT_THROW(stats::to_uniform_grid(t, v, 1e-3), std::invalid_argument);
}

TEST(AllanPipeline, RemovingTheTurnOnDriftRestoresTheWhiteNoiseCurve) {
    // eq. 1 transient of 40 counts with T = 300 s over white noise: the raw ADEV rises at long tau, the
    // drift-removed one follows sigma / sqrt(tau / tau0).
    const double tau0 = 0.1;
    const double sigma = 0.5;
    std::mt19937_64 rng(31);
    std::normal_distribution<double> g(0.0, sigma);
    std::vector<double> t, y;
    for (int k = 0; k < 40000; ++k) {
        const double ts = k * tau0;
        t.push_back(ts);
        y.push_back(500.0 + 40.0 * (1.0 - std::exp(-ts / 300.0)) + g(rng));
    }
    AllanRequest req;
    req.deviations = {stats::Deviation::oadev, stats::Deviation::mdev};
    req.confidence = 0.999;  // every tau inside its interval with high probability (one fixed seed)
    const AllanResult r = analyse_allan(t, y, tau0, req);
    ASSERT_TRUE(r.drift_removed.has_value()) << r.drift_status_name();
    ASSERT_TRUE(r.drift.has_value());
    EXPECT_NEAR(r.drift->t_s / 300.0, 1.0, 0.05);
    const stats::AnalysedCurve& clean = r.drift_removed->curves.front();
    const stats::AnalysedCurve& raw = r.raw.curves.front();
    ASSERT_EQ(clean.curve.type, stats::Deviation::oadev);
    ASSERT_NE(r.drift_removed->find(stats::Deviation::mdev), nullptr);
    for (std::size_t i = 0; i < clean.curve.m.size(); ++i) {
        const double expected = sigma / std::sqrt(static_cast<double>(clean.curve.m[i]));
        EXPECT_GT(expected, clean.ci_low[i]) << clean.curve.m[i];
        EXPECT_LT(expected, clean.ci_high[i]) << clean.curve.m[i];
    }
    // At the longest tau the transient dominates the raw curve.
    EXPECT_GT(raw.curve.dev.back(), 3.0 * clean.curve.dev.back());
    EXPECT_TRUE(r.drift_removed->terms.ok);
    EXPECT_NEAR(r.drift_removed->terms.value[1] / (sigma * std::sqrt(tau0)), 1.0, 0.05);
}

// A drift fit whose evaluation budget ran out removes nothing and says why: in fit's table's words on a terminal,
// as fit --json spells it in JSON (drift_status). allan's text had printed the JSON name iteration_limit. A fit that
// converged reads "converged" in both; a reason no fit ran is the same in both.
TEST(AllanPipeline, AnExhaustedDriftFitReadsInWordsOnATerminalAndAsANameInJson) {
    std::mt19937_64 rng(33);
    std::normal_distribution<double> g(0.0, 0.5);
    std::vector<double> t, y;
    for (int k = 0; k < 3000; ++k) {
        t.push_back(k * 1.0);
        y.push_back(500.0 + 40.0 * (1.0 - std::exp(-k / 300.0)) + g(rng));
    }
    AllanRequest req;
    req.drift_fit.max_function_evaluations = 2;
    const AllanResult stopped = analyse_allan(t, y, 1.0, req);
    ASSERT_EQ(stopped.drift_fit_status, FitStatus::iteration_limit);
    EXPECT_FALSE(stopped.drift_removed.has_value());
    EXPECT_EQ(stopped.drift_status_words(), "not converged (iteration limit)");
    EXPECT_EQ(stopped.drift_status_name(), "iteration_limit");

    const AllanResult removed = analyse_allan(t, y, 1.0, AllanRequest{});
    ASSERT_TRUE(removed.drift_removed.has_value()) << removed.drift_status_name();
    EXPECT_EQ(removed.drift_status_words(), "converged");
    EXPECT_EQ(removed.drift_status_name(), "converged");

    req.remove_drift = false;
    req.kept_drift_status = "kept on request";
    const AllanResult kept = analyse_allan(t, y, 1.0, req);
    EXPECT_FALSE(kept.drift_fit_status.has_value());
    EXPECT_EQ(kept.drift_status_words(), "kept on request");
    EXPECT_EQ(kept.drift_status_name(), "kept on request");
}

TEST(AllanPipeline, TimeGapIsCountedAndNotBridged) {
    std::vector<double> t, y;
    std::mt19937_64 rng(32);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int k = 0; k < 5000; ++k) {
        if (k >= 2000 && k < 2100) continue;  // 100 samples lost
        t.push_back(k * 1.0);
        y.push_back(g(rng));
    }
    AllanRequest req;
    req.remove_drift = false;
    const AllanResult r = analyse_allan(t, y, 1.0, req);
    EXPECT_EQ(r.samples, 5000u);
    EXPECT_EQ(r.gap_samples, 100u);
    const stats::AnalysedCurve& c = r.raw.curves.front();
    ASSERT_FALSE(c.curve.m.empty());
    // m = 1: a gap of 100 rate samples removes 100 + 2m - 1 = 101 overlapping terms (the 5000-sample record
    // has 5001 - 2 = 4999).
    EXPECT_EQ(c.curve.n[0], 4999 - 101);
    // Rate samples 2100..4999 are the longest run: 2900 intervals of 1 s.
    EXPECT_DOUBLE_EQ(r.longest_gap_free_s, 2900.0);
}

// Stable32's bound m <= (N - 1) / 4 for N phase samples: 4 rate samples (5 phase) give the first averaging time,
// with 3 overlapping terms; fewer give none, which is an error rather than an empty table.
TEST(AllanPipeline, TooShortASeriesForAnyAveragingTimeIsRefused) {
    AllanRequest req;
    req.remove_drift = false;
    for (std::size_t n : {2u, 3u}) {
        std::vector<double> t(n), y(n);
        for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k), y[k] = static_cast<double>(k % 2);
        EXPECT_THROW(analyse_allan(t, y, 1.0, req), std::invalid_argument) << n << " samples";
    }
    const AllanResult r = analyse_allan({0.0, 1.0, 2.0, 3.0}, {1.0, 0.0, 1.0, 0.0}, 1.0, req);
    ASSERT_EQ(r.raw.curves.front().curve.m.size(), 1u);
    EXPECT_EQ(r.raw.curves.front().curve.m[0], 1);
    // Rate differences of +-1 at every step: sigma^2 = (1/2) <(y_{k+1} - y_k)^2> = 1/2 over the 3 pairs.
    EXPECT_NEAR(r.raw.curves.front().curve.dev[0], std::sqrt(0.5), 1e-12);
}

// Gaps that leave no stretch of 2m + 1 phase samples give no term at any averaging time: refused, not answered
// with an empty table. Rows 2 s apart on a 1 s grid: every other slot empty, each sample alone (2 phase samples).
TEST(AllanPipeline, GapsThatLeaveNoTermAnywhereAreRefused) {
    AllanRequest req;
    req.remove_drift = false;
    std::vector<double> t(400), y(400);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = 2.0 * static_cast<double>(k), y[k] = static_cast<double>(k % 3);
    try {
        analyse_allan(t, y, 1.0, req);
        ADD_FAILURE() << "an empty curve was returned";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("no averaging time has a term between the gaps"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(analyse_allan(t, y, 2.0, req).raw.curves.front().curve.m.front(), 1);
}

}  // namespace
}  // namespace driftlab::host::fit
