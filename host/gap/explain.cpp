// Candidate fits, held-out judgement and stepwise selection; see explain.hpp.
#include "host/gap/explain.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>

#include "host/gap/calibrate.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/code_density.hpp"
#include "host/gap/comparison.hpp"
#include "host/gap/mean_shapes.hpp"
#include "host/gap/nelder_mead.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/spectral_fit.hpp"
#include "host/gap/whittle.hpp"
#include "host/stats/median.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/parallel_for.hpp"

namespace driftlab::host::gap {

namespace {

// A held-out gap-score excess below this is no gap to shrink (the score is about 1 when the model explains the log).
constexpr double kMinHeldoutExcess = 0.2;

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

double sd_of(const std::vector<double>& v) {
    double m = 0, s = 0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size()));
}

// One channel's data, battery, real values and replicate runner.
struct Judge {
    const std::vector<double>& t_s;
    const std::vector<double>& y;  ///< this channel's log values [counts]
    Channel channel;
    BatteryOptions battery;
    std::vector<Cell> layout;
    std::vector<double> real;
    std::vector<double> residual;  ///< eq. 1 residual of the whole log (the battery's)
    double target_spread = 0.0;
    std::vector<bool> fitting;  ///< per sample: in the fitting part
    std::uint64_t seed;
    int threads;
    const std::vector<double>* raw = nullptr;  ///< this channel's raw codes (raw-mode log), or null
    double alpha = 0.0;                        ///< ExplainOptions::alpha

    Comparison evaluate(const GapModel& m, int replicates) const {
        return compare(real, run_replicates(m, t_s, battery, replicates, seed, threads), alpha);
    }
};

// The judge's channel's white noise matched again to the log's short-lag spread, with `m`'s effects in place.
void match_channel_noise(GapModel& m, const Judge& judge, std::uint64_t seed) {
    const std::size_t i = channel_index(judge.channel);
    std::array<bool, kChannelCount> only{};
    only[i] = true;
    std::array<double, kChannelCount> target{};
    target[i] = judge.target_spread;
    match_noise(m, judge.t_s, only, target, seed);
}

// An accepted effect of this channel that is fitted again beside each new candidate.
struct AcceptedProcess {
    std::size_t accepted_index;  ///< into ExplainResult::accepted
    std::size_t slot;            ///< into GapModel::effects
    std::string effect;
    std::vector<double> params;
};

struct Fitted {
    GapModel model;
    std::vector<double> params;
    std::vector<std::pair<std::size_t, std::vector<double>>> refits;  ///< accepted index, new parameters
    std::vector<std::string> names;  ///< the parameters' names when they vary per fit (adc_dnl), else empty
};

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
    const auto nm = nelder_mead(objective, best, {0.7, 0.7},
                                std::max(8, options.max_evaluations - static_cast<int>(starts.size())));
    return {model_at(nm.x), {std::exp(nm.x[0]), std::exp(nm.x[1])}, {}, {}};
}

