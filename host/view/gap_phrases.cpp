// The sentences the gap result's views share; see gap_phrases.hpp.
#include "host/view/gap_phrases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/lm_fit.hpp"
#include "host/gap/candidates.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/format_number.hpp"
#include "host/view/gap_view.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::view {

using gap::Cell;
using gap::ExplainOptions;
using gap::Explanation;
using gap::GapModel;
using gap::GapOptions;
using gap::GapResult;
using gap::GivenEffects;
using gap::LocatedCell;
using gap::ParameterSpread;
using gap::VerdictStability;

PhysicalUnit display_unit(const GapModel& model, Channel c) {
    const double per_count = 1.0 / counts_per_unit(model, c);
    return c == Channel::gyro ? PhysicalUnit{per_count, "deg/s"} : PhysicalUnit{per_count * 1000.0, "mg"};
}

Channel explained_channel(const std::string& name) {
    if (const std::optional<Channel> c = channel_named(name)) return *c;
    throw std::invalid_argument("no channel '" + name + "'");
}

std::string step_size_text(const GapModel& model, Channel c, double counts, int decimals) {
    const PhysicalUnit unit = display_unit(model, c);
    std::string out = fixed_point(counts, decimals) + " counts";
    if (std::isfinite(unit.per_count) && unit.per_count > 0.0)
        out += " (" + significant_plain(counts * unit.per_count, 3) + " " + unit.name + ")";
    return out;
}

std::string verdict_reason(const GapResult& r, const GapOptions& options) {
    for (const auto& s : r.level_steps)
        if (s.significant)
            return std::string("a level step on ") + kChannelNames[channel_index(s.channel)] + " (" +
                   step_size_text(r.base, s.channel, s.steps[0].size_counts, 2) +
                   " at t = " + fixed_point(s.steps[0].t_s, 1) + " s; p = " + fixed_point(s.p_value, 3) +
                   ") that no library effect makes; the added effects stay as partial explanations";
    for (const auto& e : r.accepted)
        if (e.shape_steps.steps_win)
            return "a hop and a return on " + e.channel + " (" +
                   step_size_text(r.base, explained_channel(e.channel), e.shape_steps.steps[0].size_counts, 2) +
                   " at t = " + fixed_point(e.shape_steps.steps[0].t_s, 1) + " s, " +
                   step_size_text(r.base, explained_channel(e.channel), e.shape_steps.steps[1].size_counts, 2) +
                   " at " + fixed_point(e.shape_steps.steps[1].t_s, 1) + " s) describe its mean better than " +
                   e.effect + " (likelihood " + fixed_point(e.shape_steps.statistic, 1) + " over the price " +
                   fixed_point(e.shape_steps.margin, 1) +
                   "): a level step no library effect makes; the added effects stay as partial explanations";
    const std::string located = counted(r.located.size(), "cell") + " located";
    if (r.common.winner() || r.verdict == "temperature") return common_sentence(r);
    if (!r.accepted.empty()) {
        const Explanation& e = r.accepted.front();
        // The channel's own score, not the whole log's the gap line and table show: say so, and what the share is of.
        std::string out = "on " + e.channel + " it removes " + fixed_point(100 * e.heldout_shrink, 0) + " % of " +
                          e.channel + "'s own held-out gap excess (" + e.channel + "'s held-out score " +
                          fixed_point(e.heldout_before, 2) + " -> " + fixed_point(e.heldout_after, 2) + "; " +
                          kShrinkDefinition + "; the whole log's scores are below)";
        for (std::size_t k = 1; k < r.accepted.size(); ++k)
            out += (k == 1 ? "; then " : ", ") + r.accepted[k].effect + " on " + r.accepted[k].channel +
                   (r.accepted[k].within_bound_before() ? std::string(" (") + kWithinBoundNote + ")" : "");
        const bool closed = r.gap_after_heldout <= r.gap_bound_after;
        out += closed ? "; the gap closes" : "; the held-out gap stays above its bound";
        // Not closed at the limit: no further step was tried, so say that the search, not the library, stopped.
        const int limit = options.explain_options.max_effects;
        if (!closed && r.accepted.size() >= static_cast<std::size_t>(limit))
            out += " after " + counted(r.accepted.size(), "effect") +
                   (limit < ExplainOptions{}.max_effects ? ", the most --max-effects allows"
                                                         : ", the most the search adds");
        for (const auto& s : r.level_steps)
            if (s.outsized)
                out += std::string("; level steps on ") + kChannelNames[channel_index(s.channel)] + " (" +
                       step_size_text(r.base, s.channel, s.steps[0].size_counts, 2) +
                       " at t = " + fixed_point(s.steps[0].t_s, 1) + " s, " +
                       step_size_text(r.base, s.channel, s.steps[1].size_counts, 2) + " at " +
                       fixed_point(s.steps[1].t_s, 1) + " s; p = " + fixed_point(s.p_value, 3) +
                       ") are read as the processes' outsized increments: they remain beside them";
        return out;
    }
    if (r.located.empty() && r.link.added) {
        const Explanation& e = r.link.tried[*r.link.added];
        return "the channels agree with the simulator; the link's frame loss does not (" +
               counted(r.link.located.size(), "link cell") + " located), and " + e.effect + " removes " +
               fixed_point(100 * e.heldout_shrink, 0) + " % of its held-out excess";
    }
    if (r.located.empty()) {
        if (!r.diffuse_gap)
            return std::string(
                       "no cell located and the held-out score within its bound: the calibrated base simulator") +
                   (r.given.empty() ? "" : ", with the model's own effects,") + " explains the log";
        if (r.diffuse_searched) return "no cell located; the diffuse gap was searched and no candidate passed";
        return std::string("no cell located, but the held-out score exceeds its bound (a diffuse gap); ") +
               (options.explain ? "--search-diffuse tries the candidates on it" : "no candidate tried (--locate-only)");
    }
    if (!options.explain) return located + "; no candidate tried (--locate-only)";
    return located + " and no candidate passes (held-out shrink, held-out likelihood and penalised gain)";
}

