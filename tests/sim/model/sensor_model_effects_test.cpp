// The chain applies effects as the effect library requires (sim/effects/effect.hpp "Order"): input effects reach
// every channel's true motion, and the order of a stage does not depend on the model file's order.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"

namespace driftlab::sim {
namespace {

constexpr std::uint64_t kSeed = 11;
constexpr double kStepS = 0.001;

SimModel model_with(const std::string& effects_toml) {
    return parse_model(std::string(paper_model_text()) + "\n" + effects_toml, "test.toml");
}

double mean_gyro_counts(const SimModel& model, int n) {
    SensorModel sensor(model, kSeed);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += sensor.convert(Channel::gyro, 3600.0 + k * kStepS).code;
    return sum / n;
}

// Rectification: a 1 g tone on accel x and a gyro g^2-sensitivity of 1 deg/s/g^2 shift the gyro's mean by
// 1 * <(1 g sin)^2> = 0.5 deg/s, though only the gyro is converted. Same seed: the noise cancels in the difference.
TEST(SensorModelEffects, AccelVibrationReachesGyroGSensitivityWhileGyroIsConverted) {
    const std::string vib = "[effects.vibration]\ntone_hz = [7.3]\ntone_g_x = [1.0]\n";
    const std::string gsens = "[effects.g_sensitivity]\ng2_dps_per_g2 = [1.0, 0.0, 0.0]\n";
    const SimModel base = model_with(vib);
    const SimModel coupled = model_with(vib + gsens);
    const SensorModel probe(base, kSeed);
    const double expected_counts = 0.5 * probe.counts_per_unit(Channel::gyro);
    const int n = 20000;  // 146 periods of the tone
    const double shift = mean_gyro_counts(coupled, n) - mean_gyro_counts(base, n);
    EXPECT_NEAR(shift, expected_counts, 0.05 * expected_counts);
}

// Within the converter stage the bow of adc_inl must move the input before adc_dnl quantises it (the library's
// order, whatever the model file's): then a missing code can never appear. Applied the other way round, the bow
// would shift already-quantised codes and the final rounding would produce the missing code.
TEST(SensorModelEffects, MissingCodeStaysMissingWithABowedConverter) {
    const std::string inl = "[effects.adc_inl]\na2_lsb = 3.0\n";
    const std::string dnl = "[effects.adc_dnl]\nmissing_codes = [506]\n";
    SensorModel sensor(model_with(inl + dnl), kSeed);
    int near_missing = 0;
    for (int k = 0; k < 20000; ++k) {
        const std::uint16_t code = sensor.convert(Channel::gyro, 3600.0 + k * kStepS).code;
        ASSERT_NE(code, 506) << "conversion " << k;
        near_missing += (code == 505 || code == 507);
    }
    EXPECT_GT(near_missing, 1000) << "the test must exercise codes around the missing one";
}

// A board clock 100 ppm slow moves the instants it times by 100 ppm of the time since the board started, not since the
// sensor was powered: with the sensor powered 3600 s before the board (hil --warm 3600), the conversion the board
// times at 10 s happens at 3600 + 10 (1 + 1e-4) s of sensor time, not (3600 + 10)(1 + 1e-4) (0.36 s later, on the
// steep part of a short warm-up's curve).
TEST(SensorModelEffects, ClockDriftRunsFromTheBoardsStartNotTheSensorsPowerOn) {
    const double warm_s = 3600.0;
    SensorModel sensor(model_with("[effects.clock_jitter]\ndrift_ppm = 100.0\n"), kSeed, warm_s);
    for (const double board_s : {0.0, 10.0, 1000.0}) {
        EXPECT_DOUBLE_EQ(sensor.convert(Channel::gyro, board_s).t_s, warm_s + board_s * (1.0 + 1e-4)) << board_s;
    }
    // Without the effect, the board's instant is the sensor's plus the warm-up, exactly.
    SensorModel plain(model_with(""), kSeed, warm_s);
    EXPECT_EQ(plain.convert(Channel::gyro, 12.5).t_s, warm_s + 12.5);
}

// Jitter as large as the conversion interval (which a model file may not have, but a SimModel built in code may)
// must not reorder a channel's instants: a negative step made the Gauss-Markov bias NaN for good, which the
// converter read as code 0 on every later conversion.
TEST(SensorModelEffects, JitterNeverSendsAChannelsInstantBackwardsAndTheBiasStaysFinite) {
    SimModel m = paper_model();
    m.effects.push_back({"gauss_markov", toml::parse("sigma_dps = 0.2")});
    m.effects.push_back({"clock_jitter", toml::parse("jitter_s = 0.01")});
    SensorModel sensor(m, kSeed);
    double last_t = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const Conversion c = sensor.convert(Channel::gyro, 0.01 * k);
        ASSERT_GE(c.t_s, last_t) << "conversion " << k;
        last_t = c.t_s;
        // At rest the gyro reads near eq. 1's 505..508 counts; 0.2 deg/s of bias is 1.1 counts.
        ASSERT_NEAR(c.code, 506.0, 20.0) << "conversion " << k;
    }
}

// The walk starts at power-on (docs/effects.md): with the sensor powered W = 100 s before the board, its value at the
// board's first conversion has spread K sqrt(W) over seeds (it had started from 0 at the board's start). K = 1
// deg/s/sqrt(s) gives 10 deg/s = 57 counts, against which quantisation (1/12 count^2) is negligible; no white noise.
TEST(SensorModelEffects, RandomWalkHasRunSincePowerOnAtTheBoardsStart) {
    // Same seed with and without the walk: the noise and eq. 1 cancel, and the difference is the walk (+-1 count of
    // rounding), whose spread over seeds at the board's start must be K sqrt(W), not 0.
    const double k = 1.0, warm_s = 100.0;
    const SimModel with = model_with("[effects.rate_random_walk]\nk_dps_per_sqrt_s = 1.0\n");
    const SimModel without = model_with("");
    const int seeds = 2000;
    double sum = 0.0, sum2 = 0.0;
    for (int s = 0; s < seeds; ++s) {
        SensorModel walked(with, 5000 + s, warm_s);
        SensorModel plain(without, 5000 + s, warm_s);
        const double dps = (walked.convert(Channel::gyro, 0.0).code - plain.convert(Channel::gyro, 0.0).code) /
                           walked.counts_per_unit(Channel::gyro);
        sum += dps;
        sum2 += dps * dps;
    }
    const double mean = sum / seeds;
    const double spread = std::sqrt((sum2 - seeds * mean * mean) / (seeds - 1));
    // Relative sd of a Gaussian sample's std: 1/sqrt(2n); 4 of them.
    EXPECT_NEAR(spread / (k * std::sqrt(warm_s)), 1.0, 4.0 / std::sqrt(2.0 * seeds)) << spread;
}

// ambient_cycle's temperature (25 degC plus its lagged swing) is the chain's: a 20 K square swing without lag puts
// the unit at 35 degC in the first half of each period and 15 degC in the second, so a tempco of 1 %/K on accel_z
// (1 g at rest) moves it by +-10 % of 1 g = +-51.2 counts. The temperature had never been set: no change at all.
TEST(SensorModelEffects, TempScaleFactorFollowsTheAmbientCyclesTemperature) {
    const std::string cycle = "[effects.ambient_cycle]\namplitude_k_pp = 20.0\nperiod_s = 100.0\nlag_s = 0.0\n";
    // Same seed: the noise cancels in the difference.
    SensorModel plain(model_with(cycle), kSeed);
    SensorModel scaled(model_with(cycle + "[effects.temp_scale_factor]\nscale_pct_per_k = [0.0, 0.0, 0.0, 1.0]\n"),
                       kSeed);
    const double per_g = plain.counts_per_unit(Channel::accel_z);
    for (const double t : {10.0, 30.0, 60.0, 80.0}) {
        const double kelvin_from_reference = t < 50.0 ? 10.0 : -10.0;
        const double shift = scaled.convert(Channel::accel_z, t).code - plain.convert(Channel::accel_z, t).code;
        EXPECT_NEAR(shift, 0.01 * kelvin_from_reference * 1.0 * per_g, 1.0) << t;
    }
}

}  // namespace
}  // namespace driftlab::sim