// The converter's transitions where the fitting part's raw codes cross them (code_density.hpp), as a measured
// adc_dnl table. One converter serves every channel: a table fitted on another channel is kept, this one's codes
// replacing its entries where both cross the same codes.
Fitted fit_code_density(const GapModel& current, const Judge& judge) {
    std::vector<double> raw, level;
    for (std::size_t k = 0; k < judge.y.size(); ++k)
        if (judge.fitting[k]) raw.push_back((*judge.raw)[k]), level.push_back(judge.y[k]);
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

Explanation judge_candidate(const std::string& effect, const Fitted& fitted, const Judge& judge,
                            const Comparison& base_cmp, const ExplainOptions& options) {
    const Comparison cmp = judge.evaluate(fitted.model, options.eval_replicates);
    Explanation ex;
    ex.effect = effect;
    ex.channel = kChannelNames[channel_index(judge.channel)];
    const auto names = fitted.names.empty() ? candidate_param_names(effect, judge.channel) : fitted.names;
    for (std::size_t k = 0; k < names.size(); ++k) ex.params.emplace_back(names[k], fitted.params[k]);
    ex.gap_before = gap_score(base_cmp, judge.layout, in_segment(Segment::fit));
    ex.gap_after = gap_score(cmp, judge.layout, in_segment(Segment::fit));
    ex.heldout_before = gap_score(base_cmp, judge.layout, in_segment(Segment::heldout));
    ex.heldout_after = gap_score(cmp, judge.layout, in_segment(Segment::heldout));
    ex.heldout_bound = gap_score_threshold(base_cmp, judge.layout, in_segment(Segment::heldout), judge.alpha);
    const double excess = ex.heldout_before - 1.0;
    ex.heldout_shrink = excess > 0.0 ? (ex.heldout_before - ex.heldout_after) / excess : 0.0;
    ex.heldout_loss_gain =
        synthetic_loss(base_cmp, judge.layout, Segment::heldout) - synthetic_loss(cmp, judge.layout, Segment::heldout);
    // The penalised likelihood counts every cell: an effect confined in time (rare bursts) may fall mostly in one
    // part, and the held-out rules below already demand that the fit carries over.
    ex.loss_gain = synthetic_loss(base_cmp, judge.layout, Segment::fit) -
                   synthetic_loss(cmp, judge.layout, Segment::fit) + ex.heldout_loss_gain;
    ex.penalty = static_cast<double>(names.size()) * std::log(static_cast<double>(judge.layout.size()));
    ex.cells_left = locate(judge.real, cmp, judge.layout).size();
    for (std::size_t j = 0; j < judge.layout.size(); ++j)
        if (judge.layout[j].segment == Segment::heldout)
            ex.heldout_cell_loss.push_back(cmp.z[j] * cmp.z[j] + 2.0 * std::log(cmp.sim_sd[j]));
    ex.accepted = passes(ex, options.penalty_per_param, options.min_heldout_shrink);
    ex.gaussian = candidate(effect).route == FitRoute::deterministic || candidate(effect).route == FitRoute::spectral;
    ex.settle = candidate(effect).settle;
    // A Gauss-Markov process whose correlation time is not well inside the log shows neither its bump's fall nor
    // its plateau: within the log it is a flicker or a random walk (method: report coloured noise, don't choose).
    constexpr double kIdentifiableSpans = 20.0;
    if (effect == "gauss_markov")
        ex.long_memory = fitted.params[1] * kIdentifiableSpans > judge.t_s.back() - judge.t_s.front();
    return ex;
}

// The full-log spectral likelihood of the current model with the candidate added (all parameters fitted on the
// whole log) against the current model's (`base_nll`, `base_parameters`): the gain, the parameters added and the
// per-frequency terms.
void spectral_evidence(Explanation& ex, const GapModel& current, const Judge& judge,
                       const std::vector<AcceptedProcess>& earlier, double base_nll, int base_parameters) {
    const std::vector<bool> all(judge.t_s.size(), true);
    const bool shape = candidate(ex.effect).route == FitRoute::deterministic;
    GapModel m = shape ? fit_deterministic(ex.effect, current, judge, all).model : current;
    const PartPeriodogram p = residual_periodogram(m, judge, all);
    const SpectralFit fit = fit_noise(m, judge, p, earlier, shape ? "" : ex.effect, nullptr);
    spectral_nll(fit, judge.channel, m, p, &ex.spectral_terms);
    ex.spectral_gain = 2.0 * (base_nll - fit.nll);
    // A shape on a channel whose noise is the white floor alone (no Gaussian process accepted on it) must also
    // describe the log better than a hop and a return would (steps_over_shape()).
    if (shape && earlier.empty()) {
        const std::vector<double> with_shape = model_mean_counts(m, judge.channel, judge.t_s);
        const std::vector<double> without = model_mean_counts(current, judge.channel, judge.t_s);
        std::vector<double> shape_residual(judge.y.size()), base_residual(judge.y.size());
        for (std::size_t k = 0; k < judge.y.size(); ++k)
            shape_residual[k] = judge.y[k] - with_shape[k], base_residual[k] = judge.y[k] - without[k];
        const Eigen::MatrixXd q = eq1_tangent_basis(judge.t_s, current.base[channel_index(judge.channel)].drift.tau_s);
        ex.shape_steps = steps_over_shape(judge.t_s, base_residual, shape_residual, static_cast<int>(ex.params.size()),
                                          white_floor_long_run_factor(current.smoothing), q);
    }
    ex.spectral_extra_parameters =
        fit.free_parameters + (shape ? static_cast<int>(ex.params.size()) : 0) - base_parameters;
    ex.spectral_observations = p.count;
}

// The level-step test of the model with Gaussian-process candidate `spectral`: its Gaussian processes on this
// channel (the earlier ones and the candidate, with their parameters) whiten the residual.
LevelStep step_test(const GapModel& m, const Judge& judge, const std::vector<AcceptedProcess>& earlier,
                    const std::string& spectral, const std::vector<double>& params, const ExplainOptions& options) {
    std::vector<std::string> effects;
    std::vector<double> known;
    for (const AcceptedProcess& e : earlier)
        effects.push_back(e.effect), known.insert(known.end(), e.params.begin(), e.params.end());
    effects.push_back(spectral);
    known.insert(known.end(), params.begin(), params.end());
    return test_level_step(m, judge.channel, judge.t_s, judge.y, effects, known,
                           std::max(options.eval_replicates, options.step_replicates), options.seed + 17,
                           options.threads, options.step_alpha);
}

}  // namespace