std::string slow_drift_sentence(const GapResult& r, const LogData& log) {
    if (r.verdict != "none") return "";
    const double span_s = log.t_s.back() - log.t_s.front();
    std::string slow;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (r.channels[c] && r.base.base[c].drift.tau_s >= 0.5 * span_s)
            slow += (slow.empty() ? "" : ", ") + significant_plain(r.base.base[c].drift.tau_s, 3) + " s on " +
                    kChannelNames[c];
    if (slow.empty()) return "";
    return "the paper's drift model, eq. 1: C1(1 - e^(-t/T)) + C2, is fitted with T = " + slow +
           ", at least half the log's " + fixed_point(span_s, 0) +
           " s, so it still bends at the log's end: an effect this slow (a second time constant, a slow "
           "thermal drift) would be taken up by the drift fit rather than left as a gap, and only a log several T long "
           "tells them apart";
}

std::string parameter_text(double value) { return significant_plain(value, 4); }

std::string parameter_list(const std::vector<std::pair<std::string, double>>& params) {
    std::string out;
    for (const auto& [k, v] : params) out += (out.empty() ? "" : " ") + k + "=" + parameter_text(v);
    return out;
}

std::string given_effects_sentence(const GivenEffects& given) {
    std::string out;
    const auto part = [&](const std::string& what, const std::vector<Explanation>& list) {
        for (std::size_t k = 0; k < list.size(); ++k)
            out += (k ? "; " : (out.empty() ? "" : "; ") + what) + list[k].effect + " on " + list[k].channel + " " +
                   parameter_list(list[k].params);
    };
    part("the model's own effects refitted to this log: ", given.refitted);
    part("held at the model's values: ", given.held);
    for (std::size_t k = 0; k < given.kept.size(); ++k)
        out += (k ? ", " : (out.empty() ? "" : "; ") + std::string("kept as the model gives them: ")) + given.kept[k];
    return out;
}

