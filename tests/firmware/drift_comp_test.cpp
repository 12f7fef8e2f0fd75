// DriftComp against a double-precision reference of eq. 1: the Q36 step constant, the recursive exponential with its
// interpolation over 10 h at 100 Hz (Table 1 and the extremes of the accepted ranges), a calibration loaded hours
// after the reset, a warm restart and the channels referred to mid-scale.
#include "firmware/core/drift_comp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace driftlab {
namespace fw {
namespace {

constexpr double kTickHz = 250000.0;
// Output LSB: Q8 counts. The integer correction is the double one rounded, so it is within half an LSB plus what the
// fixed point adds; that addition must stay below a hundredth of an LSB.
constexpr double kFixedPointSlackQ8 = 0.01;

double reference_correction_q8(const ChannelModel& m, double t_s) {
  const double offset = m.zero ? m.c1_q8 + m.c2_q8 - 512.0 * 256.0 : 0.0;
  return m.c1_q8 * std::exp(-t_s / (m.t_ms / 1000.0)) - offset;
}

TEST(DriftComp, TheStepConstantHas30SignificantBitsWhateverT) {
  for (uint32_t t_ms :
       {proto::kCalTMinMs, proto::kCalTMinMs + 1, 411000U, 953000U, 3600000U, 33554431U, proto::kCalTMaxMs}) {
    const double x = (65536.0 / kTickHz) / (t_ms / 1000.0);
    const StepDecay s = step_decay(t_ms);
    EXPECT_GE(s.mantissa, 1UL << 29) << "T = " << t_ms << " ms";
    EXPECT_NEAR(std::ldexp(s.mantissa, -s.shift) / -std::expm1(-x), 1.0, 4e-9) << "T = " << t_ms << " ms";
  }
}

// Runs `models` from the reset to `hours` with a SAMPLE every `period_ticks`, the grid advanced by every tick as the
// firmware's conversions advance it, and returns the largest |integer correction - double correction| of any channel
// [Q8].
double worst_error_q8(const ChannelModel (&models)[kChannelCount], double hours, uint32_t period_ticks,
                      uint32_t load_tick = 0) {
  DriftComp comp;
  comp.reset(false);
  double worst = 0.0;
  const uint64_t end = static_cast<uint64_t>(hours * 3600.0 * kTickHz);
  bool loaded = false;
  for (uint64_t tick = period_ticks; tick <= end; tick += period_ticks) {
    const uint32_t wrapped = static_cast<uint32_t>(tick);  // the board's tick wraps after 4.77 h
    comp.advance_to(wrapped);
    if (!loaded && tick >= load_tick) {
      comp.load(models);
      loaded = true;
    }
    if (!loaded) continue;
    const double t_s = static_cast<double>(tick) / kTickHz;
    for (uint8_t c = 0; c < kChannelCount; ++c) {
      const double expected = reference_correction_q8(models[c], t_s);
      const double got = comp.apply(static_cast<Channel>(c), 0, wrapped);
      worst = std::fmax(worst, std::fabs(got - expected));
    }
  }
  return worst;
}

TEST(DriftComp, TableOneStaysWithinHalfAnLsbOfTheDoubleReferenceOver10Hours) {
  // Table 1 of the paper in counts: gyro, accel x, y, z.
  const ChannelModel table1[kChannelCount] = {{3 * 256, 505 * 256, 411000, false},
                                              {2 * 256, 470 * 256, 953000, false},
                                              {23 * 256, 474 * 256, 937000, false},
                                              {28 * 256, 622 * 256, 1050000, false}};
  const double worst = worst_error_q8(table1, 10.0, 25000);  // 100 Hz
  EXPECT_LE(worst, 0.5 + kFixedPointSlackQ8);
}

TEST(DriftComp, TheRangesExtremesStayWithinHalfAnLsbOver10Hours) {
  // The largest amplitude with the shortest and the longest time constant, both signs, an odd period.
  const ChannelModel extremes[kChannelCount] = {{proto::kCalCountsMaxQ8, 0, proto::kCalTMinMs, false},
                                                {-proto::kCalCountsMaxQ8, 0, proto::kCalTMinMs, false},
                                                {proto::kCalCountsMaxQ8, 0, proto::kCalTMaxMs, false},
                                                {-proto::kCalCountsMaxQ8, 0, proto::kCalTMaxMs, false}};
  const double worst = worst_error_q8(extremes, 10.0, 24977);
  EXPECT_LE(worst, 0.5 + kFixedPointSlackQ8);
}

TEST(DriftComp, ACalibrationLoadedHoursAfterTheResetStartsAtTheRightPointOfTheExponential) {
  const ChannelModel models[kChannelCount] = {{proto::kCalCountsMaxQ8, 0, 600000, false},
                                              {-100 * 256, 0, 3600000, false},
                                              {proto::kCalCountsMaxQ8, 0, proto::kCalTMaxMs, false},
                                              {50 * 256, 0, proto::kCalTMinMs, false}};
  // Loaded 3 h in: past 40 000 grid steps, found by squaring.
  const double worst = worst_error_q8(models, 6.0, 25000, static_cast<uint32_t>(3.0 * 3600.0 * kTickHz));
  EXPECT_LE(worst, 0.5 + kFixedPointSlackQ8);
}

TEST(DriftComp, AChannelReferredToZeroReadsMidScaleFromPowerOn) {
  // value = eps(t) exactly: the corrected output is 512 counts at every time.
  const ChannelModel models[kChannelCount] = {{3 * 256, 505 * 256, 411000, true},
                                              {-7 * 256, 530 * 256, 100000, true},
                                              {0, 512 * 256, 100000, true},
                                              {28 * 256, 622 * 256, 1050000, true}};
  DriftComp comp;
  comp.reset(false);
  comp.load(models);
  for (uint32_t tick = 25000; tick < 3600U * 250000U; tick += 25000 * 97) {
    comp.advance_to(tick);
    const double t_s = tick / kTickHz;
    for (uint8_t c = 0; c < kChannelCount; ++c) {
      const ChannelModel& m = models[c];
      const double eps_q8 = m.c1_q8 * -std::expm1(-t_s / (m.t_ms / 1000.0)) + m.c2_q8;
      const int32_t value_q8 = static_cast<int32_t>(std::lround(eps_q8));
      EXPECT_NEAR(comp.apply(static_cast<Channel>(c), value_q8, tick), 512 * 256, 1) << "channel " << int(c);
    }
  }
}

TEST(DriftComp, AWarmRestartTakesTheTransientAsOverAndKeepsTheOffset) {
  const ChannelModel models[kChannelCount] = {{3 * 256, 505 * 256, 411000, true},
                                              {20 * 256, 470 * 256, 953000, false},
                                              {20 * 256, 474 * 256, 937000, false},
                                              {20 * 256, 622 * 256, 1050000, false}};
  DriftComp comp;
  comp.reset(true);
  comp.load(models);
  EXPECT_TRUE(comp.settled());
  comp.advance_to(250000);
  // Gyro: only the settled offset C1 + C2 - 512 = -4 counts is removed; the others are left as they are.
  EXPECT_EQ(comp.apply(Channel::gyro, 508 * 256, 250000), 512 * 256);
  EXPECT_EQ(comp.apply(Channel::accel_x, 490 * 256, 250000), 490 * 256);
}

TEST(DriftComp, WithoutACalibrationTheValueIsUnchanged) {
  DriftComp comp;
  comp.reset(false);
  comp.advance_to(1000000);
  EXPECT_FALSE(comp.active());
  EXPECT_EQ(comp.apply(Channel::accel_z, 123456, 1000000), 123456);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