bool passes(const Explanation& e, double penalty_per_param, double min_heldout_shrink) {
    // The held-out likelihood must improve too: a shrink bought by wider replicates does not count.
    return e.loss_gain > penalty_per_param * e.penalty && e.heldout_before - 1.0 > kMinHeldoutExcess &&
           e.heldout_shrink >= min_heldout_shrink && e.heldout_loss_gain > 0.0;
}

bool closes_gap(const Explanation& e, double step_alpha) {
    return !leaves_step(e.residual_step, step_alpha) && !e.shape_steps.steps_win;
}

double delta_ic(const Explanation& e, InformationCriterion ic) {
    return e.spectral_gain - e.spectral_extra_parameters * parameter_price(ic, e.spectral_observations);
}

bool close_call(const Explanation& best, const Explanation& runner_up, double z, InformationCriterion ic) {
    const auto low_frequency = [](const Explanation& e) {
        return e.effect == "flicker" || e.effect == "rate_random_walk";
    };
    if ((best.long_memory && low_frequency(runner_up)) || (runner_up.long_memory && low_frequency(best))) return true;
    const bool spectral = best.gaussian && runner_up.gaussian && !best.spectral_terms.empty() &&
                          best.spectral_terms.size() == runner_up.spectral_terms.size();
    const auto& a = spectral ? best.spectral_terms : best.heldout_cell_loss;
    const auto& b = spectral ? runner_up.spectral_terms : runner_up.heldout_cell_loss;
    const std::size_t n = std::min(a.size(), b.size());
    if (n < 2) return false;
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        const double d = b[j] - a[j];
        sum += d;
        sum2 += d * d;
    }
    const double nd = static_cast<double>(n);
    const double sd = std::sqrt(std::max(0.0, (sum2 - sum * sum / nd) / (nd - 1.0)));
    // Vuong's correction: the likelihood ratio is charged half the criterion's price per extra parameter.
    if (spectral)
        sum -= 0.5 * (best.spectral_extra_parameters - runner_up.spectral_extra_parameters) *
               parameter_price(ic, best.spectral_observations);
    return sum < z * std::sqrt(nd) * sd;
}

Choice choose(const std::vector<const Explanation*>& passing, InformationCriterion ic) {
    const Explanation *g1 = nullptr, *g2 = nullptr, *other = nullptr, *simpler = nullptr;
    for (const Explanation* e : passing) {
        if (e->gaussian) {
            if (!g1 || delta_ic(*e, ic) > delta_ic(*g1, ic)) {
                g2 = g1;
                g1 = e;
            } else if (!g2 || delta_ic(*e, ic) > delta_ic(*g2, ic)) {
                g2 = e;
            }
            if ((e->effect == "rate_random_walk" || e->effect == "flicker") &&
                (!simpler || delta_ic(*e, ic) > delta_ic(*simpler, ic)))
                simpler = e;
        } else if (!other || e->heldout_loss_gain > other->heldout_loss_gain) {
            other = e;
        }
    }
    if (other && (!g1 || other->heldout_loss_gain > g1->heldout_loss_gain)) return {other, g1};
    if (g1 && g1->long_memory && simpler &&
        delta_ic(*g1, ic) - delta_ic(*simpler, ic) <= parameter_price(ic, g1->spectral_observations))
        return {simpler, g1};
    return {g1, g2 ? g2 : other};
}

