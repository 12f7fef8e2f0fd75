// link_capacity_refusal, the one check that a model's link carries its firmware's output: 10 bits per byte, a
// 33-byte SAMPLE (plus a 21-byte RAW in raw mode) per output period. At 9600 baud (960 bytes/s) that is a SAMPLE
// every 34.375 ms and SAMPLE + RAW every 56.25 ms: 35 and 57 whole ms are carried, 34 and 56 refused (docs/sim.md §5).
#include <gtest/gtest.h>

#include "sim/hil/hil.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::sim {
namespace {

SimModel at(unsigned period_ms, bool raw, double baud) {
    SimModel m = paper_model();
    m.firmware.output_period_ms = static_cast<std::uint16_t>(period_ms);
    m.firmware.raw = raw ? 1 : 0;
    m.link.baud = baud;
    return m;
}

TEST(LinkCapacity, TheShortestPeriodIsTheFramesTimeOnTheLine) {
    EXPECT_FALSE(link_capacity_refusal(at(35, false, 9600.0)));
    EXPECT_TRUE(link_capacity_refusal(at(34, false, 9600.0)));
    EXPECT_FALSE(link_capacity_refusal(at(57, true, 9600.0)));
    EXPECT_TRUE(link_capacity_refusal(at(56, true, 9600.0)));
    // Twelve times the baud carries the same bytes in a twelfth of the time: 34.375 / 12 = 2.86 ms.
    EXPECT_FALSE(link_capacity_refusal(at(10, true, 115200.0)));
}

TEST(LinkCapacity, TheRefusalNamesTheFigures) {
    const auto refusal = link_capacity_refusal(at(20, true, 9600.0));
    ASSERT_TRUE(refusal);
    EXPECT_NE(refusal->find("cannot carry 54 bytes (SAMPLE + RAW) every 20 ms (2700 bytes/s)"), std::string::npos) << *refusal;
}

}  // namespace
}  // namespace driftlab::sim
