// Noise calibration through the quantiser: the standard deviation of the RAW codes must be the target.
#include "sim/model/white_noise.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sim/model/adc.hpp"

namespace driftlab::sim {
namespace {

double raw_code_std(double mean_counts, double sigma_counts, std::uint64_t seed, int n) {
    const Adc adc({10, 5.0});
    WhiteNoise noise(sigma_counts, Rng(seed, 1));
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double code = adc.convert_counts(mean_counts + noise.sample_counts());
        sum += code;
        sum2 += code * code;
    }
    const double mean = sum / n;
    return std::sqrt((sum2 - n * mean * mean) / (n - 1));
}

TEST(WhiteNoise, AnalogSigmaRemovesTheQuantisationVariance) {
    EXPECT_NEAR(analog_sigma_for_raw_std_counts(1.0), std::sqrt(1.0 - 1.0 / 12.0), 1e-15);
    EXPECT_EQ(analog_sigma_for_raw_std_counts(0.0), 0.0);
    // The inverse, for a model file written from a calibrated sigma: back and forth lands where it started.
    for (double raw : {0.5, 1.0, 1.0625, 7.3})
        EXPECT_NEAR(raw_std_counts_for_analog_sigma(analog_sigma_for_raw_std_counts(raw)), raw, 1e-14);
    EXPECT_EQ(raw_std_counts_for_analog_sigma(0.0), 0.0);
}

// Paper targets: gyro 0.187 deg/s at 512/90 counts per deg/s, accel X 0.0141 g at 512 counts per g.
TEST(WhiteNoise, RawCodeStdMatchesThePaperTargetsWhereTheMeanFallsBetweenCodes) {
    const int n = 400000;  // relative standard error of a std: 1/sqrt(2n) = 0.11 %
    for (double target : {0.187 * 512.0 / 90.0, 0.0141 * 512.0}) {
        for (double frac : {0.0, 0.25, 0.5, 0.8}) {
            const double s = raw_code_std(505.0 + frac, analog_sigma_for_raw_std_counts(target), 7, n);
            EXPECT_NEAR(s / target, 1.0, 0.006) << "target " << target << " frac " << frac;
        }
    }
}

TEST(WhiteNoise, UncalibratedSigmaWouldOverestimateTheRawStd) {
    // The correction matters at the gyro's level: sigma = target gives a raw std about 4 % too high.
    const double target = 0.187 * 512.0 / 90.0;
    const double s = raw_code_std(505.3, target, 11, 400000);
    EXPECT_NEAR(s, std::sqrt(target * target + 1.0 / 12.0), 0.006 * target);
    EXPECT_GT(s / target, 1.03);
}

TEST(WhiteNoise, SamplesAreZeroMeanWithTheGivenSigma) {
    WhiteNoise noise(2.0, Rng(3, 9));
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double x = noise.sample_counts();
        sum += x;
        sum2 += x * x;
    }
    EXPECT_NEAR(sum / n, 0.0, 4.0 * 2.0 / std::sqrt(n));
    EXPECT_NEAR(std::sqrt(sum2 / n), 2.0, 2.0 * 4.0 / std::sqrt(2.0 * n));
}

}  // namespace
}  // namespace driftlab::sim