namespace {

struct CandidateOutcome {
    Explanation ex;
    GapModel model;
    std::vector<std::pair<std::size_t, std::vector<double>>> refits;
};

// The stepwise search's state after some steps.
struct SearchPath {
    ExplainResult result;
    std::array<std::vector<std::string>, kChannelCount> used;  ///< effects added per channel
    std::array<bool, kChannelCount> open;                      ///< channels still searched
};

// A channel's choice at one step and, when that is a Gaussian process, the best accepted mean shape beside it.
struct ChannelChoice {
    CandidateOutcome best;
    std::optional<CandidateOutcome> shape;
};

struct Search {
    const std::vector<double>& t_s;
    const std::array<const std::vector<double>*, kChannelCount>& y;
    const BatteryOptions& battery;
    const ExplainOptions& options;
    const RawCodes& raw;
    std::vector<std::string> names;
    std::size_t first_added;  // effects[first_added + k] is accepted[k]
    std::vector<bool> fitting;
    std::vector<bool> everywhere;

    // The Gaussian processes accepted on channel `i`, with their parameters and model slots.
    std::vector<AcceptedProcess> processes(const ExplainResult& r, std::size_t i) const {
        std::vector<AcceptedProcess> out;
        for (std::size_t k = 0; k < r.accepted.size(); ++k) {
            const Explanation& e = r.accepted[k];
            if (e.channel != kChannelNames[i] || candidate(e.effect).route != FitRoute::spectral) continue;
            std::vector<double> p;
            for (const auto& kv : e.params) p.push_back(kv.second);
            out.push_back({k, first_added + k, e.effect, p});
        }
        return out;
    }

    // Channel `i`'s judge with candidates fitted on `part`: the channel's own battery of the log, its eq. 1 residual
    // and short-lag spread.
    Judge judge_for(std::size_t i, const std::vector<bool>& part) const {
        Judge judge{t_s,
                    *y[i],
                    static_cast<Channel>(i),
                    battery,
                    {},
                    {},
                    {},
                    0.0,
                    part,
                    options.seed,
                    options.threads,
                    battery.raw_codes[i] ? raw[i] : nullptr,
                    options.alpha};
        judge.battery.channels = {};
        judge.battery.channels[i] = true;
        judge.battery.raw_codes = {};
        judge.battery.raw_codes[i] = battery.raw_codes[i];
        std::array<const std::vector<double>*, kChannelCount> yc{};
        yc[i] = y[i];
        RawCodes raw_c{};
        raw_c[i] = raw[i];
        const BatteryResult real = compute_battery(t_s, yc, judge.battery, &judge.layout, raw_c);
        judge.real = real.values;
        judge.residual = real.residual[i];
        judge.target_spread = short_lag_spread(judge.residual);
        return judge;
    }

