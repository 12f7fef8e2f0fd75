// Transducer + amplifier: the spans put ±90 deg/s and ±1 g (Z: 0..2 g) exactly onto the converter's range.
#include "sim/model/sensor.hpp"

#include <gtest/gtest.h>

#include "sim/model/adc.hpp"

namespace driftlab::sim {
namespace {

std::uint16_t code_for(Channel c, double quantity) {
    const Adc adc({10, 5.0});
    const FrontEnd fe(kPaperFrontEnd[channel_index(c)], 5.0);
    return adc.convert(fe.amplifier_v(fe.sensor_v(quantity)));
}

TEST(FrontEnd, GyroCountIs90Over512DegreesPerSecond) {
    EXPECT_EQ(code_for(Channel::gyro, 0.0), 512);
    EXPECT_EQ(code_for(Channel::gyro, 45.0), 768);
    EXPECT_EQ(code_for(Channel::gyro, -45.0), 256);
    EXPECT_EQ(code_for(Channel::gyro, 10 * 90.0 / 512.0), 522);
    const FrontEnd fe(kPaperFrontEnd[0], 5.0);
    EXPECT_DOUBLE_EQ(fe.counts_per_unit(1024.0), 512.0 / 90.0);
}

TEST(FrontEnd, FullScaleInputsClipAtTheRails) {
    EXPECT_EQ(code_for(Channel::gyro, 90.0), 1023);
    EXPECT_EQ(code_for(Channel::gyro, -90.0), 0);
    EXPECT_EQ(code_for(Channel::gyro, 300.0), 1023);
    EXPECT_EQ(code_for(Channel::accel_x, -1.5), 0);
}

TEST(FrontEnd, AccelCountIsOneOver512G) {
    EXPECT_EQ(code_for(Channel::accel_x, 0.0), 512);
    EXPECT_EQ(code_for(Channel::accel_y, 0.5), 768);
    EXPECT_EQ(code_for(Channel::accel_x, 20.0 / 512.0), 532);
}

TEST(FrontEnd, VerticalAxisUsesTheZeroToTwoGSpan) {
    EXPECT_EQ(code_for(Channel::accel_z, 1.0), 512);
    EXPECT_EQ(code_for(Channel::accel_z, 0.0), 0);
    EXPECT_EQ(code_for(Channel::accel_z, 1.5), 768);
    EXPECT_EQ(code_for(Channel::accel_z, 2.0), 1023);
}

TEST(FrontEnd, GainIsHalfVrefOverSensitivityTimesSpan) {
    const FrontEnd fe({0.0222, 2.5, 90.0, 0.0}, 5.0);
    EXPECT_DOUBLE_EQ(fe.gain(), 2.5 / (0.0222 * 90.0));
    EXPECT_DOUBLE_EQ(fe.sensor_v(10.0), 2.5 + 0.222);
}

}  // namespace
}  // namespace driftlab::sim
