// The whole diagnosis; see diagnose.hpp.
#include "host/gap/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "host/gap/calibrate.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/replicates.hpp"
#include "host/stats/lone_values.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::gap {

namespace {

constexpr std::size_t kMinSamples = 200;

TimingCheck check_timing(const LogData& log, double period_s) {
    TimingCheck t;
    t.gap_events = log.gaps.size();
    const std::uint64_t frames_per_row = log.frames_per_row();
    double sum = 0.0, sum2 = 0.0;
    std::size_t steps = 0;
    auto cut = log.cuts.begin();
    for (std::size_t i = 1; i < log.size(); ++i) {
        while (cut != log.cuts.end() && cut->before_row < i) ++cut;
        if (cut != log.cuts.end() && cut->before_row == i) continue;  // rows the user left out, not lost
        ++steps;
        if (log.seq[i] > log.seq[i - 1] + frames_per_row) {
            ++t.sequence_jumps;
            t.lost_frames += log.seq[i] - log.seq[i - 1] - frames_per_row;
        }
        const double d = (log.t_s[i] - log.t_s[i - 1]) / period_s - 1.0;
        sum += d;
        sum2 += d * d;
    }
    const double n = static_cast<double>(std::max<std::size_t>(1, steps));
    t.dt_jitter_rel = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
    return t;
}

CellFilter in_segment(Segment s) {
    return [s](const Cell& c) { return c.segment == s; };
}

// The level-step test of the final model on each channel with an accepted Gaussian process and no mean shape
// (whose misfit is judged by the cells it leaves located), at alpha / channels (Bonferroni; the test itself
// takes enough replicates for its level to be reachable). A shape the model file holds (refitted) counts as one;
// its held processes whiten beside the accepted ones through the model's spectrum (GapModel::held).
std::vector<LevelStep> check_level_steps(const GapResult& result, const LogData& log, const GapOptions& options) {
    std::vector<std::size_t> tested;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const auto on_channel = [&](const std::vector<Explanation>& list, FitRoute route) {
            return std::any_of(list.begin(), list.end(), [&](const Explanation& e) {
                return e.channel == kChannelNames[c] && candidate(e.effect).route == route;
            });
        };
        const bool shaped = on_channel(result.accepted, FitRoute::deterministic) ||
                            on_channel(result.given.refitted, FitRoute::deterministic);
        if (on_channel(result.accepted, FitRoute::spectral) && !shaped) tested.push_back(c);
    }
    std::vector<LevelStep> out;
    if (tested.empty()) return out;
    const double alpha = options.explain_options.step_alpha / static_cast<double>(tested.size());
    const int replicates = std::max(options.replicates, options.explain_options.step_replicates);
    for (std::size_t c : tested) {
        std::vector<std::string> effects;
        std::vector<double> params;
        for (const auto& e : result.accepted) {
            if (e.channel != kChannelNames[c] || candidate(e.effect).route != FitRoute::spectral) continue;
            effects.push_back(e.effect);
            for (const auto& kv : e.params) params.push_back(kv.second);
        }
        out.push_back(test_level_step(result.final_model, static_cast<Channel>(c), log.t_s, log.counts[c], effects,
                                      params, replicates, options.seed + 17, options.threads, alpha));
    }
    return out;
}

// The analysed channels whose rows the log's sat_flags column flags, with how many, the first and the last.
std::vector<SaturatedChannel> saturated_channels(const LogData& log, const std::array<bool, kChannelCount>& channels) {
    std::vector<SaturatedChannel> out;
    const auto column = log.optional_columns.find("sat_flags");
    if (column == log.optional_columns.end()) return out;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!channels[c]) continue;
        SaturatedChannel s{static_cast<Channel>(c), 0, 0.0, 0.0};
        for (std::size_t k = 0; k < column->second.size() && k < log.size(); ++k) {
            if (!flags_saturation(column->second[k], c)) continue;
            if (s.rows++ == 0) s.first_t_s = log.t_s[k];
            s.last_t_s = log.t_s[k];
        }
        if (s.rows > 0) out.push_back(s);
    }
    return out;
}

