// The converter truth generator: a successive-approximation converter with a mismatched capacitor DAC. truth.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "host/gap_eval/truth.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kBits = 10;
constexpr int kTopCode = (1 << kBits) - 1;
// The comparator's input-referred noise per decision, per LSB of rms DNL: small beside the sensor's own noise, but
// it makes every decision of the search random, which no transition table is.
constexpr double kComparatorNoisePerDnl = 0.2;

// The largest code-width error the converter may have [LSB]: its worst code at most three LSB wide, or codes missing.
constexpr double kMaxAbsDnlLsb = 2.0;

using Weights = std::array<double, kBits>;

double dac(const Weights& w, int code) {
    double v = 0.0;
    for (int b = 0; b < kBits; ++b)
        if (code & (1 << b)) v += w[static_cast<std::size_t>(b)];
    return v;
}

// Ideal binary weights plus `errors`, rescaled so that the full-scale code keeps its ideal value (a gain error is
// not what this converter stands for).
Weights weights_with(const Weights& errors) {
    Weights w{};
    double sum = 0.0;
    for (int b = 0; b < kBits; ++b)
        sum += w[static_cast<std::size_t>(b)] = std::ldexp(1.0, b) + errors[static_cast<std::size_t>(b)];
    for (double& x : w) x *= kTopCode / sum;
    return w;
}

// Code j spans [dac(j) - 1/2, dac(j + 1) - 1/2): its width error is the DAC's step between neighbours less 1 LSB.
double dnl_lsb(const Weights& w, int code) { return dac(w, code + 1) - dac(w, code) - 1.0; }

double max_abs_dnl_lsb(const Weights& w) {
    double worst = 0.0;
    for (int j = 1; j < kTopCode; ++j) worst = std::max(worst, std::abs(dnl_lsb(w, j)));
    return worst;
}

// Root mean square of the code-width errors over `occupancy` (weights by code; empty: the inner codes 1..1022 alike).
double rms_dnl_lsb(const Weights& w, const std::vector<double>& occupancy) {
    double sum = 0.0, weight = 0.0;
    for (int j = 1; j < kTopCode; ++j) {
        const double h = occupancy.empty() ? 1.0 : occupancy[static_cast<std::size_t>(j)];
        const double dnl = dnl_lsb(w, j);
        sum += h * dnl * dnl;
        weight += h;
    }
    return weight > 0.0 ? std::sqrt(sum / weight) : 0.0;
}

}  // namespace

sim::Quantiser truth_sar_mismatch(double size_counts, const std::vector<double>& occupancy, std::uint64_t seed,
                                  std::uint64_t noise_seed) {
    // A self-calibrated converter: calibration leaves every bit's weight off by a residual of one absolute size
    // (raw unit-capacitor mismatch, growing as the square root of a bit's weight, would make the MSB carry some
    // thirty times the typical code's error, where calibration is aimed). A code's width error is the error of the
    // bit its carry sets less those of the bits it clears, so a carry through b bits is off by about sqrt(b + 1)
    // residuals: the largest at the MSB carry (code 511 -> 512), the sawtooth of a SAR's DNL plot.
    sim::Rng shape(seed, 0x78);
    Weights unit{};
    for (double& e : unit) e = shape.normal();
    // Scaled to the rms DNL asked for; the full-scale rescaling is nonlinear in the errors, so once more.
    Weights errors = unit;
    for (int pass = 0; pass < 2 && size_counts > 0.0; ++pass) {
        const double r = rms_dnl_lsb(weights_with(errors), occupancy);
        if (!(r > 0.0)) break;
        for (double& e : errors) e *= size_counts / r;
        // Where the log's own codes happen to be nearly right, the size asked for would need a converter far worse
        // next to them (its MSB carry is within a few noise deviations of mid-scale): a code many LSB wide, on which
        // the log sticks. Bounded, the worst code binds only beyond about 2 x a_50 (at 1 LSB it bound at 1 x and
        // flattened the detection curve).
        const double worst = max_abs_dnl_lsb(weights_with(errors));
        if (worst > kMaxAbsDnlLsb)
            for (double& e : errors) e *= kMaxAbsDnlLsb / worst;
    }
    if (!(size_counts > 0.0)) errors = {};
    struct State {
        Weights w;
        double comparator_sd;
        sim::Rng rng;
    };
    auto s = std::make_shared<State>(
        State{weights_with(errors), kComparatorNoisePerDnl * size_counts, sim::Rng(noise_seed, 0x79)});
    return [s](double x_counts) {
        // Successive approximation, MSB first: keep a bit when the input is at or above the DAC's trial level
        // less half an LSB (with ideal weights: round to nearest, clamped to 0..1023, as sim::Adc does).
        int code = 0;
        for (int b = kBits - 1; b >= 0; --b) {
            const int trial = code | (1 << b);
            if (x_counts + s->comparator_sd * s->rng.normal() >= dac(s->w, trial) - 0.5) code = trial;
        }
        return code;
    };
}

}  // namespace driftlab::host::gap
