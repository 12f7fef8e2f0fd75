// E6 adc_dnl: ADC differential non-linearity and missing codes as a code-transition table, converter stage;
// docs/effects.md.
//
// Equation: code = #{ j in 1..1023 : T_j <= x }, x = continuous ADC input [counts]; ideal T_j = j - 1/2.
//   Widths W_j = T_{j+1} - T_j = 1 + DNL_j [LSB] for codes 1..1022, DNL_j = rms * eta_j (+ carry_dnl on codes
//   that are multiples of 2^carry_bits: the SAR major-carry pattern), W_j >= 0, W_j = 0 for listed missing codes;
//   then all widths are rescaled so that T_1 = 0.5 and T_1023 = 1022.5 stay ideal (no gain error: that is INL's).
//   Code 0 and 1023 are the open end codes. (gap-method.md E6; IEEE 1241 code-density test.) Listed transitions
//   (transition_codes, transition_counts: a measured table, or what the gap diagnosis fits) then replace T_j at
//   their codes; the table is kept increasing.
// The pattern is a property of the device: it is drawn once from `pattern_seed` (not the run seed), so every run
// and replicate of a model sees the same DNL. apply() returns integral codes; the chain's rounding keeps them.
// Default parameters leave the input untouched (the chain's ideal rounding applies).
// Cannot represent: noise on the transitions (code-edge noise), DNL that depends on the previous code or on the
// conversion rate, converters other than 10-bit.
#pragma once

#include <cmath>
#include <vector>

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct AdcDnlParams {
    double dnl_rms_lsb = 0.0;                    ///< rms of the random DNL before rescaling [LSB]
    std::vector<std::int64_t> missing_codes;     ///< codes of width 0, in 1..1022 [counts]
    std::uint64_t carry_bits = 0;                ///< codes that are multiples of 2^carry_bits get carry_dnl, 0 = none
    double carry_dnl_lsb = 0.0;                  ///< extra DNL at those codes [LSB]
    std::uint64_t pattern_seed = 1;              ///< seed of the device's DNL pattern (independent of the run seed)
    std::vector<std::int64_t> transition_codes;  ///< codes j whose lower transition is given (a measured table)
    std::vector<double> transition_counts;       ///< T_j of those codes [counts], overriding the pattern there

    template <class V>
    void visit(V& v) {
        v.field("dnl_rms_lsb", dnl_rms_lsb, "LSB", "rms of the random code-width error", Check::nonneg);
        v.field("missing_codes", missing_codes, "counts", "codes that never occur (width 0)", 1, 1022);
        v.field("carry_bits", carry_bits, "bits", "SAR carry pattern period 2^carry_bits (0 = none)");
        v.field("carry_dnl_lsb", carry_dnl_lsb, "LSB", "extra DNL on codes that are multiples of 2^carry_bits");
        v.field("pattern_seed", pattern_seed, "-", "seed of the device's fixed DNL pattern");
        v.field("transition_codes", transition_codes, "counts", "codes whose lower transition is given", 1, 1023);
        v.field("transition_counts", transition_counts, "counts", "the input at which each of those codes begins");
    }
    void validate(const TomlReader& r) const {
        if (carry_bits > 9) r.fail("carry_bits", "expected 0..9 bits for a 10-bit converter");
        if (carry_dnl_lsb < -1.0) r.fail("carry_dnl_lsb", "expected >= -1 [LSB] (-1 = missing code)");
        if (transition_codes.size() != transition_counts.size())
            r.fail("transition_counts", "expected one value per entry of transition_codes");
        for (std::size_t k = 0; k < transition_codes.size(); ++k) {
            const double ideal = static_cast<double>(transition_codes[k]) - 0.5;
            if (!(std::abs(transition_counts[k] - ideal) < 1.0))
                r.fail("transition_counts", "expected each transition within 1 LSB of its ideal place (code - 1/2)");
            if (k > 0 &&
                (transition_codes[k] <= transition_codes[k - 1] || transition_counts[k] <= transition_counts[k - 1]))
                r.fail("transition_codes", "expected increasing codes with increasing transitions");
        }
    }
};

class AdcDnl : public EffectWith<AdcDnl, AdcDnlParams> {
public:
    using Params = AdcDnlParams;
    static constexpr std::string_view kName = "adc_dnl";
    static constexpr Stage kStage = Stage::converter;
    static constexpr std::string_view kEquation = "code = #{j : T_j <= x}, T_{j+1} - T_j = 1 + DNL_j";
    static constexpr std::string_view kSummary = "ADC differential non-linearity and missing codes (E6)";
    static constexpr int kCodeCount = 1024;

    explicit AdcDnl(const Params& params);
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;

    /// Code for a continuous input x [counts] through the transition table.
    int code_of(double x_counts) const;
    /// Lower transition T_j of code j in 1..1023 [counts].
    double transition_counts(int code) const { return transitions_[static_cast<std::size_t>(code - 1)]; }

private:
    bool active_ = false;
    std::vector<double> transitions_;  // T_1 .. T_1023
};

}  // namespace driftlab::sim
