// The stepwise explanation search over candidate effects; see explain.hpp. Fitting and judging a candidate are in
// candidate_fit.cpp and candidate_judge.cpp.
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

using namespace explain_parts;

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
                    battery.raw_codes[i]      ? raw[i]
                    : battery.output_codes[i] ? y[i]
                                              : nullptr,
                    options.alpha};
        judge.battery.channels = {};
        judge.battery.channels[i] = true;
        judge.battery.raw_codes = {};
        judge.battery.raw_codes[i] = battery.raw_codes[i];
        judge.battery.output_codes = {};
        judge.battery.output_codes[i] = battery.output_codes[i];
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

    // What a step knows of one open channel while its candidates are fitted and judged.
    struct ChannelStep {
        std::size_t i;
        int step;
        Judge judge;
        Comparison base_cmp;                   // the path's model against the log
        std::vector<AcceptedProcess> earlier;  // Gaussian processes accepted on the channel
        SpectralFit base_fit;                  // the path's noise fitted on the whole log
        bool shaped;                           // a mean shape is accepted on the channel
    };

    // Channel `i` at this step, or none when it closes.
    std::optional<ChannelStep> open_channel(const SearchPath& path, std::size_t i, int step) const {
        Judge judge = judge_for(i, fitting);
        Comparison base_cmp = judge.evaluate(path.result.model, options.eval_replicates);
        // A channel stays open while cells are located or, after an accepted effect, a held-out excess remains
        // for another effect to shrink (one broad process may cover a line that is still there).
        const double heldout = gap_score(base_cmp, judge.layout, in_segment(Segment::heldout));
        const bool diffuse =
            options.diffuse_alpha > 0.0 &&
            heldout > gap_score_threshold(base_cmp, judge.layout, in_segment(Segment::heldout), options.diffuse_alpha);
        if (locate(judge.real, base_cmp, judge.layout).empty() && !diffuse &&
            (step == 1 || heldout - 1.0 <= kMinHeldoutExcess))
            return std::nullopt;
        // Gaussian processes accepted earlier on this channel are fitted again beside each new candidate:
        // one sized alone may have swallowed what the candidate explains (a broad flicker covers a sinusoid).
        std::vector<AcceptedProcess> earlier = processes(path.result, i);
        const bool shaped =
            std::any_of(path.result.accepted.begin(), path.result.accepted.end(), [&](const Explanation& e) {
                return e.channel == kChannelNames[i] && candidate(e.effect).route == FitRoute::deterministic;
            });
        GapModel m = path.result.model;
        const SpectralFit base_fit =
            fit_noise(m, judge, residual_periodogram(m, judge, everywhere), earlier, "", nullptr);
        return ChannelStep{i, step, std::move(judge), std::move(base_cmp), std::move(earlier), base_fit, shaped};
    }

    // One candidate fitted and judged beside the path's model; none when it has nothing to fit.
    std::optional<CandidateOutcome> try_candidate(const std::string& effect, const SearchPath& path,
                                                  const ChannelStep& s) const {
        const Judge& judge = s.judge;
        const FitRoute route = candidate(effect).route;
        // A process the base holds on this channel (not yet replaced on this path: the name is then in `used`)
        // is fitted in place of the model file's: the model it is judged against lacks that one outcomes.
        const bool replaces = route == FitRoute::spectral && holds(options.given, effect, judge.channel);
        const std::optional<GapModel> replaced =
            replaces ? std::optional<GapModel>(without_held(path.result.model, *options.given, effect, judge.channel))
                     : std::nullopt;
        const GapModel& current = replaced ? *replaced : path.result.model;
        Fitted fitted;
        if (route == FitRoute::deterministic) {
            fitted = fit_deterministic(effect, path.result.model, judge, fitting);
            if (!s.earlier.empty())
                fit_noise(fitted.model, judge, residual_periodogram(fitted.model, judge, fitting), s.earlier, "",
                          &fitted.refits);
        } else if (route == FitRoute::spectral) {
            fitted.model = current;
            const SpectralFit f = fit_noise(fitted.model, judge, residual_periodogram(fitted.model, judge, fitting),
                                            s.earlier, effect, &fitted.refits);
            fitted.params.assign(f.params.end() - static_cast<std::ptrdiff_t>(candidate(effect).param_keys.size()),
                                 f.params.end());
        } else if (route == FitRoute::code_density) {
            fitted = fit_code_density(path.result.model, judge);
            if (fitted.params.empty()) return std::nullopt;  // no transition crossed often enough to place
        } else {
            fitted = fit_spikes(path.result.model, judge, options);
        }
        // The candidate takes part of the short-lag spread: match the white noise again with it in place.
        match_channel_noise(fitted.model, judge, options.seed);
        Explanation ex = judge_candidate(effect, fitted, judge, s.base_cmp, options);
        // The choice among accepted candidates and the level-step test concern accepted ones only. The level-step
        // test is for Gaussian-process explanations, which can close the battery's gap around a step: a mean
        // shape's misfit is judged by the cells it leaves located, and spikes cannot hold a level (a burst longer
        // than one conversion, which the library's spikes do not make, would read as a short step).
        ex.replaces_given = replaces;
        if (ex.accepted && ex.gaussian)
            spectral_evidence(ex, current, judge, s.earlier, s.base_fit.nll, s.base_fit.free_parameters);
        if (options.step_test_candidates && ex.accepted && route == FitRoute::spectral && !s.shaped)
            ex.residual_step = step_test(fitted.model, judge, s.earlier, effect, fitted.params, options);
        ex.step = s.step;
        return CandidateOutcome{ex, fitted.model, std::move(fitted.refits)};
    }

    // The channel's candidates not yet on the path, fitted side by side (they are independent and mostly serial:
    // the spectral fits) and kept in the list's order, so that the result does not depend on which finishes first.
    std::vector<CandidateOutcome> fit_candidates(const SearchPath& path, const ChannelStep& s) const {
        const std::vector<std::string>& used = path.used[s.i];
        std::vector<std::string> to_try;
        for (const std::string& effect : names) {
            if (std::find(used.begin(), used.end(), effect) != used.end()) continue;
            if (effect == "spikes" && !tails_differ(s.judge, s.base_cmp)) continue;
            if (candidate(effect).route == FitRoute::code_density && !s.judge.raw) continue;  // needs raw codes
            to_try.push_back(effect);
        }
        std::vector<std::optional<CandidateOutcome>> slots(to_try.size());
        std::mutex progress_mutex;
        parallel_for(to_try.size(), options.threads, [&](std::size_t n) {
            if (options.progress) {
                const std::lock_guard<std::mutex> lock(progress_mutex);
                options.progress("step " + std::to_string(s.step) + ", " + kChannelNames[s.i] + ": " + to_try[n]);
            }
            slots[n] = try_candidate(to_try[n], path, s);
        });
        std::vector<CandidateOutcome> outcomes;
        for (auto& o : slots)
            if (o) outcomes.push_back(std::move(*o));
        return outcomes;
    }

    // The channel's choice among its candidates' outcomes, every one added to the path's tried; none when none passed.
    std::optional<ChannelChoice> choose_outcome(std::vector<CandidateOutcome> outcomes, SearchPath& path) const {
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
        if (best_index == outcomes.size()) return std::nullopt;
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
        return ChannelChoice{outcomes[best_index], shape ? std::optional<CandidateOutcome>(*shape) : std::nullopt};
    }

    // Every open channel's candidates fitted and judged beside the path's model; tried fits are added to the path.
    std::vector<ChannelChoice> step(SearchPath& path, int step) const {
        std::vector<ChannelChoice> chosen;
        for (std::size_t i = 0; i < kChannelCount; ++i) {
            if (!path.open[i]) continue;
            const std::optional<ChannelStep> s = open_channel(path, i, step);
            std::optional<ChannelChoice> choice;
            if (s) choice = choose_outcome(fit_candidates(path, *s), path);
            // Closed, or nothing passed (the later steps change other channels only: they would make the same fits).
            if (!choice) {
                path.open[i] = false;
                continue;
            }
            chosen.push_back(std::move(*choice));
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