// The analysed channels whose lone values are worth a warning, with the rows named.
std::vector<LoneValueChannel> lone_value_channels(const LogData& log, const std::array<bool, kChannelCount>& channels) {
    std::vector<LoneValueChannel> out;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!channels[c]) continue;
        const stats::LoneValues found = stats::lone_values(log.counts[c], 1.0);  // counts: one code is 1
        const std::optional<std::string> warning = stats::lone_values_warning(log.t_s, log.counts[c], found);
        if (!warning) continue;
        LoneValueChannel lone{static_cast<Channel>(c), {}, found.variance_share, *warning};
        for (std::size_t k : found.indices) lone.t_s.push_back(log.t_s[k]);
        out.push_back(std::move(lone));
    }
    return out;
}

// Whether channel `c` is among those the options select (none named: all).
bool selected(const GapOptions& options, std::size_t c) {
    const bool any = std::any_of(options.channels.begin(), options.channels.end(), [](bool b) { return b; });
    return !any || options.channels[c];
}

}  // namespace

bool any_raw_codes(const GapResult& result) {
    return std::any_of(result.raw_codes.begin(), result.raw_codes.end(), [](bool r) { return r; });
}

bool gap_located(const GapResult& result) { return !result.located.empty() || !result.link.located.empty(); }

bool any_codes(const GapResult& result) {
    return any_raw_codes(result) ||
           std::any_of(result.output_codes.begin(), result.output_codes.end(), [](bool r) { return r; });
}

const std::vector<double>* code_column(const LogData& log, const GapResult& result, std::size_t c) {
    if (result.output_codes[c]) return &log.counts[c];
    if (!result.raw_codes[c]) return nullptr;
    return &log.optional_columns.at(std::string("raw_") + kChannelNames[c]);
}

bool was_added(const GapResult& r, const Explanation& e) {
    return std::any_of(r.accepted.begin(), r.accepted.end(), [&](const Explanation& a) {
        return a.step == e.step && a.effect == e.effect && a.channel == e.channel;
    });
}

std::array<bool, kChannelCount> analysed_channels(const LogData& log, const GapOptions& options) {
    const auto varying = varying_channels(log);
    std::array<bool, kChannelCount> out{};
    for (std::size_t c = 0; c < kChannelCount; ++c) out[c] = varying[c] && selected(options, c);
    return out;
}

std::vector<ConstantChannel> constant_channels(const LogData& log, const GapOptions& options) {
    const auto varying = varying_channels(log);
    std::vector<ConstantChannel> out;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (log.recorded[c] && selected(options, c) && !log.counts[c].empty() && !varying[c])
            out.push_back({static_cast<Channel>(c), log.counts[c].front()});
    return out;
}

std::string constant_channels_text(const std::vector<ConstantChannel>& channels) {
    std::string out;
    for (const auto& k : channels)
        out += (out.empty() ? "" : ", ") + std::string(kChannelNames[channel_index(k.channel)]) + " at " +
               format_double(k.counts) + " counts in every row";
    return out;
}

std::string noise_free_text(const std::vector<NoiseFreeChannel>& channels) {
    std::string out;
    for (const auto& k : channels) {
        char spread[32];
        std::snprintf(spread, sizeof spread, "%.2g", k.spread_counts);
        out += (out.empty() ? "" : ", ") + std::string(kChannelNames[channel_index(k.channel)]) +
               " with a short-lag spread of " + spread + " counts";
    }
    return out;
}

