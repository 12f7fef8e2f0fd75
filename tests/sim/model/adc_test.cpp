// Converter transfer function: codes against the closed form code = clamp(floor(v/lsb + 0.5), 0, 1023).
#include "sim/model/adc.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace driftlab::sim {
namespace {

TEST(Adc, LsbIsVrefOver1024For10Bits) {
    const Adc adc({10, 5.0});
    EXPECT_DOUBLE_EQ(adc.lsb_v(), 5.0 / 1024.0);
    EXPECT_EQ(adc.max_code(), 1023);
}

TEST(Adc, MidSupplyReadsMidScale) {
    const Adc adc({10, 5.0});
    EXPECT_EQ(adc.convert(2.5), 512);
}

TEST(Adc, RoundsToNearestCodeWithTransitionsHalfAnLsbFromEachCode) {
    const Adc adc({10, 5.0});
    const double lsb = 5.0 / 1024.0;
    for (int k = 1; k < 1023; k += 37) {
        EXPECT_EQ(adc.convert((k - 0.49) * lsb), k);
        EXPECT_EQ(adc.convert(k * lsb), k);
        EXPECT_EQ(adc.convert((k + 0.49) * lsb), k);
        EXPECT_EQ(adc.convert((k + 0.51) * lsb), k + 1);
    }
}

TEST(Adc, ClipsBelowZeroAndAboveFullScale) {
    const Adc adc({10, 5.0});
    EXPECT_EQ(adc.convert(-1.0), 0);
    EXPECT_EQ(adc.convert(0.0), 0);
    EXPECT_EQ(adc.convert(5.0), 1023);
    EXPECT_EQ(adc.convert(12.0), 1023);
    EXPECT_EQ(adc.convert(std::nan("")), 0);
}

TEST(Adc, QuantisationErrorNeverExceedsHalfAnLsbInsideTheRange) {
    const Adc adc({10, 3.3});
    for (int i = 0; i < 10000; ++i) {
        const double v = 0.01 + i * (3.25 / 10000.0);
        const double exact = v / (3.3 / 1024.0);
        EXPECT_LE(std::abs(adc.convert(v) - exact), 0.5 + 1e-12) << v;
    }
}

TEST(Adc, OtherResolutionsScaleTheLsb) {
    const Adc adc({12, 4.096});
    EXPECT_DOUBLE_EQ(adc.lsb_v(), 0.001);
    EXPECT_EQ(adc.max_code(), 4095);
    EXPECT_EQ(adc.convert(1.2344), 1234);
}

}  // namespace
}  // namespace driftlab::sim