std::string estimate_text(const Explanation& e, double record_end_s) {
    std::string text = parameter_list(e.estimate());
    if (!e.whole_log_params.empty()) text += " (whole log; fitting part: " + parameter_list(e.params) + ")";
    // A size the whole log sets to almost nothing (a walk beside a process that takes it all) is no estimate to copy.
    if (!e.whole_log_params.empty() && !e.params.empty() && e.params[0].second != 0.0 &&
        std::abs(e.whole_log_params[0].second) < 0.01 * std::abs(e.params[0].second))
        text += "; on the whole log, beside the other effects, its " + e.whole_log_params[0].first +
                " is under 1 % of the fitting part's: there the others take all of it";
    // A copied t2 of five times the log would pass for a measured one (the search's longest time constant).
    if (e.effect == "thermal_second_tc" && e.estimate().size() == 2 &&
        fit::beyond_record(e.estimate()[1].second, record_end_s)) {
        const auto& [size_key, size] = e.estimate()[0];
        const double t2 = e.estimate()[1].second;
        text += "; t2 is beyond 3x the log's " + fixed_point(record_end_s, 0) +
                " s, so within it the exponential is a straight slope: "
                "the log tells its initial slope, " +
                significant_plain(size / t2, 2) + (size_key == "c3_dps" ? " deg/s" : " g") +
                " per s, not c3 and t2 apart";
    }
    return text;
}

std::string constant_channels_sentence(const GapResult& r) {
    if (r.constant_channels.empty()) return "";
    return constant_channels_text(r.constant_channels) +
           ": a channel that never changes has no noise to compare with the simulator's (a stuck or unconnected "
           "sensor?)";
}

std::string noise_free_sentence(const GapResult& r) {
    if (r.noise_free.empty()) return "";
    return noise_free_text(r.noise_free) +
           ": no white noise beyond the converter's is needed for that, and the simulator then makes the "
           "same output for every seed, so its replicates give nothing to compare with (a generated or "
           "filtered signal, or a sensor far quieter than one count?)";
}

std::string saturated_channels_sentence(const GapResult& r) {
    std::string out;
    for (const auto& s : r.saturated)
        out +=
            (out.empty() ? "" : ", ") + std::string(kChannelNames[channel_index(s.channel)]) + " in " +
            counted(s.rows, "row") +
            (s.rows == 1 ? " at t = " + fixed_point(s.first_t_s, 1) + " s"
                         : " from t = " + fixed_point(s.first_t_s, 1) + " s to " + fixed_point(s.last_t_s, 1) + " s");
    if (out.empty()) return "";
    return out +
           ": a conversion reached code 0 or the top code there (the firmware's sat_flags); the simulator clips only "
           "where its own noise reaches a rail, so a shock, or a rail the unit sits near, can read as a gap (--from "
           "and --to "
           "leave a disturbed start or end out, --exclude a stretch in the middle, --exclude-saturated S every "
           "saturated stretch "
           "and S seconds either side)";
}

std::string left_out_sentence(const GapResult& r) {
    std::string out;
    for (const auto& c : r.left_out)
        out += (out.empty() ? "" : ", ") + counted(c.rows, "row") + " from t = " + format_double(c.from_s) + " s to " +
               format_double(c.to_s) + " s (" + c.by + ")";
    if (out.empty()) return "";
    return out +
           ": the rows either side are joined, and the replicates, simulated on the same instants, "
           "live through the same time";
}

std::vector<const Explanation*> candidates_in_table_order(const GapResult& r) {
    std::vector<const Explanation*> out;
    for (const auto& e : r.tried) out.push_back(&e);
    std::stable_sort(out.begin(), out.end(), [&r](const Explanation* a, const Explanation* b) {
        const bool a_added = was_added(r, *a), b_added = was_added(r, *b);
        if (a_added != b_added) return a_added;
        return a->step < b->step;
    });
    return out;
}