    // Every open channel's candidates fitted and judged beside the path's model; tried fits are added to the path.
    std::vector<ChannelChoice> step(SearchPath& path, int step) const {
        std::vector<ChannelChoice> chosen;
        for (std::size_t i = 0; i < kChannelCount; ++i) {
            if (!path.open[i]) continue;
            const Channel c = static_cast<Channel>(i);
            const Judge judge = judge_for(i, fitting);
            const Comparison base_cmp = judge.evaluate(path.result.model, options.eval_replicates);
            // A channel stays open while cells are located or, after an accepted effect, a held-out excess remains
            // for another effect to shrink (one broad process may cover a line that is still there).
            const double heldout = gap_score(base_cmp, judge.layout, in_segment(Segment::heldout));
            const bool diffuse = options.diffuse_alpha > 0.0 &&
                                 heldout > gap_score_threshold(base_cmp, judge.layout, in_segment(Segment::heldout),
                                                               options.diffuse_alpha);
            if (locate(judge.real, base_cmp, judge.layout).empty() && !diffuse &&
                (step == 1 || heldout - 1.0 <= kMinHeldoutExcess)) {
                path.open[i] = false;
                continue;
            }
            // Gaussian processes accepted earlier on this channel are fitted again beside each new candidate:
            // one sized alone may have swallowed what the candidate explains (a broad flicker covers a sinusoid).
            const std::vector<AcceptedProcess> earlier = processes(path.result, i);
            const bool shaped =
                std::any_of(path.result.accepted.begin(), path.result.accepted.end(), [&](const Explanation& e) {
                    return e.channel == kChannelNames[i] && candidate(e.effect).route == FitRoute::deterministic;
                });
            const SpectralFit base_fit = [&] {
                GapModel m = path.result.model;
                return fit_noise(m, judge, residual_periodogram(m, judge, everywhere), earlier, "", nullptr);
            }();
            std::vector<std::string> to_try;
            for (const std::string& effect : names) {
                if (std::find(path.used[i].begin(), path.used[i].end(), effect) != path.used[i].end()) continue;
                if (effect == "spikes" && !tails_differ(judge, base_cmp)) continue;
                if (candidate(effect).route == FitRoute::code_density && !judge.raw) continue;  // needs raw codes
                to_try.push_back(effect);
            }
            // The candidates' fits are independent and mostly serial (the spectral fits): they run side by side, and
            // keep the list's order, so that the result does not depend on which finishes first.
            std::vector<std::optional<CandidateOutcome>> slots(to_try.size());
            std::mutex progress_mutex;
            parallel_for(to_try.size(), options.threads, [&](std::size_t n) {
                const std::string& effect = to_try[n];
                if (options.progress) {
                    const std::lock_guard<std::mutex> lock(progress_mutex);
                    options.progress("step " + std::to_string(step) + ", " + kChannelNames[i] + ": " + effect);
                }
                const FitRoute route = candidate(effect).route;
                // A process the base holds on this channel (not yet replaced on this path: the name is then in `used`)
                // is fitted in place of the model file's: the model it is judged against lacks that one outcomes.
                const bool replaces = route == FitRoute::spectral && holds(options.given, effect, c);
                const std::optional<GapModel> replaced =
                    replaces ? std::optional<GapModel>(without_held(path.result.model, *options.given, effect, c))
                             : std::nullopt;
                const GapModel& current = replaced ? *replaced : path.result.model;
                Fitted fitted;
                if (route == FitRoute::deterministic) {
                    fitted = fit_deterministic(effect, path.result.model, judge, fitting);
                    if (!earlier.empty())
                        fit_noise(fitted.model, judge, residual_periodogram(fitted.model, judge, fitting), earlier, "",
                                  &fitted.refits);
                } else if (route == FitRoute::spectral) {
                    fitted.model = current;
                    const SpectralFit f =
                        fit_noise(fitted.model, judge, residual_periodogram(fitted.model, judge, fitting), earlier,
                                  effect, &fitted.refits);
                    fitted.params.assign(
                        f.params.end() - static_cast<std::ptrdiff_t>(candidate(effect).param_keys.size()),
                        f.params.end());
                } else if (route == FitRoute::code_density) {
                    fitted = fit_code_density(path.result.model, judge);
                    if (fitted.params.empty()) return;  // no transition crossed often enough to place
                } else {
                    fitted = fit_spikes(path.result.model, judge, options);
                }
                // The candidate takes part of the short-lag spread: match the white noise again with it in place.
                match_channel_noise(fitted.model, judge, options.seed);
                Explanation ex = judge_candidate(effect, fitted, judge, base_cmp, options);
                // The choice among accepted candidates and the level-step test concern accepted ones only. The
                // level-step test is for Gaussian-process explanations, which can close the battery's gap around a
                // step: a mean shape's misfit is judged by the cells it leaves located, and spikes cannot hold a
                // level (a burst longer than one conversion, which the library's spikes do not make, would read as
                // a short step).
                ex.replaces_given = replaces;
                if (ex.accepted && ex.gaussian)
                    spectral_evidence(ex, current, judge, earlier, base_fit.nll, base_fit.free_parameters);
                if (options.step_test_candidates && ex.accepted && route == FitRoute::spectral && !shaped)
                    ex.residual_step = step_test(fitted.model, judge, earlier, effect, fitted.params, options);
                ex.step = step;
                slots[n] = CandidateOutcome{ex, fitted.model, std::move(fitted.refits)};
            });
            std::vector<CandidateOutcome> outcomes;  // this channel's candidates fitted at this step
            for (auto& o : slots)
                if (o) outcomes.push_back(std::move(*o));
            std::vector<const Explanation*> passing;
            for (const auto& o : outcomes)
                if (o.ex.accepted) passing.push_back(&o.ex);
            const Choice choice = choose(passing, options.information_criterion);
            std::size_t best_index = outcomes.size();
            for (std::size_t k = 0; k < outcomes.size(); ++k)
                if (&outcomes[k].ex == choice.best) best_index = k;
            if (choice.best && choice.runner_up &&
                close_call(*choice.best, *choice.runner_up, options.ambiguity_z, options.information_criterion)) {
                Explanation& b = outcomes[best_index].ex;
                b.ambiguous_with = choice.runner_up->effect;
                b.settle += "; vs " + choice.runner_up->effect + ": " + choice.runner_up->settle;
            }
            for (const auto& o : outcomes) path.result.tried.push_back(o.ex);
            if (best_index == outcomes.size()) {
                // Nothing passed, and the later steps change other channels only: they would make the same fits again.
                path.open[i] = false;
                continue;
            }
            // A process chosen over an accepted mean shape may have taken the shape's signal with the rest: the shape's
            // path is followed too (run()). A shape that two level steps beat is no explanation to follow.
            const CandidateOutcome* shape = nullptr;
            if (candidate(outcomes[best_index].ex.effect).route == FitRoute::spectral)
                for (const auto& o : outcomes)
                    if (o.ex.accepted && candidate(o.ex.effect).route == FitRoute::deterministic &&
                        !o.ex.shape_steps.steps_win &&
                        (!shape || delta_ic(o.ex, options.information_criterion) >
                                       delta_ic(shape->ex, options.information_criterion)))
                        shape = &o;
            chosen.push_back({outcomes[best_index], shape ? std::optional<CandidateOutcome>(*shape) : std::nullopt});
        }
        return chosen;
    }

