// DriftComp: fixed-point forward correction (drift_comp.hpp; docs/firmware.md "Drift compensation").
#include "firmware/core/drift_comp.hpp"

namespace driftlab {
namespace fw {
namespace {

constexpr int32_t kMidScaleQ8 = 512L * 256;

// round(2^shift / d) for a quotient that fits 32 bits, by restoring division one bit at a time: the only division
// the calibration needs, without the 64-bit division routine the AVR would otherwise link.
uint32_t round_pow2_over(uint8_t shift, uint32_t d) {
  uint32_t q = 0;
  uint32_t r = 1;  // the numerator's one set bit, below d
  for (uint8_t i = 0; i < shift; ++i) {
    const bool carry = (r & 0x80000000UL) != 0;
    r <<= 1;
    q <<= 1;
    if (carry || r >= d) {
      r -= d;
      q |= 1U;
    }
  }
  return r >= d - r ? q + 1U : q;
}

// a b as two 32-bit words, from four 16 x 16 products: on the AVR a 64-bit product and the shift that takes its high
// word are library loops (send_sample took 10 000 cycles more with them).
struct Wide {
  uint32_t high;
  uint32_t low;
};

// 16-bit halves widened at the multiply, which the AVR does in one library call of some 30 cycles.
inline uint32_t mul16(uint16_t x, uint16_t y) { return static_cast<uint32_t>(x) * y; }

Wide mul_wide(uint32_t a, uint32_t b) {
  const uint16_t a0 = static_cast<uint16_t>(a);
  const uint16_t a1 = static_cast<uint16_t>(a >> 16);
  const uint16_t b0 = static_cast<uint16_t>(b);
  const uint16_t b1 = static_cast<uint16_t>(b >> 16);
  const uint32_t low_low = mul16(a0, b0);
  const uint32_t mid = mul16(a1, b0) + (low_low >> 16);  // below 2^32: (2^16 - 1)^2 + 2^16 - 1
  const uint32_t mid2 = mul16(a0, b1) + (mid & 0xFFFFU);
  return Wide{mul16(a1, b1) + (mid >> 16) + (mid2 >> 16), (mid2 << 16) | (low_low & 0xFFFFU)};
}

// a b / 2^shift for shift >= 32, rounded to nearest (ties up).
uint32_t mul_shift(uint32_t a, uint32_t b, uint8_t shift) {
  const Wide p = mul_wide(a, b);
  const uint8_t k = static_cast<uint8_t>(shift - 32U);
  if (k == 0) {
    return p.high + (p.low >> 31);
  }
  return (p.high >> k) + ((p.high >> (k - 1U)) & 1U);
}

// The high 64 bits of the 128-bit product of two Q64 fractions, less at most 2 units of the last place.
uint64_t mul_q64(uint64_t a, uint64_t b) {
  const uint32_t ah = static_cast<uint32_t>(a >> 32);
  const uint32_t bh = static_cast<uint32_t>(b >> 32);
  return static_cast<uint64_t>(ah) * bh + ((static_cast<uint64_t>(ah) * static_cast<uint32_t>(b)) >> 32) +
         ((static_cast<uint64_t>(static_cast<uint32_t>(a)) * bh) >> 32);
}

// e^(-n x) = (1 - s)^n as a Q32 fraction, by squaring the complement u = 1 - (1 - s)^m in Q64: s keeps its relative
// precision there (powering (1 - s) in Q32 would multiply its rounding by n), and 1 - u loses only the low half.
uint32_t power_q32(uint32_t s_mantissa, uint8_t s_shift, uint32_t n) {
  if (n == 0) {
    return 0xFFFFFFFFUL;
  }
  const uint64_t s = static_cast<uint64_t>(s_mantissa) << (64U - s_shift);
  uint8_t bit = 31;
  while ((n >> bit) == 0) {
    --bit;
  }
  uint64_t u = s;
  while (bit-- != 0) {
    // 1 - (1 - u)^2 and 1 - (1 - u)(1 - s) only grow u and stay below 1, so the wrap of 2u cancels; a result below u
    // is one that the products' truncation pushed past 1.
    const uint64_t squared = 2U * u - mul_q64(u, u);
    u = squared < u ? ~static_cast<uint64_t>(0) : squared;
    if (((n >> bit) & 1U) != 0) {
      const uint64_t stepped = u + s - mul_q64(u, s);
      u = stepped < u ? ~static_cast<uint64_t>(0) : stepped;
    }
  }
  const uint64_t e = 0U - u;
  return e >= 0xFFFFFFFF80000000ULL ? 0xFFFFFFFFUL : static_cast<uint32_t>((e + 0x80000000ULL) >> 32);
}

}  // namespace

StepDecay step_decay(uint32_t t_ms) {
  // x = h / T = (2^16 / 250000 s) / (T_ms / 1000 s) = 2^15 / d with d = 125 T_ms < 2^L: scaled by 2^(15 + L) it
  // lies in (2^30, 2^31], so s keeps 30 significant bits whatever T is.
  const uint32_t d = 125UL * t_ms;
  uint8_t bits = 0;
  while (bits < 32 && (d >> bits) != 0) {
    ++bits;
  }
  StepDecay out = {0, static_cast<uint8_t>(15U + bits)};
  const uint32_t x = round_pow2_over(static_cast<uint8_t>(30U + bits), d);
  // 1 - e^-x = x - x^2/2 + x^3/6 - x^4/24 + x^5/120: with x < 0.0044 the next term is below the last bit.
  uint32_t term = x;
  out.mantissa = x;
  for (uint8_t k = 2; k <= 5; ++k) {
    term = (mul_shift(term, x, out.shift) + k / 2U) / k;
    out.mantissa = (k % 2U) == 0 ? out.mantissa - term : out.mantissa + term;
  }
  return out;
}

void ChannelDrift::load(const ChannelModel& model, uint32_t steps, bool settled) {
  c1_q8_ = model.c1_q8;
  offset_q8_ = model.zero ? model.c1_q8 + model.c2_q8 - kMidScaleQ8 : 0;
  s_ = step_decay(model.t_ms);
  // a^steps by squaring, so a calibration uploaded hours after power-on costs some 64 products, not one per step.
  e_q32_ = settled ? 0 : power_q32(s_.mantissa, s_.shift, steps);
  prepare_step();
}

void ChannelDrift::step() {
  e_q32_ -= d_q32_;
  prepare_step();
}

void ChannelDrift::prepare_step() {
  // The step's decrement d = E s, and the chord's bow d x/2 (below), once a grid step rather than once a SAMPLE.
  d_q32_ = mul_shift(e_q32_, s_.mantissa, s_.shift);
  bend_q32_ = mul_shift(d_q32_, s_.mantissa >> 1, s_.shift);
}

uint32_t ChannelDrift::e_q32(uint16_t fraction) const {
  // The chord to the next grid point lies above the exponential by E x^2/2 f (1 - f) (to second order); with the
  // step's decrement d = E s ~ E x that is d x/2 f (1 - f). Error left: some x^3 E / 30, below 1e-8 E for T >= 60 s.
  const uint32_t along = mul_shift(d_q32_, static_cast<uint32_t>(fraction) << 16, 32);
  const uint32_t bow = mul_shift(bend_q32_, static_cast<uint32_t>(fraction) * (kCompStepTicks - fraction), 32);
  return e_q32_ - along - bow;
}

int32_t ChannelDrift::correction_q8(uint16_t fraction) const {
  const uint32_t magnitude = c1_q8_ < 0 ? static_cast<uint32_t>(-c1_q8_) : static_cast<uint32_t>(c1_q8_);
  const int32_t c1_e = static_cast<int32_t>(mul_shift(magnitude, e_q32(fraction), 32));
  return (c1_q8_ < 0 ? -c1_e : c1_e) - offset_q8_;
}

void DriftComp::reset(bool warm) {
  grid_tick_ = 0;
  steps_ = 0;
  active_ = false;
  settled_ = warm;
}

void DriftComp::load(const ChannelModel (&models)[kChannelCount]) {
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    channels_[c].load(models[c], steps_, settled_);
  }
  active_ = true;
}

void DriftComp::advance_to(uint32_t tick) {
  while (static_cast<uint32_t>(tick - grid_tick_) >= kCompStepTicks) {
    grid_tick_ += kCompStepTicks;
    ++steps_;
    if (active_ && !settled_) {
      for (uint8_t c = 0; c < kChannelCount; ++c) {
        channels_[c].step();
      }
    }
  }
}

int32_t DriftComp::apply(Channel channel, int32_t value_q8, uint32_t tick) const {
  if (!active_) {
    return value_q8;
  }
  const uint16_t fraction = static_cast<uint16_t>(tick - grid_tick_);
  return value_q8 + channels_[channel_index(channel)].correction_q8(fraction);
}

}  // namespace fw
}  // namespace driftlab
