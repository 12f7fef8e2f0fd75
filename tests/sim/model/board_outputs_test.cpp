// The board's outputs without the link: the firmware smoother's variance law and the noiseless code path.
#include <cmath>

#include <gtest/gtest.h>

#include "sim/model/board_outputs.hpp"
#include "sim/model/drift.hpp"

namespace driftlab::sim {
namespace {

OutputModel flat_model(double level_counts, double sigma_counts, int window, int order) {
    OutputModel m;
    m.unit = paper_model();
    m.unit.effects.clear();
    m.smoothing = {1.0, window, window, order};
    for (auto& b : m.base) b = {{0.0, level_counts, 100.0}, sigma_counts};
    return m;
}

EffectSpec gauss_markov_on_gyro(double sigma_dps, double tau_s) {
    EffectSpec gm{"gauss_markov", {}};
    gm.table.insert("sigma_dps", sigma_dps);
    gm.table.insert("tau_s", tau_s);
    return gm;
}

std::vector<double> instants(std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k + 1);
    return t;
}

TEST(BoardOutputs, NoiselessLevelQuantisesToNearestCode) {
    const auto t = instants(50);
    OutputRequest req;
    req.t_s = &t;
    const Outputs out = simulate_outputs(flat_model(600.3, 0.0, 8, 0), req, 1);
    for (std::size_t c = 0; c < kChannelCount; ++c)
        for (double v : out[c]) EXPECT_EQ(v, 600.0);
}

// Polled rows 10 s apart of a firmware whose outputs are 1 s apart: each row is the mean of the 25 conversions of the
// last output period, 40 ms apart (not 400 ms, the rows' period over the conversions per output). Noiseless, on
// eq. 1 rising 8 counts/s at t = 0: the mean of the rounded codes at t - 0.04 j, j = 0..24, to the Q8 output's step.
TEST(BoardOutputs, PolledRowsSlowerThanTheOutputsConvertAtTheOutputPeriod) {
    OutputModel m = flat_model(0.0, 0.0, 25, 0);
    m.smoothing = {10.0, 25, 25, 0, 10.0};
    m.base[0].drift = {800.0, 100.0, 100.0};  // C1, C2, T: 100 .. 900 counts
    std::vector<double> t;
    for (int k = 1; k <= 30; ++k) t.push_back(10.0 * k);
    OutputRequest req;
    req.t_s = &t;
    req.channels = {true, false, false, false};
    const Outputs out = simulate_outputs(m, req, 1);
    for (std::size_t k = 0; k < t.size(); ++k) {
        double mean = 0.0;
        for (int j = 0; j < 25; ++j)
            mean += std::floor(800.0 * (1.0 - std::exp(-(t[k] - 0.04 * j) / 100.0)) + 100.0 + 0.5) / 25.0;
        EXPECT_NEAR(out[0][k], mean, 1.0 / 256.0) << "row " << k;
    }
}

TEST(BoardOutputs, MeanSmootherVarianceIsNoisePlusQuantisationOverN) {
    // sigma_n = 2 counts >> 0.5 LSB: var(y) = (sigma_n^2 + 1/12) / N for the order-0 window (gap-method §1).
    const auto t = instants(20000);
    OutputRequest req;
    req.t_s = &t;
    req.channels = {true, false, false, false};
    const int n = 8;
    const Outputs out = simulate_outputs(flat_model(512.4, 2.0, n, 0), req, 3);
    double m = 0, v = 0;
    for (double x : out[0]) m += x;
    m /= static_cast<double>(out[0].size());
    for (double x : out[0]) v += (x - m) * (x - m);
    v /= static_cast<double>(out[0].size() - 1);
    EXPECT_NEAR(v / ((4.0 + 1.0 / 12.0) / n), 1.0, 0.04);
    EXPECT_NEAR(m, 512.4, 0.02);
    EXPECT_TRUE(out[1].empty());
}

// The raw column of a raw-mode log is one conversion, not a window: integral codes of variance sigma_n^2 + 1/12,
// N times the smoothed output's.
TEST(BoardOutputs, RawCodesAreSingleConversions) {
    const auto t = instants(20000);
    Outputs raw;
    OutputRequest req;
    req.t_s = &t;
    req.channels = {true, false, false, false};
    req.raw_codes = &raw;
    const Outputs out = simulate_outputs(flat_model(512.4, 2.0, 8, 0), req, 5);
    ASSERT_EQ(raw[0].size(), t.size());
    EXPECT_TRUE(raw[1].empty());
    double m = 0, v = 0;
    for (double x : raw[0]) {
        EXPECT_EQ(x, std::round(x));
        m += x;
    }
    m /= static_cast<double>(raw[0].size());
    for (double x : raw[0]) v += (x - m) * (x - m);
    v /= static_cast<double>(raw[0].size() - 1);
    EXPECT_NEAR(m, 512.4, 0.05);
    EXPECT_NEAR(v, 4.0 + 1.0 / 12.0, 4.083 * 0.05);  // sampling error of a variance from 20000 draws: 1 %
    // A window of one conversion per output: the output is the raw code itself.
    const Outputs single = simulate_outputs(flat_model(512.4, 2.0, 1, 0), req, 6);
    EXPECT_EQ(single[0], raw[0]);
}

TEST(BoardOutputs, LineSmootherVarianceFollowsItsKernelPower) {
    // Order 1 evaluated at the newest conversion: sum h^2 = 2(2N-1)/(N(N+1)).
    const auto t = instants(20000);
    OutputRequest req;
    req.t_s = &t;
    req.channels = {true, false, false, false};
    const int n = 8;
    const Outputs out = simulate_outputs(flat_model(512.0, 2.0, n, 1), req, 4);
    double m = 0, v = 0;
    for (double x : out[0]) m += x;
    m /= static_cast<double>(out[0].size());
    for (double x : out[0]) v += (x - m) * (x - m);
    v /= static_cast<double>(out[0].size() - 1);
    const double h2 = 2.0 * (2.0 * n - 1.0) / (n * (n + 1.0));
    EXPECT_NEAR(v / ((4.0 + 1.0 / 12.0) * h2), 1.0, 0.05);
}

TEST(BoardOutputs, SameSeedGivesSameLogAndAddedSignalShiftsIt) {
    const auto t = instants(300);
    OutputRequest req;
    req.t_s = &t;
    req.channels = {true, false, false, false};
    const OutputModel m = flat_model(512.0, 1.0, 4, 0);
    const Outputs a = simulate_outputs(m, req, 9);
    EXPECT_EQ(a[0], simulate_outputs(m, req, 9)[0]);
    req.added_counts[0].assign(t.size(), 10.0);
    const Outputs b = simulate_outputs(m, req, 9);
    for (std::size_t k = 0; k < t.size(); ++k) EXPECT_DOUBLE_EQ(b[0][k], a[0][k] + 10.0);
}

// Replicates of one model share eq. 1 at the conversion instants (drift_at_conversions()): a window of 8 over 4
// conversions per output visits 8 instants for the first output and 4 new ones for each later one, eq. 1 at each, and
// a replicate given them is the replicate that computes them, byte for byte, beside a physical effect. A timing
// effect moves the instants by seed: then there is nothing to share.
TEST(BoardOutputs, SharedDriftAtTheConversionsGivesTheSameReplicate) {
    OutputModel m = flat_model(0.0, 1.5, 8, 1);
    m.smoothing = {1.0, 4, 8, 1};
    m.base[0].drift = {40.0, 505.0, 300.0};
    m.effects.push_back(gauss_markov_on_gyro(0.05, 20.0));
    const auto t = instants(400);
    const std::array<bool, kChannelCount> gyro{true, false, false, false};
    const auto drift = drift_at_conversions(m, t, gyro);
    ASSERT_TRUE(drift);
    ASSERT_EQ((*drift)[0].size(), 8u + 4u * 399u);
    EXPECT_TRUE((*drift)[1].empty());
    const Drift eq1(m.base[0].drift);
    EXPECT_EQ((*drift)[0][0], eq1.at_counts(1.0 - 7 * 0.25) - 512.0);  // the first output's oldest conversion
    EXPECT_EQ((*drift)[0].back(), eq1.at_counts(400.0) - 512.0);       // the last output's newest
    OutputRequest req;
    req.t_s = &t;
    req.channels = gyro;
    const Outputs own = simulate_outputs(m, req, 21);
    req.drift = &*drift;
    EXPECT_EQ(simulate_outputs(m, req, 21)[0], own[0]);
    // Beyond its budget the drift is not shared (the replicate then computes it, as `own` did).
    const std::size_t bytes = (*drift)[0].size() * sizeof(double);
    EXPECT_TRUE(drift_at_conversions(m, t, gyro, bytes));
    EXPECT_FALSE(drift_at_conversions(m, t, gyro, bytes / 2));
    EXPECT_FALSE(drift_at_conversions(m, t, {true, true, false, false}, bytes));  // two channels, twice the block

    EffectSpec jitter{"clock_jitter", {}};
    jitter.table.insert("jitter_s", 1e-3);
    m.effects.push_back(jitter);
    EXPECT_FALSE(drift_at_conversions(m, t, gyro));
}

}  // namespace
}  // namespace driftlab::sim
