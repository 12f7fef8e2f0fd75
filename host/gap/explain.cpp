// Candidate fits, held-out judgement and stepwise selection; see explain.hpp.
#include "host/gap/explain.hpp"

#include <algorithm>
#include <cmath>

#include "host/gap/calibrate.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/comparison.hpp"
#include "host/gap/mean_shapes.hpp"
#include "host/gap/nelder_mead.hpp"
#include "host/gap/replicates.hpp"

namespace driftlab::host::gap {

namespace {

constexpr double kAlpha = 0.05;

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

std::size_t cells_in(const std::vector<Cell>& layout, Segment s) {
    return static_cast<std::size_t>(std::count_if(layout.begin(), layout.end(), [s](const Cell& c) { return c.segment == s; }));
}

// One channel's battery, real values and replicate runner.
struct Judge {
    const std::vector<double>& t_s;
    BatteryOptions battery;
    std::vector<Cell> layout;
    std::vector<double> real;
    std::vector<double> residual;
    double target_spread = 0.0;
    std::vector<double> t_fit, y_fit;  ///< the fitting part's instants and values (deterministic fits)
    std::uint64_t seed;
    int threads;

    Comparison evaluate(const GapModel& m, int replicates) const {
        return compare(real, run_replicates(m, t_s, battery, replicates, seed, threads), kAlpha);
    }
};

double sd_of(const std::vector<double>& v) {
    double m = 0, s = 0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size()));
}

struct Fitted {
    GapModel model;
    std::vector<double> params;
};

Fitted fit_deterministic(const std::string& effect, const GapModel& current, Channel c, const Judge& judge) {
    const std::size_t i = channel_index(c);
    const double cpu = counts_per_unit(current, c);
    Fitted out{current, {}};
    if (effect == "thermal_second_tc") {
        const TwoExponentials f = fit_two_exponentials(judge.t_fit, judge.y_fit, judge.t_fit.size());
        out.model.base[i].drift = {f.c1_counts, f.c2_counts, f.t_s};
        out.params = {f.c3_counts / cpu, f.t2_s};
    } else {
        const ExponentialAndSine f = fit_exponential_and_sine(judge.t_fit, judge.y_fit, judge.t_fit.size());
        out.model.base[i].drift = {f.c1_counts, f.c2_counts, f.t_s};
        out.params = {f.amplitude_counts / cpu, f.period_s, f.phase_rad};
    }
    return out;
}

Fitted fit_simulated(const std::string& effect, const GapModel& current, Channel c, const Judge& judge,
                     const ExplainOptions& options) {
    const double cpu = counts_per_unit(current, c);
    const double span_s = judge.t_s.back() - judge.t_s.front();
    const double sd_unit = std::max(sd_of(judge.residual), 0.05) / cpu;
    auto model_at = [&](const std::vector<double>& log_p) {
        std::vector<double> p(log_p.size());
        for (std::size_t k = 0; k < p.size(); ++k) p[k] = std::exp(log_p[k]);
        GapModel m = current;
        m.effects.push_back(make_candidate_effect(effect, c, p, current));
        return m;
    };
    auto objective = [&](const std::vector<double>& log_p) {
        return synthetic_loss(judge.evaluate(model_at(log_p), options.fit_replicates), judge.layout, Segment::fit);
    };
    // A few starting points spanning the plausible range, then the simplex from the best of them.
    std::vector<std::vector<double>> starts;
    if (effect == "gauss_markov") {
        for (double tau : {span_s / 100, span_s / 20, span_s / 4})
            for (double s : {0.3, 1.0}) starts.push_back({std::log(s * sd_unit), std::log(tau)});
    } else if (effect == "flicker") {
        for (double s : {0.05, 0.2, 0.8}) starts.push_back({std::log(s * sd_unit)});
    } else if (effect == "rate_random_walk") {
        for (double s : {0.1, 0.5, 2.0}) starts.push_back({std::log(s * sd_unit / std::sqrt(span_s))});
    } else {
        // Spikes: count robust outliers of the residual; a spike of s counts in one conversion leaves about s/N.
        const auto& e = judge.residual;
        std::vector<double> dev(e.size());
        for (std::size_t k = 0; k < e.size(); ++k) dev[k] = std::abs(e[k]);
        std::vector<double> sorted = dev;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
        const double scale = 1.4826 * sorted[sorted.size() / 2] + 0.1;
        std::vector<double> outliers;
        for (double d : dev)
            if (d > 5.0 * scale) outliers.push_back(d);
        const double rate = std::max(1.0, static_cast<double>(outliers.size())) / span_s;
        const double amp = (outliers.empty() ? 5.0 * scale : sd_of(outliers) + outliers.front()) * current.smoothing.window;
        starts.push_back({std::log(rate), std::log(amp)});
        starts.push_back({std::log(rate * 3), std::log(amp / 2)});
    }
    std::vector<double> best = starts.front();
    double best_value = INFINITY;
    for (const auto& s : starts) {
        const double v = objective(s);
        if (v < best_value) best_value = v, best = s;
    }
    const std::vector<double> step(best.size(), 0.7);
    const auto nm = nelder_mead(objective, best, step, std::max(8, options.max_evaluations - static_cast<int>(starts.size())));
    Fitted out{model_at(nm.x), {}};
    for (double v : nm.x) out.params.push_back(std::exp(v));
    return out;
}