namespace {

// What no diagnosis can run on: too few replicates or samples, a channel the recording lacks.
void refuse_request(const LogData& log, const GapOptions& options) {
    if (options.replicates < 10) throw UsageError("--replicates: need at least 10");
    if (!(options.fit_fraction > 0.2 && options.fit_fraction < 0.9))
        throw UsageError("fit fraction must be in (0.2, 0.9)");
    if (log.size() < kMinSamples)
        throw DataError(
            log.source_name, 0,
            "gap needs at least " + std::to_string(kMinSamples) + " samples, got " + std::to_string(log.size()));
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (options.channels[c] && !log.recorded[c])
            throw UsageError(std::string("--channel ") + kChannelNames[c] + ": " + log.source_name +
                             " does not record it (a plain recording has the channels its --as options map)");
}

// The base simulator calibrated to the log, with the model's own effects, and the channels it can be compared on.
void calibrate_and_select(GapResult& result, const LogData& log, const sim::SimModel& unit, const GapOptions& options,
                          const std::array<const std::vector<double>*, kChannelCount>& y) {
    result.channels = analysed_channels(log, options);
    result.constant_channels = constant_channels(log, options);
    if (std::none_of(result.channels.begin(), result.channels.end(), [](bool b) { return b; })) {
        const std::string constant = constant_channels_text(result.constant_channels);
        throw DataError(
            log.source_name, 0,
            "no selected channel varies" + (constant.empty() ? "" : " (" + constant + ")") + ": nothing to compare");
    }
    if (options.progress) options.progress("calibrating the base simulator");
    std::array<double, kChannelCount> spread{};
    result.base = calibrate_base(log, unit, result.channels, options.seed, &spread);
    if (!unit.effects.empty()) {
        if (options.progress) options.progress("fitting the model's own effects");
        result.given = add_given_effects(result.base, unit.effects, log.t_s, y, result.channels, spread, options.seed);
    }
    // Before the channels left out below: a stuck channel with one corrupt row is named for the row as well.
    result.lone_values = lone_value_channels(log, result.channels);
    // Replicates of a channel that cannot spread make every z a division by the floor: leave it out and say so.
    const auto fixed = deterministic_channels(result.base, log.t_s, result.channels, options.seed);
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (fixed[c]) {
            result.channels[c] = false;
            result.noise_free.push_back({static_cast<Channel>(c), spread[c]});
        }
    if (std::none_of(result.channels.begin(), result.channels.end(), [](bool b) { return b; }))
        throw DataError(log.source_name, 0,
                        "no selected channel has noise to compare (" + noise_free_text(result.noise_free) + ")");
}

// A raw-mode log's raw column (integral codes, one per row) gives the channel its code-histogram cells.
RawCodes raw_code_columns(const LogData& log, const std::array<bool, kChannelCount>& channels,
                          BatteryOptions& battery) {
    RawCodes raw{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const auto column = log.optional_columns.find(std::string("raw_") + kChannelNames[c]);
        if (!channels[c] || column == log.optional_columns.end() || column->second.size() != log.size() ||
            !std::all_of(column->second.begin(), column->second.end(),
                         [](double v) { return std::isfinite(v) && v == std::round(v); }))
            continue;
        raw[c] = &column->second;
        battery.raw_codes[c] = true;
    }
    return raw;
}

// Channels without a raw column whose outputs are single conversions (window 1): every output is one code, so the
// outputs themselves get the code-histogram cells and the adc_dnl candidate.
void output_code_channels(const LogData& log, const std::array<bool, kChannelCount>& channels,
                          const Smoothing& smoothing, BatteryOptions& battery) {
    if (smoothing.window != 1) return;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        battery.output_codes[c] = channels[c] && !battery.raw_codes[c] &&
                                  std::all_of(log.counts[c].begin(), log.counts[c].end(), [](double v) {
                                      return std::isfinite(v) && v >= 0.0 && v == std::round(v);
                                  });
}

// The battery the log is judged by: its channels, hold-out and cells, with the raw-mode columns (into `raw`) and the
// outputs that are codes given their code-histogram cells; the result records which.
BatteryOptions log_battery(GapResult& result, const LogData& log, const GapOptions& options, RawCodes& raw) {
    BatteryOptions battery;
    battery.channels = result.channels;
    battery.holdout = options.holdout;
    battery.fit_fraction = options.fit_fraction;
    battery.sample_period_s = result.base.smoothing.sample_period_s;
    battery.frac_cells = !options.less_known_input;
    if (!options.less_known_input) {
        raw = raw_code_columns(log, result.channels, battery);
        output_code_channels(log, result.channels, result.base.smoothing, battery);
    }
    result.raw_codes = battery.raw_codes;
    result.output_codes = battery.output_codes;
    if (!any_codes(result)) result.not_tried = not_tried_without_raw_codes(options.less_known_input);
    return battery;
}

// The explanation search on the channels with located cells (for a diffuse gap, on every channel), and the verdict.
void search(GapResult& result, const LogData& log, const GapOptions& options,
            const std::array<const std::vector<double>*, kChannelCount>& y, const BatteryOptions& battery,
            const RawCodes& raw) {
    std::array<bool, kChannelCount> open = result.located.empty() ? result.channels : std::array<bool, kChannelCount>{};
    for (const auto& l : result.located) {
        const int ci = result.layout[l.index].channel_index;
        if (ci >= 0) open[static_cast<std::size_t>(ci)] = true;
    }
    ExplainOptions eo = options.explain_options;
    if (options.search_diffuse) eo.diffuse_alpha = options.alpha;
    eo.alpha = options.alpha;
    eo.seed = options.seed;
    eo.threads = options.threads;
    eo.eval_replicates = options.replicates;
    eo.progress = options.progress;
    eo.given = &result.given;
    ExplainResult ex = explain(result.base, log.t_s, y, open, battery, eo, raw);
    result.tried = std::move(ex.tried);
    result.accepted = std::move(ex.accepted);
    result.paths = std::move(ex.paths);
    result.final_model = std::move(ex.model);
    result.whole_log_model = std::move(ex.whole_log_model);
    // Only located cells make a gap no effect explains; a diffuse gap's search can name an effect or nothing.
    const char* nothing = result.located.empty() ? "none" : "unexplained";
    result.verdict = result.accepted.empty() ? nothing : result.accepted.front().effect;
}

// The channels read together (common_cause.hpp), where two or more are analysed and a cell of theirs is located,
// after what follows the measured temperature is taken out (temperature_coupling.hpp). A shared reading that wins
// replaces the accepted Gaussian processes of the channels it loads (their size there set to 0 in the models) and joins
// the models as the library's supply wander.
void search_common(GapResult& result, const LogData& log, int threads) {
    CommonFindings& common = result.common;
    std::array<std::vector<double>, kChannelCount> residual;
    std::array<const std::vector<double>*, kChannelCount> r{};
    std::array<double, kChannelCount> dc{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!result.channels[c]) continue;
        const auto channel = static_cast<Channel>(c);
        std::vector<double> shapes = model_mean_counts(result.whole_log_model, channel, log.t_s);
        const std::vector<double> base = model_mean_counts(result.base, channel, log.t_s);
        for (std::size_t k = 0; k < shapes.size(); ++k) shapes[k] -= base[k];
        residual[c] = common_residual(log.t_s, log.counts[c], shapes);
        r[c] = &residual[c];
        for (double v : log.counts[c]) dc[c] += v / static_cast<double>(log.size());
    }
    result.temperature =
        couple_to_temperature(residual, result.channels, temperature_residual(log), result.base, threads);
    common = fit_common(r, dc, result.base, threads);
    common.shared = shared_bands(result.located, result.layout);
    const CommonFit* won = common.winner();
    // The replicates cannot replay a measured temperature: a process the search added stays as its stand-in.
    if (!won && result.temperature.any()) result.verdict = "temperature";
    if (!won) return;
    const std::size_t own = result.base.effects.size();
    std::erase_if(result.accepted, [&](const Explanation& e) {
        std::size_t c = 0;
        while (c < kChannelCount && e.channel != kChannelNames[c]) ++c;
        if (c == kChannelCount || !won->loaded[c] || candidate(e.effect).route != FitRoute::spectral) return false;
        common.replaced.push_back(e.effect + " on " + e.channel);
        for (GapModel* m : {&result.final_model, &result.whole_log_model})
            for (std::size_t i = own; i < m->effects.size(); ++i)
                if (m->effects[i].name == e.effect && candidate_size_in(m->effects[i], static_cast<Channel>(c)) > 0.0)
                    m->effects[i] = without_channel(m->effects[i], static_cast<Channel>(c));
        return true;
    });
    common.effect = common_effect(*won, result.base);
    result.final_model.effects.push_back(*common.effect);
    result.whole_log_model.effects.push_back(*common.effect);
    result.verdict = won->reading;
}

}  // namespace

