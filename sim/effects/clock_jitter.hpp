// E13 clock_jitter: sample-clock drift and white sample-time jitter, timing stage; docs/effects.md.
//
// Equation: t_actual = t_nominal (1 + rho 1e-6) + sigma_j eta_k, eta_k ~ N(0, 1) per conversion/sample
// (gap-method.md E13; imusim ParametricTimer freqError ppm). rho > 0: the board's clock runs slow against true
// time, so instants that the firmware believes are t happen at t (1 + rho 1e-6) of true time.
// apply() is the identity; the chain calls actual_instant_s(). One substream per channel (plus one for whole
// samples), so jitter draws do not depend on the round-robin order.
// Cannot represent: correlated (random-walk) phase noise, temperature-dependent drift, jitter large enough to
// reorder conversions (a model file's sigma_j must be at most a tenth of a channel's conversion interval,
// sim/model/model_file.cpp; the sensor model never lets an instant go before its channel's previous one).
#pragma once

#include <vector>

#include "sim/effects/params.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

struct ClockJitterParams {
    double drift_ppm = 0.0;  ///< clock rate error rho [ppm]
    double jitter_s = 0.0;   ///< std of the white instant jitter sigma_j [s]

    template <class V>
    void visit(V& v) {
        v.field("drift_ppm", drift_ppm, "ppm", "clock rate error rho (signed)");
        v.field("jitter_s", jitter_s, "s", "standard deviation of the white sample-time jitter", Check::nonneg);
    }
    // At -1e6 ppm the board's clock stands still, below it time runs backwards.
    void validate(const TomlReader& r) const {
        if (!(drift_ppm > -1e6)) r.fail("drift_ppm", "expected drift_ppm > -1e6 [ppm] (at -1e6 the clock stops)");
    }
};

class ClockJitter : public EffectWith<ClockJitter, ClockJitterParams> {
public:
    using Params = ClockJitterParams;
    static constexpr std::string_view kName = "clock_jitter";
    static constexpr Stage kStage = Stage::timing;
    static constexpr std::string_view kEquation = "t = t_nom (1 + rho 1e-6) + sigma_j eta";
    static constexpr std::string_view kSummary = "sample-clock drift (ppm) and sample-time jitter (E13)";

    explicit ClockJitter(const Params& params) : EffectWith(params) { reset(0); }
    void reset(std::uint64_t seed) override;
    void apply(ChannelValues&, const EffectContext&) override {}
    double actual_instant_s(double nominal_s, const EffectContext& ctx) override;

private:
    std::vector<Rng> rng_;  // one per channel, then one for whole samples
};

}  // namespace driftlab::sim