    static SearchPath with(SearchPath path, const CandidateOutcome& o) {
        path.result.model = o.model;
        for (const auto& [k, params] : o.refits)
            for (std::size_t p = 0; p < params.size(); ++p) path.result.accepted[k].params[p].second = params[p];
        path.result.accepted.push_back(o.ex);
        if (const std::optional<Channel> c = channel_named(o.ex.channel))
            path.used[channel_index(*c)].push_back(o.ex.effect);
        return path;
    }

    // The full-log spectral information criterion of channel `i` under `r`'s model: its Gaussian processes fitted
    // again on the whole log beside its mean shapes, charged for those and for the shapes' parameters.
    double criterion(const ExplainResult& r, std::size_t i) const {
        const Judge judge{t_s,        *y[i],        static_cast<Channel>(i), battery, {},           {}, {}, 0.0,
                          everywhere, options.seed, options.threads,         nullptr, options.alpha};
        const std::vector<AcceptedProcess> earlier = processes(r, i);
        int shape_parameters = 0;
        for (const Explanation& e : r.accepted)
            if (e.channel == kChannelNames[i] && candidate(e.effect).route == FitRoute::deterministic)
                shape_parameters += static_cast<int>(e.params.size());
        GapModel m = r.model;
        const PartPeriodogram p = residual_periodogram(m, judge, everywhere);
        const SpectralFit fit = fit_noise(m, judge, p, earlier, "", nullptr);
        return 2.0 * fit.nll +
               parameter_price(options.information_criterion, p.count) * (fit.free_parameters + shape_parameters);
    }