GapResult diagnose(const LogData& log, const sim::SimModel& unit, const GapOptions& options) {
    refuse_request(log, options);
    const auto tell = [&](const std::string& stage) {
        if (options.progress) options.progress(stage);
    };
    std::array<const std::vector<double>*, kChannelCount> y{};
    for (std::size_t c = 0; c < kChannelCount; ++c) y[c] = &log.counts[c];
    GapResult result;
    calibrate_and_select(result, log, unit, options, y);
    result.timing = check_timing(log, result.base.smoothing.sample_period_s);
    result.left_out = log.cuts;
    result.saturated = saturated_channels(log, result.channels);

    RawCodes raw{};
    const BatteryOptions battery = log_battery(result, log, options, raw);
    result.real_values = compute_battery(log.t_s, y, battery, &result.layout, raw).values;

    auto judge = [&](const GapModel& model, Comparison& cmp, std::vector<LocatedCell>& located, double& fit,
                     double& held, double& bound) {
        cmp = compare(result.real_values,
                      run_replicates(model, log.t_s, battery, options.replicates, options.seed, options.threads),
                      options.alpha);
        located = locate(result.real_values, cmp, result.layout);
        fit = gap_score(cmp, result.layout, in_segment(Segment::fit));
        held = gap_score(cmp, result.layout, in_segment(Segment::heldout));
        bound = gap_score_threshold(cmp, result.layout, in_segment(Segment::heldout), options.alpha);
    };
    tell("comparing the link's frame loss");
    result.link =
        diagnose_link(log, unit.link, battery, options.replicates, options.seed, options.alpha, options.explain);
    tell("comparing with " + std::to_string(options.replicates) + " replicates");
    judge(result.base, result.before, result.located, result.gap_before_fit, result.gap_before_heldout,
          result.gap_bound_before);

    result.final_model = result.whole_log_model = result.base;
    result.diffuse_gap = result.located.empty() && result.gap_before_heldout > result.gap_bound_before;
    result.diffuse_searched = result.diffuse_gap && options.search_diffuse && options.explain;
    if (result.located.empty() && !result.diffuse_searched) {
        result.verdict = "none";
    } else if (options.explain) {
        search(result, log, options, y, battery, raw);
    } else {
        result.verdict = "unexplained";
    }
    // The link's explanation names a log whose channels the simulator explains.
    if (result.verdict == "none" && !result.link.located.empty())
        result.verdict = result.link.added ? result.link.tried[*result.link.added].effect : "unexplained";
    if (result.link.added) set_link_loss(result.whole_log_model.unit.link, result.link.tried[*result.link.added]);
    const auto analysed = std::count(result.channels.begin(), result.channels.end(), true);
    if (options.explain && analysed >= 2 && !result.located.empty()) {
        tell("reading the channels together");
        search_common(result, log, options.threads);
    }
    if (result.accepted.empty() && !result.common.winner()) {
        result.after = result.before;
        result.located_after = result.located;
        result.gap_after_fit = result.gap_before_fit;
        result.gap_after_heldout = result.gap_before_heldout;
        result.gap_bound_after = result.gap_bound_before;
    } else {
        tell("judging the final model");
        judge(result.final_model, result.after, result.located_after, result.gap_after_fit, result.gap_after_heldout,
              result.gap_bound_after);
        // A level step no library effect makes leaves the log unexplained (closes_gap()); the accepted effects stay
        // as partial explanations.
        tell("testing for level steps");
        result.level_steps = check_level_steps(result, log, options);
        if (std::any_of(result.level_steps.begin(), result.level_steps.end(),
                        [](const LevelStep& s) { return s.significant; }) ||
            std::any_of(result.accepted.begin(), result.accepted.end(),
                        [](const Explanation& e) { return e.shape_steps.steps_win; }))
            result.verdict = "unexplained";
    }
    return result;
}

}  // namespace driftlab::host::gap
