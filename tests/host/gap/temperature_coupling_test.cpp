// The channels against the logged temperature: a four-channel log whose gyro and accel_z follow a measured
// temperature (warm-up plus a wander, in the board's 0.1 degC steps) is coupled on those two at their coefficients;
// a temperature that only warms up as eq. 1 does couples nothing; a log without a temperature in every row is not
// compared.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap/common_cause.hpp"
#include "host/gap/temperature_coupling.hpp"
#include "sim/model/board_outputs.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {
namespace {

constexpr std::size_t kSamples = 1500;

struct Case {
    LogData log;
    GapModel model;
    std::array<std::vector<double>, kChannelCount> residual;
};

// The paper's four channels at 1 s (window 8), each seeing `coefficient` counts per degC of `temperature`(t).
template <class Temperature>
Case make_case(const std::array<double, kChannelCount>& coefficient, Temperature temperature, std::uint64_t seed) {
    Case k;
    k.model.unit = sim::paper_model();
    k.model.unit.effects.clear();
    k.model.smoothing = {1.0, 8, 8, 0};
    k.model.base = sim::base_of(k.model.unit);
    k.log.source_name = "temperature test";
    std::vector<double>& temp = k.log.optional_columns["temp_c"];
    for (std::size_t i = 0; i < kSamples; ++i) {
        k.log.t_s.push_back(static_cast<double>(i + 1));
        temp.push_back(std::round(temperature(k.log.t_s.back()) * 10.0) / 10.0);  // the log's 0.1 degC
    }
    sim::OutputRequest req;
    req.t_s = &k.log.t_s;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        for (double v : temp) req.added_counts[c].push_back(coefficient[c] * v);
    const sim::Outputs y = sim::simulate_outputs(k.model, req, seed);
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        k.log.counts[c] = y[c];
        k.residual[c] = common_residual(k.log.t_s, y[c], {});
    }
    return k;
}

const std::array<bool, kChannelCount> kAll{true, true, true, true};

TEST(TemperatureCoupling, ChannelsFollowingTheMeasuredTemperatureAreCoupledAtTheirCoefficients) {
    const std::array<double, kChannelCount> coefficient{0.5, 0.0, 0.0, -3.0};
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        sim::Rng rng(seed, 1);
        const double phase = 2.0 * std::numbers::pi * rng.uniform();
        // A room that warms the board over 300 s and swings 1 degC every 400 s (an air conditioner).
        const auto room = [&](double t) {
            return 25.0 + 3.0 * (1.0 - std::exp(-t / 300.0)) + std::sin(2.0 * std::numbers::pi * t / 400.0 + phase);
        };
        Case k = make_case(coefficient, room, seed);
        const TemperatureCoupling tc = couple_to_temperature(k.residual, kAll, temperature_residual(k.log), k.model, 2);
        ASSERT_TRUE(tc.compared);
        EXPECT_TRUE(tc.coupled[0]);
        EXPECT_FALSE(tc.coupled[1]);
        EXPECT_FALSE(tc.coupled[2]);
        EXPECT_TRUE(tc.coupled[3]);
        // The coefficient by least squares against the 0.7 degC rms swing: the gyro's 0.37-count output noise over
        // 1500 samples scatters it by some 0.02 count per degC, an axis's 2.6 counts by some 0.1.
        EXPECT_NEAR(tc.coefficient[0], 0.5, 0.1);
        EXPECT_NEAR(tc.coefficient[3], -3.0, 0.4);
    }
}

TEST(TemperatureCoupling, AWarmUpAloneCouplesNothingAndAMissingReadingIsNotCompared) {
    const auto warm_up = [](double t) { return 25.0 + 3.0 * (1.0 - std::exp(-t / 300.0)); };
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        Case k = make_case({0.0, 0.0, 0.0, 0.0}, warm_up, seed);
        const TemperatureCoupling tc = couple_to_temperature(k.residual, kAll, temperature_residual(k.log), k.model, 2);
        ASSERT_TRUE(tc.compared);
        EXPECT_FALSE(tc.any());
    }
    Case k = make_case({0.0, 0.0, 0.0, 0.0}, warm_up, 1);
    k.log.optional_columns["temp_c"][700] = kNoTemperatureC;  // a schedule too fast for one reading
    EXPECT_TRUE(temperature_residual(k.log).empty());
    for (double& v : k.log.optional_columns["temp_c"]) v = 25.0;
    EXPECT_TRUE(temperature_residual(k.log).empty());
}

}  // namespace
}  // namespace driftlab::host::gap