    // The added effects (accepted[from...]) estimated again on the whole log once the held-out part has judged them:
    // on each channel its mean shapes one by one with eq. 1 beside the others, then its Gaussian processes together
    // on what the shapes leave, and the white noise matched again. The interleaved fitting part sees a slow
    // process only inside its blocks of one or two tenths of the log (the forecast part only before its end); the
    // whole log has all the data and its lowest frequencies. Spikes and a DNL table keep the fitting part's values.
    void estimate_on_whole_log(ExplainResult& r, std::size_t from) const {
        r.whole_log_model = r.model;
        GapModel& m = r.whole_log_model;
        for (std::size_t i = 0; i < kChannelCount; ++i) {
            const Channel c = static_cast<Channel>(i);
            bool outcomes = false, noise = false;
            for (std::size_t k = from; k < r.accepted.size(); ++k)
                if (r.accepted[k].channel == kChannelNames[i]) {
                    outcomes = true;
                    noise = noise || candidate(r.accepted[k].effect).route == FitRoute::spectral;
                }
            if (!outcomes) continue;
            const Judge judge = judge_for(i, everywhere);
            const auto record = [&](Explanation& e, const std::vector<double>& q) {
                e.whole_log_params = e.params;
                for (std::size_t p = 0; p < q.size(); ++p) e.whole_log_params[p].second = q[p];
            };
            for (std::size_t k = from; k < r.accepted.size(); ++k) {
                Explanation& e = r.accepted[k];
                if (e.channel != kChannelNames[i] || candidate(e.effect).route != FitRoute::deterministic) continue;
                const std::size_t slot = first_added + k;
                GapModel others = m;
                others.effects[slot] = without_channel(others.effects[slot], c);
                const Fitted f = fit_deterministic(e.effect, others, judge, everywhere);
                m.base[i].drift = f.model.base[i].drift;
                m.effects[slot] = make_candidate_effect(e.effect, c, f.params, m);
                record(e, f.params);
            }
            if (noise) {
                std::vector<std::pair<std::size_t, std::vector<double>>> refits;
                fit_noise(m, judge, residual_periodogram(m, judge, everywhere), processes(r, i), "", &refits);
                for (const auto& [k, q] : refits) record(r.accepted[k], q);
            }
            match_channel_noise(m, judge, options.seed);
        }
    }

    // Steps from `step` on. Across channels the choice with the largest held-out likelihood gain is added; where a
    // process was chosen over an accepted mean shape of its channel, the path with the shape instead is searched
    // as well and the one whose final model has the lower criterion on that channel is kept.
    ExplainResult run(SearchPath path, int step) const {
        if (step > options.max_effects) return std::move(path.result);
        std::vector<ChannelChoice> chosen = this->step(path, step);
        if (chosen.empty()) return std::move(path.result);
        const auto best =
            std::max_element(chosen.begin(), chosen.end(), [](const ChannelChoice& a, const ChannelChoice& b) {
                return a.best.ex.heldout_loss_gain < b.best.ex.heldout_loss_gain;
            });
        ExplainResult process_first = run(with(path, best->best), step + 1);
        if (!best->shape) return process_first;
        ExplainResult shape_first = run(with(path, *best->shape), step + 1);
        const std::size_t i = channel_index(channel_named(best->best.ex.channel).value());
        PathChoice choice{step,
                          best->best.ex.channel,
                          best->best.ex.effect,
                          best->shape->ex.effect,
                          criterion(process_first, i),
                          criterion(shape_first, i),
                          false};
        choice.shape_kept = choice.criterion_shape + options.shape_path_margin < choice.criterion_process;
        ExplainResult kept = choice.shape_kept ? std::move(shape_first) : std::move(process_first);
        kept.paths.insert(kept.paths.begin(), choice);
        return kept;
    }
};

}  // namespace

