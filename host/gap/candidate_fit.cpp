// Candidate fitting: mean shapes by variable projection, Gaussian processes by their spectra, spikes and code
// densities by simulation; see explain_parts.hpp.
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>

#include "host/gap/calibrate.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/code_density.hpp"
#include "host/gap/comparison.hpp"
#include "host/gap/explain_parts.hpp"
#include "host/gap/mean_shapes.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/spectral_fit.hpp"
#include "host/gap/whittle.hpp"
#include "host/stats/median.hpp"
#include "host/stats/nelder_mead.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/parallel_for.hpp"

namespace driftlab::host::gap::explain_parts {

namespace {

double sd_of(const std::vector<double>& v) {
    double m = 0, s = 0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size()));
}

// The log minus the mean shapes accepted earlier (not eq. 1): what a new mean shape is fitted to, jointly with eq. 1.
std::vector<double> without_earlier_shapes(const GapModel& m, const Judge& judge) {
    GapModel shapes_only = m;
    const std::vector<double> with_shapes = model_mean_counts(shapes_only, judge.channel, judge.t_s);
    shapes_only.effects.clear();
    const std::vector<double> drift_only = model_mean_counts(shapes_only, judge.channel, judge.t_s);
    std::vector<double> out(judge.y.size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = judge.y[k] - (with_shapes[k] - drift_only[k]);
    return out;
}

}  // namespace

CellFilter in_segment(Segment s) {
    return [s](const Cell& c) { return c.segment == s; };
}

// Diagonal synthetic negative log-likelihood (x2) of the real cells: sum z^2 + 2 ln sd (Wood 2010). The ln sd
// term stops a candidate from "explaining" a gap by merely widening the replicates' spread.
double synthetic_loss(const Comparison& cmp, const std::vector<Cell>& layout, Segment s) {
    double loss = 0.0;
    for (std::size_t j = 0; j < layout.size(); ++j)
        if (layout[j].segment == s) loss += cmp.z[j] * cmp.z[j] + 2.0 * std::log(cmp.sim_sd[j]);
    return loss;
}

// The judge's channel's white noise matched again to the log's short-lag spread, with `m`'s effects in place.
void match_channel_noise(GapModel& m, const Judge& judge, std::uint64_t seed) {
    const std::size_t i = channel_index(judge.channel);
    std::array<bool, kChannelCount> only{};
    only[i] = true;
    std::array<double, kChannelCount> target{};
    target[i] = judge.target_spread;
    match_noise(m, judge.t_s, only, target, seed);
}

// A mean-shape candidate fitted with eq. 1 by variable projection on the samples of `part`.
Fitted fit_deterministic(const std::string& effect, const GapModel& current, const Judge& judge,
                         const std::vector<bool>& part) {
    const Channel c = judge.channel;
    const std::size_t i = channel_index(c);
    const double cpu = counts_per_unit(current, c);
    const std::vector<double> y = without_earlier_shapes(current, judge);
    std::vector<double> t_part, y_part;
    for (std::size_t k = 0; k < judge.t_s.size(); ++k)
        if (part[k]) t_part.push_back(judge.t_s[k]), y_part.push_back(y[k]);
    Fitted out{current, {}, {}, {}};
    if (effect == "thermal_second_tc") {
        const TwoExponentials f = fit_two_exponentials(t_part, y_part, t_part.size());
        out.model.base[i].drift = {f.c1_counts, f.c2_counts, f.t_s};
        out.params = {f.c3_counts / cpu, f.t2_s};
    } else {
        const ExponentialAndSine f = fit_exponential_and_sine(t_part, y_part, t_part.size());
        out.model.base[i].drift = {f.c1_counts, f.c2_counts, f.t_s};
        out.params = {f.amplitude_counts / cpu, f.period_s, f.phase_rad};
    }
    out.model.effects.push_back(make_candidate_effect(effect, c, out.params, out.model));
    return out;
}

// Spikes raise the residual's kurtosis before anything else: when the `tail` cells agree with the model
// (|z| < kTailScreenZ in both parts), spikes cannot explain the gap and their simulated fit is skipped.
bool tails_differ(const Judge& judge, const Comparison& cmp) {
    constexpr double kTailScreenZ = 2.0;
    for (std::size_t j = 0; j < judge.layout.size(); ++j)
        if (judge.layout[j].statistic == "tail" && std::abs(cmp.z[j]) >= kTailScreenZ) return true;
    return false;
}

