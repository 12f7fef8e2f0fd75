// Candidate judgement: held-out shrink, spectral evidence, the level-step test, and the choice among candidates
// that pass; see explain_parts.hpp and explain.hpp.
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

namespace driftlab::host::gap {

namespace explain_parts {

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

}  // namespace explain_parts

bool passes(const Explanation& e, double penalty_per_param, double min_heldout_shrink) {
    // The held-out likelihood must improve too: a shrink bought by wider replicates does not count.
    return e.loss_gain > penalty_per_param * e.penalty && e.heldout_before - 1.0 > explain_parts::kMinHeldoutExcess &&
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

}  // namespace driftlab::host::gap