Explanation judge_candidate(const std::string& effect, const Fitted& fitted, Channel c, const Judge& judge,
                            const Comparison& base_cmp, const ExplainOptions& options) {
    const Comparison cmp = judge.evaluate(fitted.model, options.eval_replicates);
    Explanation ex;
    ex.effect = effect;
    ex.channel = kChannelNames[channel_index(c)];
    const auto names = candidate_param_names(effect, c);
    for (std::size_t k = 0; k < names.size(); ++k) ex.params.emplace_back(names[k], fitted.params[k]);
    ex.gap_before = gap_score(base_cmp, judge.layout, in_segment(Segment::fit));
    ex.gap_after = gap_score(cmp, judge.layout, in_segment(Segment::fit));
    ex.heldout_before = gap_score(base_cmp, judge.layout, in_segment(Segment::heldout));
    ex.heldout_after = gap_score(cmp, judge.layout, in_segment(Segment::heldout));
    const double excess = ex.heldout_before - 1.0;
    ex.heldout_shrink = excess > 0.0 ? (ex.heldout_before - ex.heldout_after) / excess : 0.0;
    ex.loss_gain = synthetic_loss(base_cmp, judge.layout, Segment::fit) - synthetic_loss(cmp, judge.layout, Segment::fit);
    ex.penalty = static_cast<double>(names.size()) * std::log(static_cast<double>(cells_in(judge.layout, Segment::fit)));
    ex.heldout_loss_gain =
        synthetic_loss(base_cmp, judge.layout, Segment::heldout) - synthetic_loss(cmp, judge.layout, Segment::heldout);
    for (std::size_t j = 0; j < judge.layout.size(); ++j)
        if (judge.layout[j].segment == Segment::heldout)
            ex.heldout_cell_loss.push_back(cmp.z[j] * cmp.z[j] + 2.0 * std::log(cmp.sim_sd[j]));
    ex.accepted = passes(ex, options.penalty_per_param, options.min_heldout_shrink);
    ex.settle = candidate(effect).settle;
    // A Gauss-Markov process whose correlation time is not well inside the log shows neither its bump's fall nor
    // its plateau: within the log it is a flicker or a random walk (method: report coloured noise, don't choose).
    constexpr double kIdentifiableSpans = 20.0;
    if (effect == "gauss_markov") ex.long_memory = fitted.params[1] * kIdentifiableSpans > judge.t_s.back() - judge.t_s.front();
    return ex;
}

}  // namespace

bool passes(const Explanation& e, double penalty_per_param, double min_heldout_shrink) {
    // A held-out excess below kMinHeldoutExcess is no gap to shrink (the score is about 1 when the model explains
    // the log); the held-out likelihood must improve too, so a shrink bought by wider replicates does not count.
    constexpr double kMinHeldoutExcess = 0.2;
    return e.loss_gain > penalty_per_param * e.penalty && e.heldout_before - 1.0 > kMinHeldoutExcess &&
           e.heldout_shrink >= min_heldout_shrink && e.heldout_loss_gain > 0.0;
}

bool close_call(const Explanation& best, const Explanation& runner_up, double z) {
    const auto low_frequency = [](const Explanation& e) { return e.effect == "flicker" || e.effect == "rate_random_walk"; };
    if ((best.long_memory && low_frequency(runner_up)) || (runner_up.long_memory && low_frequency(best))) return true;
    const std::size_t n = std::min(best.heldout_cell_loss.size(), runner_up.heldout_cell_loss.size());
    if (n < 2) return false;
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        const double d = runner_up.heldout_cell_loss[j] - best.heldout_cell_loss[j];
        sum += d;
        sum2 += d * d;
    }
    const double nd = static_cast<double>(n);
    const double sd = std::sqrt(std::max(0.0, (sum2 - sum * sum / nd) / (nd - 1.0)));
    return sum < z * std::sqrt(nd) * sd;
}