// Periodogram, on `part`, of the differenced log minus the model's mean (eq. 1 and the mean shapes). Eq. 1 was fitted
// to the log, so the periodogram carries its tangent: a walk's lowest frequencies went into the fit (in a one-off
// check on 640 walks of 2 x a_50 the criterion named the walk in 81 % of logs without it, 85 % with it and 90 % on
// the residual of the true drift).
PartPeriodogram residual_periodogram(const GapModel& m, const Judge& judge, const std::vector<bool>& part) {
    const std::vector<double> mean = model_mean_counts(m, judge.channel, judge.t_s);
    std::vector<double> r(judge.y.size());
    for (std::size_t k = 0; k < r.size(); ++k) r[k] = judge.y[k] - mean[k];
    const Eigen::MatrixXd tangent = eq1_tangent(judge.t_s, m.base[channel_index(judge.channel)].drift.tau_s);
    return part_periodogram(r, part, &tangent);
}

// Whittle fit on `p` of the earlier spectral effects plus `extra` ("" = none); writes the refitted parameters into
// `m` (earlier slots in place, `extra` appended) and, when `refits` is not null, lists the earlier ones there.
SpectralFit fit_noise(GapModel& m, const Judge& judge, const PartPeriodogram& p,
                      const std::vector<AcceptedProcess>& earlier, const std::string& extra,
                      std::vector<std::pair<std::size_t, std::vector<double>>>* refits) {
    std::vector<std::string> effects;
    std::vector<double> known;
    for (const AcceptedProcess& e : earlier) {
        effects.push_back(e.effect);
        known.insert(known.end(), e.params.begin(), e.params.end());
    }
    if (!extra.empty()) effects.push_back(extra);
    const SpectralFit fit = fit_spectral(effects, judge.channel, m, p, known);
    std::size_t k = 0;
    for (const AcceptedProcess& e : earlier) {
        const std::vector<double> q(fit.params.begin() + static_cast<std::ptrdiff_t>(k),
                                    fit.params.begin() + static_cast<std::ptrdiff_t>(k + e.params.size()));
        m.effects[e.slot] = make_candidate_effect(e.effect, judge.channel, q, m);
        if (refits) refits->emplace_back(e.accepted_index, q);
        k += e.params.size();
    }
    if (!extra.empty()) {
        const std::vector<double> q(fit.params.begin() + static_cast<std::ptrdiff_t>(k), fit.params.end());
        m.effects.push_back(make_candidate_effect(extra, judge.channel, q, m));
    }
    return fit;
}

// Whether the base holds the model file's process `effect` on channel `c` (add_given_effects()).
bool holds(const GivenEffects* given, const std::string& effect, Channel c) {
    return given && std::any_of(given->held.begin(), given->held.end(), [&](const Explanation& e) {
               return e.effect == effect && e.channel == kChannelNames[channel_index(c)];
           });
}

// `m` with the model file's process `effect` taken off channel `c` (its spec zeroed there, the channel's held
// spectrum rebuilt from the others), for the candidate of that name to be fitted in its place.
GapModel without_held(const GapModel& m, const GivenEffects& given, const std::string& effect, Channel c) {
    GapModel out = m;
    const std::string channel = kChannelNames[channel_index(c)];
    HeldNoise& held = out.held[channel_index(c)];
    held = {};
    for (std::size_t k = 0; k < given.held.size(); ++k) {
        if (given.held[k].channel != channel) continue;
        sim::EffectSpec& spec = out.effects[given.held_slot[k]];
        if (given.held[k].effect == effect) spec = without_channel(spec, c);
        if (candidate_size_in(spec, c) != 0.0) hold_noise(held, spec, c, out);
    }
    return out;
}

