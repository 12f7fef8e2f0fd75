// The composed chain without effects: codes average eq. 1 plus the input and scatter with the raw target std.
#include "sim/model/sensor_model.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "sim/model/model_file.hpp"

namespace driftlab::sim {
namespace {

struct Moments {
    double mean;
    double std;
};

Moments moments_at(SensorModel& s, Channel c, double t_s, int n) {
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double code = s.convert(c, t_s).code;
        sum += code;
        sum2 += code * code;
    }
    const double mean = sum / n;
    return {mean, std::sqrt((sum2 - n * mean * mean) / (n - 1))};
}

TEST(SensorModel, AtRestCodesAverageEquationOneOfTableOne) {
    SensorModel s(paper_model(), 1);
    const int n = 100000;
    const double table1[4][3] = {{3, 505, 411}, {2, 470, 953}, {23, 474, 937}, {28, 622, 1050}};
    const double raw_std[4] = {0.187 * 512 / 90, 0.0141 * 512, 0.0141 * 512, 0.0141 * 512};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        for (double t : {0.0, 500.0, 4000.0}) {
            const double expected = table1[c][0] * (1 - std::exp(-t / table1[c][2])) + table1[c][1];
            const Moments m = moments_at(s, static_cast<Channel>(c), t, n);
            EXPECT_NEAR(m.mean, expected, 5.0 * raw_std[c] / std::sqrt(n)) << kChannelNames[c] << " t=" << t;
            EXPECT_NEAR(m.std / raw_std[c], 1.0, 0.01) << kChannelNames[c] << " t=" << t;
        }
    }
}

TEST(SensorModel, AnalogSigmaIsCalibratedFromThePaperRawStd) {
    SensorModel s(paper_model(), 1);
    const double g = 0.187 * 512.0 / 90.0;
    EXPECT_NEAR(s.analog_sigma_counts(Channel::gyro), std::sqrt(g * g - 1.0 / 12.0), 1e-12);
    EXPECT_DOUBLE_EQ(s.counts_per_unit(Channel::accel_x), 512.0);
}

TEST(SensorModel, ARotationShiftsTheGyroByItsScale) {
    SimModel m = paper_model();
    m.channels[0].input_unit = 9.0;  // 9 deg/s = 51.2 counts
    m.channels[0].raw_noise_std_unit = 0.0;
    SensorModel s(m, 1);
    EXPECT_EQ(s.convert(Channel::gyro, 0.0).code, 505 + 51);
}

TEST(SensorModel, SameSeedSameCodesDifferentSeedDifferentCodes) {
    SensorModel a(paper_model(), 42), b(paper_model(), 42), c(paper_model(), 43);
    int differ = 0;
    for (int i = 0; i < 1000; ++i) {
        const auto ch = static_cast<Channel>(i % 4);
        const auto ca = a.convert(ch, i * 0.01).code;
        EXPECT_EQ(ca, b.convert(ch, i * 0.01).code);
        differ += ca != c.convert(ch, i * 0.01).code;
    }
    EXPECT_GT(differ, 300);
}

}  // namespace
}  // namespace driftlab::sim
