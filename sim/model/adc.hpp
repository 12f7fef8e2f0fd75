// The successive-approximation converter of the board: Vref, round-to-nearest quantisation, clipping at the
// rails. Transfer function of the ATmega328P ADC (datasheet §24.7, "ADC = Vin·1024/Vref", ideal first
// transition at 0.5 LSB); docs/sim.md §1 "The chain" (ADC).
#pragma once

#include <cstdint>

namespace driftlab::sim {

/// Converter parameters.
struct AdcParams {
    int bits = 10;        ///< resolution [bits], 1..16
    double vref_v = 5.0;  ///< reference voltage = full scale [V]
};

/// Ideal N-bit converter: code = clamp(floor(v / lsb + 0.5), 0, 2^bits - 1), lsb = Vref / 2^bits.
class Adc {
public:
    explicit Adc(const AdcParams& params);

    /// Quantises an input voltage [V] into a code [counts]; inputs beyond the rails clip to 0 or max_code().
    std::uint16_t convert(double input_v) const { return convert_counts(counts_from_volts(input_v)); }
    /// The same for an input already expressed in fractional counts (input / lsb).
    std::uint16_t convert_counts(double input_counts) const;

    /// Input voltage [V] expressed in (fractional, unquantised) counts.
    double counts_from_volts(double input_v) const { return input_v / lsb_v_; }

    double lsb_v() const { return lsb_v_; }               ///< one count [V]
    std::uint16_t max_code() const { return max_code_; }  ///< 2^bits - 1 [counts]
    const AdcParams& params() const { return params_; }

private:
    AdcParams params_;
    double lsb_v_;
    std::uint16_t max_code_;
};

}  // namespace driftlab::sim