// Spikes: Nelder-Mead on log (rate, scale) minimising the synthetic loss of the fitting cells, started from a
// robust outlier count (a spike of s counts in one conversion leaves about s/N in the output).
Fitted fit_spikes(const GapModel& current, const Judge& judge, const ExplainOptions& options) {
    const double span_s = judge.t_s.back() - judge.t_s.front();
    auto model_at = [&](const std::vector<double>& log_p) {
        GapModel m = current;
        m.effects.push_back(
            make_candidate_effect("spikes", judge.channel, {std::exp(log_p[0]), std::exp(log_p[1])}, current));
        return m;
    };
    auto objective = [&](const std::vector<double>& log_p) {
        return synthetic_loss(judge.evaluate(model_at(log_p), options.fit_replicates), judge.layout, Segment::fit);
    };
    const auto& e = judge.residual;
    std::vector<double> dev(e.size());
    for (std::size_t k = 0; k < e.size(); ++k) dev[k] = std::abs(e[k]);
    const double scale = 1.4826 * stats::median(dev) + 0.1;
    std::vector<double> outliers;
    for (double d : dev)
        if (d > 5.0 * scale) outliers.push_back(d);
    const double rate = std::max(1.0, static_cast<double>(outliers.size())) / span_s;
    const double amp = (outliers.empty() ? 5.0 * scale : sd_of(outliers) + outliers.front()) * current.smoothing.window;
    const std::vector<std::vector<double>> starts{{std::log(rate), std::log(amp)},
                                                  {std::log(rate * 3), std::log(amp / 2)}};
    std::vector<double> best = starts.front();
    double best_value = INFINITY;
    for (const auto& s : starts) {
        const double v = objective(s);
        if (v < best_value) best_value = v, best = s;
    }
    const auto nm = stats::nelder_mead(objective, best, {0.7, 0.7},
                                       std::max(8, options.max_evaluations - static_cast<int>(starts.size())));
    return {model_at(nm.x), {std::exp(nm.x[0]), std::exp(nm.x[1])}, {}, {}};
}

// The converter's transitions where the fitting part's raw codes cross them (code_density.hpp), as a measured
// adc_dnl table. One converter serves every channel: a table fitted on another channel is kept, this one's codes
// replacing its entries where both cross the same codes.
Fitted fit_code_density(const GapModel& current, const Judge& judge) {
    // Outputs that are codes themselves are placed against their neighbours, as the battery's codes cells place them.
    const std::vector<double> levels =
        judge.battery.output_codes[channel_index(judge.channel)] ? neighbour_level(judge.y) : judge.y;
    std::vector<double> raw, level;
    for (std::size_t k = 0; k < judge.y.size(); ++k)
        if (judge.fitting[k]) raw.push_back((*judge.raw)[k]), level.push_back(levels[k]);
    const TransitionFit fit = fit_transitions(raw, level);
    Fitted out{current, {}, {}, {}};
    std::map<std::int64_t, double> table;
    auto slot = std::find_if(out.model.effects.begin(), out.model.effects.end(),
                             [](const sim::EffectSpec& e) { return e.name == "adc_dnl"; });
    if (slot != out.model.effects.end()) {
        const auto* codes = slot->table["transition_codes"].as_array();
        const auto* counts = slot->table["transition_counts"].as_array();
        for (std::size_t k = 0; codes && counts && k < codes->size(); ++k)
            table[codes->get(k)->value_or<std::int64_t>(0)] = counts->get(k)->value_or(0.0);
    }
    for (const auto& t : fit.transitions) {
        table[t.code] = t.counts;
        out.params.push_back(t.counts);
        out.names.push_back("t" + std::to_string(t.code) + "_counts");
    }
    sim::EffectSpec spec{"adc_dnl", {}};
    toml::array codes, counts;
    double previous = -1e300;
    for (const auto& [code, counts_at] : table) {
        const double t = std::max(counts_at, previous + 1e-3);  // tables of two channels meet increasing
        codes.push_back(code);
        counts.push_back(t);
        previous = t;
    }
    spec.table.insert_or_assign("transition_codes", codes);
    spec.table.insert_or_assign("transition_counts", counts);
    if (slot != out.model.effects.end()) {
        out.model.effects[static_cast<std::size_t>(slot - out.model.effects.begin())] = spec;
    } else {
        out.model.effects.push_back(spec);
    }
    return out;
}

}  // namespace driftlab::host::gap::explain_parts
