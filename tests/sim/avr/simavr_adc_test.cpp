// millivolts_for_code() inverts simavr's conversion: every code's input converts back to that code, and one
// millivolt less to the code below, so the emulated ATmega328P reads exactly the code the sensor model chose.
#include <gtest/gtest.h>

#include "sim/avr/simavr_adc.hpp"

namespace driftlab::sim::avr {
namespace {

TEST(SimavrAdc, EveryCodesInputIsTheSmallestThatConvertsToIt) {
    for (const std::uint32_t vref : {kBoardVrefMv, 3300U, 1100U + 1023U}) {
        for (std::uint16_t code = 0; code <= 1023; ++code) {
            const std::uint32_t mv = millivolts_for_code(code, vref);
            ASSERT_EQ(simavr_code_for_millivolts(mv, vref), code) << "vref " << vref << " mV";
            if (code > 0) {
                ASSERT_EQ(simavr_code_for_millivolts(mv - 1, vref), code - 1) << "vref " << vref << " mV";
            }
        }
        EXPECT_EQ(simavr_code_for_millivolts(vref + 500, vref), 1023);  // above the reference: clipped
    }
}

}  // namespace
}  // namespace driftlab::sim::avr
