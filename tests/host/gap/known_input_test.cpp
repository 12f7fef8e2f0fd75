// The known input of a log in motion (host/gap/known_input.hpp) against the closed form of the firmware's smoothing
// of a ramp, and its choice of the round robin's phase in a polled log.
#include <gtest/gtest.h>

#include <cmath>

#include "host/gap/known_input.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {
namespace {

// 0.1 s outputs of 10 conversions per channel: one conversion every 2.5 ms, channel after channel.
constexpr double kConversionS = 0.0025;
constexpr double kPaperGyroCountsPerDps = 512.0 / 90.0;  // docs/hardware.md: 90 deg/s over half the converter

LogData ramp_log(int window, int order, const char* mode) {
    LogData log;
    log.source_name = "ramp.csv";
    log.metadata.set("sample_period_s", 0.1);
    log.metadata.set("conversions_per_output", std::int64_t{10});
    log.metadata.set("window", std::int64_t{window});
    log.metadata.set("fit_order", std::int64_t{order});
    log.metadata.set("mode", std::string(mode));
    log.metadata.set("tick_hz", 250000.0);
    for (int k = 0; k < 200; ++k) {
        log.t_s.push_back(2.0 + 0.1 * k);
        for (auto& c : log.counts) c.push_back(512.0);
    }
    return log;
}

// A yaw rate rising 3 deg/s per second, and a forward acceleration 0.01 g per second: linear, so the interpolation
// between rows is exact.
TruthFile ramp_truth(const LogData& log) {
    TruthFile t;
    t.path = "ramp.truth.csv";
    for (std::size_t k = 0; k < log.size(); ++k) {
        t.t_s.push_back(log.t_s[k]);
        t.yaw_rate_dps.push_back(3.0 * log.t_s[k]);
        t.accel_x_g.push_back(0.01 * log.t_s[k]);
        t.accel_y_g.push_back(0.0);
        t.lines.push_back(k + 5);
    }
    return t;
}

// Streamed rows follow accel_z's conversion: the gyro's newest is 3 conversions earlier, accel_x's 2. The mean of
// N conversions 4 apart lags its newest by 4 (N - 1) / 2 conversions; the line evaluated at the newest does not lag.
TEST(KnownInput, ARampLagsByTheRoundRobinAndTheWindowsCentre) {
    for (const int order : {0, 1}) {
        const LogData log = ramp_log(8, order, "stream");
        const KnownInput known = known_input(log, ramp_truth(log), sim::paper_model());
        EXPECT_EQ(known.newest_channel, 3);
        EXPECT_FALSE(known.newest_estimated);
        EXPECT_NEAR(known.counts_per_unit[0], kPaperGyroCountsPerDps, 1e-9);
        const double window_lag_s = order == 0 ? 4.0 * 3.5 * kConversionS : 0.0;
        const std::vector<double> gyro = known.counts(Channel::gyro);
        const std::vector<double>& ax = known.smoothed[1][static_cast<std::size_t>(MotionQuantity::accel_x)];
        for (std::size_t k = 5; k < log.size() - 1; ++k) {
            const double t = log.t_s[k];
            EXPECT_NEAR(gyro[k], kPaperGyroCountsPerDps * 3.0 * (t - 3 * kConversionS - window_lag_s), 1e-9);
            EXPECT_NEAR(ax[k], 0.01 * (t - 2 * kConversionS - window_lag_s), 1e-12);
        }
        for (const double v : known.counts(Channel::accel_z)) EXPECT_EQ(v, 0.0);
    }
}

// A polled row follows whichever channel the round robin converted last: on a log made with each phase (a yaw rate
// that is not a polynomial in time, read through the gyro's conversions), the phase that fits is found.
TEST(KnownInput, APolledLogsRoundRobinPhaseIsFoundFromTheLog) {
    for (int newest = 0; newest < 4; ++newest) {
        LogData log = ramp_log(1, 0, "poll");
        TruthFile truth = ramp_truth(log);
        const auto rate = [](double t) { return 40.0 * std::sin(2.0 * t); };
        for (std::size_t k = 0; k < log.size(); ++k) {
            truth.yaw_rate_dps[k] = rate(log.t_s[k]);
            const double instant = log.t_s[k] - ((newest + 4) % 4) * kConversionS;  // the gyro is channel 0
            log.counts[0][k] = 505.0 + kPaperGyroCountsPerDps * rate(instant) + 0.2 * std::sin(7.0 * k);
        }
        // Interpolating the truth between its rows errs alike for every phase; only the right one removes the rate.
        const KnownInput known = known_input(log, truth, sim::paper_model());
        EXPECT_TRUE(known.newest_estimated);
        EXPECT_EQ(known.newest_channel, newest);
    }
}

}  // namespace
}  // namespace driftlab::host::gap
