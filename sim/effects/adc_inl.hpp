// E7 adc_inl: ADC integral non-linearity as a smooth bow/S curve of the code, converter stage; docs/effects.md.
//
// Equation: x = x + sum_{n=2..4} a_n P_n(u),  u = 2 x / 1023 - 1 (clamped to [-1, 1]),  P_n Legendre:
//   P2 = (3u^2 - 1)/2 (bow),  P3 = (5u^3 - 3u)/2 (S curve),  P4 = (35u^4 - 30u^2 + 3)/8 (gap-method.md E7).
// Acts on the continuous ADC input before the quantiser (a shift of the transition levels), so apply it before
// adc_dnl. The same INL(c) applies to every channel (one converter).
// Cannot represent: INL with fine structure (use adc_dnl), offset and gain error (P0, P1: part of the base model).
#pragma once

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct AdcInlParams {
    double a2_lsb = 0.0;  ///< Legendre P2 coefficient, bow [LSB]
    double a3_lsb = 0.0;  ///< Legendre P3 coefficient, S curve [LSB]
    double a4_lsb = 0.0;  ///< Legendre P4 coefficient [LSB]

    template <class V>
    void visit(V& v) {
        v.field("a2_lsb", a2_lsb, "LSB", "bow: coefficient of P2(2c/1023 - 1)");
        v.field("a3_lsb", a3_lsb, "LSB", "S curve: coefficient of P3");
        v.field("a4_lsb", a4_lsb, "LSB", "coefficient of P4");
    }
};

class AdcInl : public EffectWith<AdcInl, AdcInlParams> {
public:
    using Params = AdcInlParams;
    static constexpr std::string_view kName = "adc_inl";
    static constexpr Stage kStage = Stage::converter;
    static constexpr std::string_view kEquation = "x += a2 P2(u) + a3 P3(u) + a4 P4(u), u = 2x/1023 - 1";
    static constexpr std::string_view kSummary = "ADC integral non-linearity, Legendre bow/S curve (E7)";

    explicit AdcInl(const Params& params) : EffectWith(params) {}
    void reset(std::uint64_t) override {}
    void apply(ChannelValues& values, const EffectContext& ctx) override;

    /// INL at a continuous code [LSB].
    double inl_lsb(double x_counts) const;
};

}  // namespace driftlab::sim
