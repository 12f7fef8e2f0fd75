// bandwidth: the sensor's own bandwidth, a first-order low-pass on the physical value, physical stage;
// docs/effects.md.
//
// Equation: y_k = y_(k-1) + (1 - e^(-dt/tau)) (x_k - y_(k-1)), tau = 1 / (2 pi f_c), per channel, x the value after
// the physical effects before it (the exact response of a first-order lag to an input held between instants). It
// starts settled (y = x at a channel's first instant). A transducer's internal filter precedes its output stage,
// so it comes after the input, the biases and the couplings, and before saturation. At rest it changes nothing a
// static log could see; in motion it delays and rounds the rate steps and the turns.
// Cannot represent: a second-order (resonant) response, a phase lag that differs from the first-order one.
#pragma once

#include <array>

#include "sim/effects/params.hpp"

namespace driftlab::sim {

struct BandwidthParams {
    ChannelValues cutoff_hz{};  ///< -3 dB frequency per channel [Hz]; 0 = not filtered

    template <class V>
    void visit(V& v) {
        v.field("cutoff_hz", cutoff_hz, "Hz", "-3 dB bandwidth per channel (scalar or 4 values); 0 = none",
                Check::nonneg);
    }
};

class Bandwidth : public EffectWith<Bandwidth, BandwidthParams> {
public:
    using Params = BandwidthParams;
    static constexpr std::string_view kName = "bandwidth";
    static constexpr Stage kStage = Stage::physical;
    static constexpr std::string_view kEquation = "y += (1 - e^(-dt 2 pi f_c)) (x - y)";
    static constexpr std::string_view kSummary = "the sensor's own bandwidth: a first-order low-pass";

    explicit Bandwidth(const Params& params) : EffectWith(params) { reset(0); }
    void reset(std::uint64_t) override { started_.fill(false); }
    void apply(ChannelValues& values, const EffectContext& ctx) override;

private:
    ChannelValues state_{};
    std::array<bool, kChannelCount> started_{};
};

}  // namespace driftlab::sim