GivenEffects add_given_effects(GapModel& base, const std::vector<sim::EffectSpec>& effects,
                               const std::vector<double>& t_s,
                               const std::array<const std::vector<double>*, kChannelCount>& y,
                               const std::array<bool, kChannelCount>& channels,
                               const std::array<double, kChannelCount>& target_spread, std::uint64_t seed) {
    GivenEffects given;
    const auto named = [](const std::string& effect, Channel c, const std::vector<double>& params) {
        Explanation e;
        e.effect = effect;
        e.channel = kChannelNames[channel_index(c)];
        const auto names = candidate_param_names(effect, c);
        for (std::size_t k = 0; k < names.size(); ++k) e.params.emplace_back(names[k], params[k]);
        return e;
    };
    std::array<std::vector<std::string>, kChannelCount> shapes;
    for (const sim::EffectSpec& spec : effects) {
        const CandidateInfo* info = find_candidate(spec.name);
        const FitRoute route = info ? info->route : FitRoute::simulated;
        const bool shape_or_process = route == FitRoute::deterministic || route == FitRoute::spectral;
        bool elsewhere = !shape_or_process;  // a size the diagnosis does not take on: kept as the file gives it
        sim::EffectSpec rest = spec;
        for (std::size_t i = 0; i < kChannelCount && shape_or_process; ++i) {
            const Channel c = static_cast<Channel>(i);
            if (candidate_size_in(spec, c) == 0.0) continue;
            if (route == FitRoute::spectral && channels[i]) {
                hold_noise(base.held[i], spec, c, base);
                given.held.push_back(named(spec.name, c, file_process_params(spec, c)));
                given.held_slot.push_back(base.effects.size());  // pushed below
            } else if (channels[i] && std::find(shapes[i].begin(), shapes[i].end(), spec.name) == shapes[i].end()) {
                shapes[i].push_back(spec.name);  // one such shape per channel
                rest = without_channel(rest, c);
            } else {
                elsewhere = true;
            }
        }
        if (route == FitRoute::spectral) {
            base.effects.push_back(spec);  // simulated as the file gives it, on every channel
            if (elsewhere) given.kept.push_back(spec.name);
        } else if (elsewhere) {
            base.effects.push_back(rest);
            given.kept.push_back(spec.name);
        }
    }
    // The mean shapes after everything kept, in the order of `refitted` (explain() finds them there).
    const std::vector<bool> everywhere(t_s.size(), true);
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        // Deterministic shapes are fitted by least squares: this judge runs no replicates, so has no level.
        const Judge judge{t_s, *y[i], static_cast<Channel>(i), {}, {}, {}, {}, 0.0, everywhere, seed, 1, nullptr};
        for (const std::string& effect : shapes[i]) {
            Fitted f = fit_deterministic(effect, base, judge, everywhere);
            base = std::move(f.model);
            given.refitted.push_back(named(effect, judge.channel, f.params));
        }
    }
    match_noise(base, t_s, channels, target_spread, seed);
    return given;
}

ExplainResult explain(const GapModel& base, const std::vector<double>& t_s,
                      const std::array<const std::vector<double>*, kChannelCount>& y,
                      const std::array<bool, kChannelCount>& channels, const BatteryOptions& battery,
                      const ExplainOptions& options, const RawCodes& raw) {
    // The base's refitted effects are the first accepted ones of every path, at the end of the base's effects.
    const std::size_t given = options.given ? options.given->refitted.size() : 0;
    Search search{t_s,
                  y,
                  battery,
                  options,
                  raw,
                  options.candidates,
                  base.effects.size() - given,
                  fitting_mask(t_s, battery),
                  std::vector<bool>(t_s.size(), true)};
    if (search.names.empty())
        for (const auto& info : candidate_list()) search.names.push_back(info.effect);
    SearchPath start{{}, {}, channels};
    start.result.model = base;
    if (options.given) {
        start.result.accepted = options.given->refitted;
        for (const Explanation& e : options.given->refitted)
            if (const std::optional<Channel> c = channel_named(e.channel))
                start.used[channel_index(*c)].push_back(e.effect);
        // A kept spikes or adc_dnl is not tried again on any channel: both would draw the same numbers (spikes) or
        // hold one converter's table twice. (What a refitted effect keeps gives the channels not analysed only.)
        for (const std::string& name : options.given->kept) {
            const CandidateInfo* info = find_candidate(name);
            if (info && info->route != FitRoute::deterministic && info->route != FitRoute::spectral)
                for (auto& used : start.used) used.push_back(name);
        }
    }
    ExplainResult result = search.run(std::move(start), 1);
    search.estimate_on_whole_log(result, given);
    // The refitted shapes are the model file's, not added (their parameters are not refitted during the search).
    result.accepted.erase(result.accepted.begin(), result.accepted.begin() + static_cast<std::ptrdiff_t>(given));
    std::stable_sort(result.tried.begin(), result.tried.end(), [](const Explanation& a, const Explanation& b) {
        if (a.accepted != b.accepted) return a.accepted;
        return a.heldout_shrink > b.heldout_shrink;
    });
    return result;
}

}  // namespace driftlab::host::gap