ExplainResult explain(const GapModel& base, const std::vector<double>& t_s,
                      const std::array<const std::vector<double>*, kChannelCount>& y,
                      const std::array<bool, kChannelCount>& channels, const BatteryOptions& battery,
                      const ExplainOptions& options) {
    ExplainResult result;
    result.model = base;
    std::vector<std::string> names = options.candidates;
    if (names.empty())
        for (const auto& info : candidate_list()) names.push_back(info.effect);
    std::array<std::vector<std::string>, kChannelCount> used;
    const std::size_t first_added = base.effects.size();  // effects[first_added + k] is accepted[k]
    std::array<bool, kChannelCount> open = channels;

    for (int step = 1; step <= options.max_effects; ++step) {
        struct Option {
            Explanation ex;
            GapModel model;
            std::vector<std::pair<std::size_t, std::vector<double>>> refits;  ///< accepted index, new parameters
        };
        std::vector<Option> accepted;
        for (std::size_t i = 0; i < kChannelCount; ++i) {
            if (!open[i]) continue;
            const Channel c = static_cast<Channel>(i);
            Judge judge{t_s, battery, {}, {}, {}, 0.0, {}, {}, options.seed, options.threads};
            judge.battery.channels = {};
            judge.battery.channels[i] = true;
            std::array<const std::vector<double>*, kChannelCount> yc{};
            yc[i] = y[i];
            const BatteryResult real = compute_battery(t_s, yc, judge.battery, &judge.layout);
            judge.real = real.values;
            judge.residual = real.residual[i];
            judge.target_spread = short_lag_spread(judge.residual);
            const std::vector<bool> fitting = fitting_mask(t_s, battery);
            for (std::size_t k = 0; k < t_s.size(); ++k)
                if (fitting[k]) judge.t_fit.push_back(t_s[k]), judge.y_fit.push_back((*y[i])[k]);
            const Comparison base_cmp = judge.evaluate(result.model, options.eval_replicates);
            if (locate(judge.real, base_cmp, judge.layout).empty()) {
                open[i] = false;
                continue;
            }
            std::vector<Option> here;
            for (const std::string& effect : names) {
                if (std::find(used[i].begin(), used[i].end(), effect) != used[i].end()) continue;
                const FitRoute route = candidate(effect).route;
                Fitted fitted = route == FitRoute::deterministic ? fit_deterministic(effect, result.model, c, judge)
                                                                 : fit_simulated(effect, result.model, c, judge, options);
                if (route == FitRoute::deterministic)
                    fitted.model.effects.push_back(make_candidate_effect(effect, c, fitted.params, fitted.model));
                // Refit everything: an earlier noise effect on this channel may have been sized to swallow what
                // this candidate explains (a broad flicker covers a sinusoid), so it is fitted again beside it.
                std::vector<std::pair<std::size_t, std::vector<double>>> refits;
                for (std::size_t k = 0; k < result.accepted.size(); ++k) {
                    const Explanation& prev = result.accepted[k];
                    if (prev.channel != kChannelNames[i] || candidate(prev.effect).route != FitRoute::simulated) continue;
                    const auto slot = static_cast<std::ptrdiff_t>(first_added + k);
                    GapModel without = fitted.model;
                    without.effects.erase(without.effects.begin() + slot);
                    Fitted again = fit_simulated(prev.effect, without, c, judge, options);
                    fitted.model.effects[static_cast<std::size_t>(slot)] = again.model.effects.back();
                    refits.emplace_back(k, again.params);
                }
                // The candidate takes part of the short-lag spread: match the white noise again with it in place.
                std::array<bool, kChannelCount> only{};
                only[i] = true;
                std::array<double, kChannelCount> target{};
                target[i] = judge.target_spread;
                match_noise(fitted.model, t_s, only, target, options.seed);
                Explanation ex = judge_candidate(effect, fitted, c, judge, base_cmp, options);
                ex.step = step;
                here.push_back({ex, fitted.model, std::move(refits)});
            }
            std::sort(here.begin(), here.end(), [](const Option& a, const Option& b) {
                if (a.ex.accepted != b.ex.accepted) return a.ex.accepted;
                // The held-out synthetic likelihood ranks: unlike the gap score it charges for wider replicates.
                return a.ex.heldout_loss_gain > b.ex.heldout_loss_gain;
            });
            if (here.size() >= 2 && here[0].ex.accepted && here[1].ex.accepted &&
                close_call(here[0].ex, here[1].ex, options.ambiguity_z)) {
                here[0].ex.ambiguous_with = here[1].ex.effect;
                here[0].ex.settle += "; vs " + here[1].ex.effect + ": " + here[1].ex.settle;
            }
            for (const auto& o : here) result.tried.push_back(o.ex);
            if (!here.empty() && here[0].ex.accepted) accepted.push_back(here[0]);
        }
        if (accepted.empty()) break;
        const auto best = std::max_element(accepted.begin(), accepted.end(), [](const Option& a, const Option& b) {
            return a.ex.heldout_loss_gain < b.ex.heldout_loss_gain;
        });
        result.model = best->model;
        for (const auto& [k, params] : best->refits)
            for (std::size_t p = 0; p < params.size(); ++p) result.accepted[k].params[p].second = params[p];
        result.accepted.push_back(best->ex);
        for (std::size_t i = 0; i < kChannelCount; ++i)
            if (kChannelNames[i] == best->ex.channel) used[i].push_back(best->ex.effect);
    }
    std::stable_sort(result.tried.begin(), result.tried.end(), [](const Explanation& a, const Explanation& b) {
        if (a.accepted != b.accepted) return a.accepted;
        return a.heldout_shrink > b.heldout_shrink;
    });
    return result;
}

}  // namespace driftlab::host::gap