std::string located_value_text(const LocatedCell& l) {
    const double half_width = 0.5 * (l.interval_high - l.interval_low);
    const bool ratio = !std::isnan(l.ratio);
    return (ratio ? "ratio " : "diff ") + to_precision_of(ratio ? l.ratio : l.difference, half_width) + " [" +
           to_precision_of(l.interval_low, half_width) + ", " + to_precision_of(l.interval_high, half_width) + "]";
}

std::string located_cell_text(const GapResult& r, const LocatedCell& l) {
    const std::string text = located_value_text(l);
    const Cell& c = r.layout[l.index];
    if (c.statistic != "mean") return text;
    const PhysicalUnit unit = display_unit(r.base, explained_channel(c.channel));
    if (!(std::isfinite(unit.per_count) && unit.per_count > 0.0)) return text + " counts";
    return text + " counts (" + significant_plain(l.difference * unit.per_count, 3) + " " + unit.name + ")";
}

namespace {

// A value beside the simulated logs' middle 68 %: to the digits half that range warrants (their scatter is the
// estimate's), or as a lone parameter where the range is one value.
std::string within_spread(double value, const ParameterSpread& p) {
    const double half_width = 0.5 * (p.quantile(0.84) - p.quantile(0.16));
    return half_width > 0.0 ? to_precision_of(value, half_width) : parameter_text(value);
}

}  // namespace

std::vector<std::string> spread_lines(const VerdictStability& s) {
    std::vector<std::string> lines;
    for (std::size_t k = 0; k < s.params.size();) {
        // One line per added effect: its parameters are consecutive.
        std::size_t end = k;
        while (end < s.params.size() && s.params[end].effect == s.params[k].effect &&
               s.params[end].channel == s.params[k].channel)
            ++end;
        const ParameterSpread& first = s.params[k];
        std::string line = first.effect + " on " + first.channel;
        if (first.logs_added == 0) {
            line += ": added again in none of the " + std::to_string(s.logs) + " logs (";
            for (std::size_t i = k; i < end; ++i)
                line += (i > k ? ", " : "") + s.params[i].param + " " + parameter_text(s.params[i].estimate);
            lines.push_back(line + ")");
        } else {
            line += " (" + std::to_string(first.logs_added) + " of " + std::to_string(s.logs) + " logs):";
            for (std::size_t i = k; i < end; ++i) {
                const ParameterSpread& p = s.params[i];
                line += (i > k ? "; " : " ") + p.param + " ";
                if (p.values.empty())
                    line += parameter_text(p.estimate) + " -> not found again";
                else
                    line += within_spread(p.estimate, p) + " -> " + within_spread(p.quantile(0.16), p) + " to " +
                            within_spread(p.quantile(0.84), p) + " (median " + within_spread(p.quantile(0.5), p) + ")";
                if (!p.values.empty() && p.values.size() < p.logs_added)
                    line += " in " + std::to_string(p.values.size());
            }
            lines.push_back(line);
        }
        k = end;
    }
    return lines;
}

std::vector<std::string> stability_text(const VerdictStability& s, const std::string& verdict) {
    std::vector<std::string> text{"verdict stability: " + stability_sentence(s, verdict)};
    const std::vector<std::string> spread = spread_lines(s);
    if (!spread.empty()) text.emplace_back(kSpreadHeading);
    for (const std::string& line : spread) text.push_back("  " + line);
    return text;
}

std::string stability_sentence(const VerdictStability& s, const std::string& verdict) {
    char head[200];
    std::snprintf(head, sizeof head,
                  "of %zu logs simulated from the estimated model and diagnosed alike, %zu (%.0f %%) are called %s;",
                  s.logs, s.same, s.logs ? 100.0 * static_cast<double>(s.same) / static_cast<double>(s.logs) : 0.0,
                  verdict.c_str());
    std::string text = head;
    for (const auto& [v, n] : s.verdicts) text += " " + v + " " + std::to_string(n);
    return text;
}

}  // namespace driftlab::host::view
