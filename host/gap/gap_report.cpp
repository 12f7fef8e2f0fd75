// The gap report; see gap_report.hpp.
#include "host/gap/gap_report.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/lm_fit.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/spectral.hpp"
#include "host/log/log_reader.hpp"
#include "host/report/gnuplot.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_folder.hpp"
#include "host/util/units.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kBandReplicates = 12;

// The report's plots: gap_<kind>_<channel>, as PNG (gap.md links them); plot_bands() draws them, report_files() lists
// them all.
const std::vector<report::ImageFormat> kPlotFormats{report::ImageFormat::png};
constexpr std::array<const char*, 3> kPlotKinds{"adev", "mean", "codes"};

std::string plot_name(const char* kind, const std::string& channel) {
    return std::string("gap_") + kind + "_" + channel;
}

struct Band {
    std::vector<double> low, high;

    void widen(const std::vector<double>& v) {
        if (low.empty()) low = high = v;
        for (std::size_t j = 0; j < v.size(); ++j) {
            low[j] = std::min(low[j], v[j]);
            high[j] = std::max(high[j], v[j]);
        }
    }
};

// Sample-index edges of the time bins of the mean-over-time plot: about 30 outputs each, 10 to 60 bins.
std::vector<std::size_t> time_bins(std::size_t n) {
    const std::size_t bins = std::clamp<std::size_t>(n / 30, 10, 60);
    std::vector<std::size_t> edges(bins + 1);
    for (std::size_t b = 0; b <= bins; ++b) edges[b] = b * n / bins;
    return edges;
}

std::vector<double> binned_mean(const std::vector<double>& v, const std::vector<std::size_t>& edges) {
    std::vector<double> out(edges.size() - 1);
    for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
        double sum = 0.0;
        for (std::size_t k = edges[b]; k < edges[b + 1]; ++k) sum += v[k];
        out[b] = sum / static_cast<double>(std::max<std::size_t>(1, edges[b + 1] - edges[b]));
    }
    return out;
}

// The share of rows on each code from `lowest` to `highest` (codes outside count in neither).
std::vector<double> code_shares(const std::vector<double>& codes, int lowest, int highest) {
    std::vector<double> out(static_cast<std::size_t>(highest - lowest + 1), 0.0);
    for (double v : codes) {
        const long code = std::lround(v);
        if (code >= lowest && code <= highest)
            out[static_cast<std::size_t>(code - lowest)] += 1.0 / static_cast<double>(codes.size());
    }
    return out;
}

// The codes a raw-mode log's channel holds, lowest to highest; empty for a channel without raw codes.
struct CodeRange {
    const std::vector<double>* real = nullptr;
    int lowest = 0, highest = -1;
};

// What the real log's eq. 1 residual should fall in under `model`: pointwise min/max over a few replicates, each
// refitted as the log is, of the residual's octave ADEV and of its mean per time bin; and, for a raw-mode channel,
// of the share of rows on each code (where a code of the wrong width shows).
struct ReplicateBands {
    Band adev, mean, codes;
};

ReplicateBands replicate_bands(const GapModel& model, const LogData& log, std::size_t c, std::size_t max_m,
                               const std::vector<std::size_t>& edges, const CodeRange& range, std::uint64_t seed) {
    ReplicateBands bands;
    for (int r = 0; r < kBandReplicates; ++r) {
        sim::OutputRequest req;
        req.t_s = &log.t_s;
        req.channels = {};
        req.channels[c] = true;
        sim::Outputs raw;
        if (range.real) req.raw_codes = &raw;
        const sim::Outputs sim = sim::simulate_outputs(model, req, replicate_seed(seed, r));
        const auto residual = fit::fit_drift(log.t_s, sim[c], start_at_model(model, static_cast<Channel>(c))).residual;
        bands.adev.widen(octave_oadev(residual, max_m));
        bands.mean.widen(binned_mean(residual, edges));
        if (range.real) bands.codes.widen(code_shares(raw[c], range.lowest, range.highest));
    }
    return bands;
}

// The unit plots and step sizes are shown in: the diagnosis's physical one (deg/s; g as mg, so an accelerometer's
// noise does not read in thousandths), through the model's converter, so a plain table's are in its own unit. The
// bands are drawn from counts and scaled after: a constant factor moves no line against another.
PhysicalUnit display_unit(const GapModel& model, Channel c) {
    const double per_count = 1.0 / counts_per_unit(model, c);
    return c == Channel::gyro ? PhysicalUnit{per_count, "deg/s"} : PhysicalUnit{per_count * 1000.0, "mg"};
}

// An accepted effect's or a mean cell's channel: both are named from kChannelNames, so another name is a bug.
Channel explained_channel(const std::string& name) {
    if (const std::optional<Channel> c = channel_named(name)) return *c;
    throw std::invalid_argument("no channel '" + name + "'");
}

std::vector<double> scaled(std::vector<double> v, double k) {
    for (double& x : v) x *= k;
    return v;
}

Band scaled(const Band& b, double k) { return {scaled(b.low, k), scaled(b.high, k)}; }

// A channel's real residual against the replicate bands of the base and of the final model, as DIR/<plot_name()>;
// returns gap.md's link to its image.
std::string plot_bands(const std::string& title, const std::string& x_label, const std::string& y_label, bool log_axes,
                       const std::vector<double>& x, const std::vector<double>& real, const Band& base,
                       const Band* after, const std::string& dir, const std::string& name) {
    report::Plot p;
    p.title = title;
    p.x_label = x_label;
    p.y_label = y_label;
    p.log_x = p.log_y = log_axes;
    p.series.push_back({"base simulator (" + std::to_string(kBandReplicates) + " replicates)", x, base.low, base.low,
                        base.high, report::SeriesStyle::band, false, "red", 1.0});
    if (after)
        p.series.push_back({"with the added effects", x, after->low, after->low, after->high, report::SeriesStyle::band,
                            false, "blue", 1.0});
    p.series.push_back({"real", x, real, {}, {}, report::SeriesStyle::lines, false, "black", 2.0});
    const std::string image =
        std::filesystem::path(report::render_plot(p, dir, name, kPlotFormats).front()).filename().string();
    return "![" + name + "](" + image + ")\n\n";
}

}  // namespace

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

std::vector<std::string> report_files(const std::string& dir) {
    std::vector<std::string> out{dir + "/gap.md"};
    for (const char* channel : kChannelNames)
        for (const char* kind : kPlotKinds) {
            const auto files = report::plot_files(dir, plot_name(kind, channel), kPlotFormats);
            out.insert(out.end(), files.begin(), files.end());
        }
    return out;
}

void write_gap_report(const GapResult& r, const LogData& log, const std::string& dir, const GapOptions& options,
                      const VerdictStability* stability) {
    make_output_folder(dir, "report");
    std::ostringstream md;
    md << "# Sim-to-real gap: " << log.source_name << "\n\n";
    // What was analysed, since --from/--to and --exclude may have cut it: a report read later has no command line.
    md << counted(log.size(), "row") << " analysed, t = " << format_double(log.t_s.front()) << " s to "
       << format_double(log.t_s.back()) << " s.\n\n";
    md << "**Verdict: " << r.verdict << "**: " << verdict_reason(r, options) << ".\n\n";
    if (const std::string slow = slow_drift_sentence(r, log); !slow.empty()) md << "Slow drift: " << slow << ".\n\n";
    if (stability) {
        md << "Verdict stability: " << stability_sentence(*stability, r.verdict) << ".\n\n";
        const std::vector<std::string> spread = spread_lines(*stability);
        if (!spread.empty()) {
            std::string heading = kSpreadHeading;  // the terminal's words, opening a sentence here
            heading.front() = static_cast<char>(std::toupper(static_cast<unsigned char>(heading.front())));
            md << heading << "\n\n";
        }
        for (const std::string& line : spread) md << "- " << line << "\n";
        if (!spread.empty()) md << "\n";
    }
    // The words the tables below use, for a reader who has not read docs/gap.md.
    md << "## How to read this report\n\n"
          "The simulator, calibrated to this log, is run "
       << options.replicates
       << " times with fresh noise on the log's own "
          "instants (the *replicates*). The same set of statistics (the *battery*: means and variances over tenths of "
          "the log, "
          "Allan deviations, spectra and autocorrelations by octave, and more) is computed on the log and on every "
          "replicate; "
          "one statistic on one window, band or lag of one part of the log is a *cell*. A cell is *located* where the "
          "log "
          "lies outside what the replicates do: its z (the distance from the replicates' mean in their standard "
          "deviations) "
          "is beyond a threshold that a log the simulator explains crosses in about "
       << fixed_point(100 * options.alpha, 0)
       << " % of cases, and its difference is beyond a *practical margin*, the least that matters (0.1 count for a "
          "mean, "
          "10 % for a deviation). The *gap score* is the mean z^2 over the cells divided by the replicates' own: about "
          "1 "
          "when the simulator explains the log.\n\n"
          "Candidate effects are fitted on one part of the log and judged on the other, the *held-out part*: an effect "
          "must "
          "predict data it was not fitted to. *Shrink* is the share of a held-out score's excess over 1 that an effect "
          "removes, (before - after) / (before - 1): 100 % brings the score to 1 (more, below 1), a negative shrink "
          "makes it worse. "
          "*Gain / penalty*: how much the cells' likelihood gains with the effect, against the price of its "
          "parameters. "
          "*ΔIC*: the full-log spectral information criterion without the effect minus with it, above 0 where the "
          "spectrum "
          "favours the effect. A *level step* is an abrupt jump of the mean, which no effect of the library makes. "
          "docs/gap.md, in the driftlab sources, gives the method and every rule in full.\n\n";
    if (const std::string constant = constant_channels_sentence(r); !constant.empty())
        md << "Not analysed: " << constant << ".\n\n";
    if (const std::string quiet = noise_free_sentence(r); !quiet.empty()) md << "Not analysed: " << quiet << ".\n\n";
    if (const std::string saturated = saturated_channels_sentence(r); !saturated.empty())
        md << "Saturated: " << saturated << ".\n\n";
    for (const auto& l : r.lone_values)  // no full stop after the window to copy
        md << "Warning: " << kChannelNames[channel_index(l.channel)] << ": " << l.warning << "\n\n";
    if (const std::string left_out = left_out_sentence(r); !left_out.empty()) md << "Left out: " << left_out << ".\n\n";
    if (const std::string cut = dropped_cut_line_note(log); !cut.empty()) md << "Note: " << cut << ".\n\n";
    if (const std::string given = given_effects_sentence(r.given); !given.empty()) md << "Base: " << given << ".\n\n";
    md << "Gap score (mean z^2 of the battery over its replicate null; about 1 when the simulator explains the log), "
       << options.replicates << " replicates; " << holdout_description(options.holdout, options.fit_fraction)
       << "; at most " << counted(static_cast<std::size_t>(options.explain_options.max_effects), "effect")
       << " added stepwise"
       << ". A held-out score within its bound (level " << options.alpha << ") is a closed gap."
       << "\n\n| | fitting part | held-out part | held-out bound |\n|---|---|---|---|\n";
    md << "| base simulator | " << fixed_point(r.gap_before_fit, 2) << " | " << fixed_point(r.gap_before_heldout, 2)
       << " | " << fixed_point(r.gap_bound_before, 2) << " |\n";
    md << "| with the added effects | " << fixed_point(r.gap_after_fit, 2) << " | "
       << fixed_point(r.gap_after_heldout, 2) << " | " << fixed_point(r.gap_bound_after, 2) << " |\n\n";
    if (!r.accepted.empty()) {
        md << "## Explanation: the effects added, in order\n\nParameters as estimated on the whole log beside all the "
              "added effects, and (for a mean shape or a Gaussian process) the fitting part's, which the held-out part "
              "judged; the held-out score is the channel's, before and after each step ("
           << kShrinkDefinition
           << ").\n\n"
              "| step | effect | channel | parameters | channel's held-out score | shrink | close call | what would "
              "confirm it |\n"
              "|---|---|---|---|---|---|---|---|\n";
        for (const auto& e : r.accepted)
            md << "| " << e.step << " | " << e.effect << (e.replaces_given ? " (in place of the model's)" : "") << " | "
               << e.channel << " | " << estimate_text(e, log.t_s.back()) << " | " << fixed_point(e.heldout_before, 2)
               << " -> " << fixed_point(e.heldout_after, 2)
               << (e.within_bound_before() ? " (within its bound " + fixed_point(e.heldout_bound, 2) + " before)" : "")
               << " | " << fixed_point(100 * e.heldout_shrink, 0) << " % | "
               << (e.ambiguous_with.empty() ? "-" : "ambiguous with " + e.ambiguous_with) << " | " << e.settle
               << " |\n";
        md << "\n";
    }
    if (!r.paths.empty()) {
        md << "A Gaussian process chosen over an accepted mean shape may have taken the shape's signal with the rest, "
              "so "
              "the path that adds the shape first was followed too; the path whose final model has the lower full-log "
              "spectral criterion on the channel is kept (a shape path by more than "
           << fixed_point(options.explain_options.shape_path_margin, 0) << ").\n\n"
           << "| step | channel | process first | shape first | criterion at the end | kept "
              "|\n|---|---|---|---|---|---|\n";
        for (const auto& p : r.paths)
            md << "| " << p.step << " | " << p.channel << " | " << p.process << " | " << p.shape << " | "
               << fixed_point(p.criterion_process, 1) << " / " << fixed_point(p.criterion_shape, 1) << " | "
               << (p.shape_kept ? p.shape : p.process) << " first |\n";
        md << "\n";
    }
    md << "## Where: located cells (|z| > " << fixed_point(r.before.threshold, 2)
       << " and a difference beyond the cell's practical margin)\n\n";
    if (r.located.empty()) {
        md << "None: no cell lies beyond both.\n\n";  // a table of headers alone reads as a failure to fill it
    } else {
        md << "| statistic | channel | cell | part | z | ratio or difference [95 % interval] "
              "|\n|---|---|---|---|---|---|\n";
        for (const auto& l : r.located) {
            const auto& c = r.layout[l.index];
            md << "| " << c.statistic << " | " << c.channel << " | " << c.shown() << " | " << segment_name(c.segment)
               << " | " << fixed_point(l.z, 1) << " | " << located_cell_text(r, l) << " |\n";
        }
        md << "\n"
           << counted(r.located.size(), "cell") << " located before, " << r.located_after.size() << " after.\n\n";
    }
    if (r.diffuse_gap)
        md << "Diffuse gap: the held-out score exceeds its bound with no cell located (many cells a little off, none "
              "alone beyond the threshold). "
           << (r.diffuse_searched ? "The candidates were searched on it (--search-diffuse).\n\n"
               : options.explain  ? "The candidates were not searched (--search-diffuse searches them).\n\n"
                                  : "No candidate was tried (--locate-only).\n\n");
    const ExplainOptions& rules = options.explain_options;
    md << "## Which: candidate effects\n\n";
    if (r.tried.empty())
        md << "None tried"
           << (!options.explain                           ? " (--locate-only)"
               : r.located.empty() && !r.diffuse_searched ? ": no cell located, nothing to explain"
                                                          : "")
           << ".\n";
    else
        md << "Fitted on the fitting part, judged on the held-out part: the added effects first, in step order, then "
              "the others "
              "by step. The held-out score is the channel's, before -> with the candidate ("
           << kShrinkDefinition
           << "). A candidate "
              "passes when, among other tests, its gain exceeds "
           << significant(rules.penalty_per_param, 3)
           << " x its penalty and "
              "it shrinks the held-out score by at least "
           << fixed_point(100 * rules.min_heldout_shrink, 0)
           << " %; among the mean "
              "shapes and Gaussian processes that pass, the one with the largest ΔIC ("
           << criterion_name(rules.information_criterion)
           << ": the criterion without the candidate minus with it, so above 0 favours it) is chosen. ΔIC is computed "
              "for "
              "those only (else -), and an effect added at a later step can have ΔIC at or below 0: it passed the "
              "held-out tests, "
              "but the spectrum alone would not pay for its parameters.\n\n"
              "| step | effect | channel | parameters | channel's held-out score | shrink | gain / penalty | ΔIC (> 0 "
              "favours it) | decision |\n"
              "|---|---|---|---|---|---|---|---|---|\n";
    for (const Explanation* candidate : candidates_in_table_order(r)) {
        const Explanation& e = *candidate;
        md << "| " << e.step << " | " << e.effect << " | " << e.channel << " | " << parameter_list(e.params) << " | "
           << fixed_point(e.heldout_before, 2) << " -> " << fixed_point(e.heldout_after, 2) << " | "
           << fixed_point(100 * e.heldout_shrink, 0) << " % | " << fixed_point(e.loss_gain, 1) << " / "
           << fixed_point(e.penalty, 1) << " | "
           << (has_delta_ic(e) ? fixed_point(delta_ic(e, rules.information_criterion), 1) : std::string("-")) << " | "
           << (was_added(r, e) ? "**added**"
               : e.accepted    ? "passed, not chosen"
                               : "rejected")
           << (e.residual_step.significant ? ", leaves a level step" : "")
           << (e.shape_steps.steps_win ? ", two level steps fit better" : "")
           << (e.ambiguous_with.empty() ? "" : ", ambiguous with " + e.ambiguous_with) << " |\n";
    }
    for (const auto& s : r.level_steps) {
        md << "\nLevel-step test, " << kChannelNames[channel_index(s.channel)] << ": two steps of "
           << step_size_text(r.base, s.channel, s.steps[0].size_counts, 3)
           << " at t = " << fixed_point(s.steps[0].t_s, 1) << " s and "
           << step_size_text(r.base, s.channel, s.steps[1].size_counts, 3)
           << " at t = " << fixed_point(s.steps[1].t_s, 1) << " s: likelihood over the explanation "
           << fixed_point(s.statistic, 1) << " (price " << fixed_point(s.margin, 1) << ", p "
           << fixed_point(s.rival_p, 3) << "); largest whitened impulse " << fixed_point(s.impulse, 2) << " (p "
           << fixed_point(s.impulse_p, 3) << "); combined p = " << fixed_point(s.p_value, 3)
           << "; the processes beside the steps " << fixed_point(s.process_gain, 1) << " over the floor (price "
           << fixed_point(s.process_margin, 1) << ")"
           << " (" << step_reading(s) << ")\n";
    }
    md << "\nNot identifiable from a static log:\n\n";
    for (const auto& n : not_identifiable_list()) md << "- " << n.effect << ": " << n.reason << "\n";
    if (!r.not_tried.empty()) md << "\nNot tried on this log:\n\n";
    for (const auto& n : r.not_tried) md << "- " << n.effect << ": " << n.reason << "\n";
    md << "\n## The residual against the simulator's replicates\n\nThe eq. 1 residual of the real log (black) against "
          "the min-max band of "
       << kBandReplicates
       << " replicates of the base simulator (red) and of the simulator with "
          "the added effects (blue), each replicate refitted as the log is: its Allan deviation by octave, and its "
          "mean "
          "over time (where a mean shape or a step shows); for a raw-mode log also the share of rows on each raw code "
          "(where a code of the wrong width shows).\n\n";
    std::string scales;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!r.channels[c]) continue;
        const PhysicalUnit unit = display_unit(r.base, static_cast<Channel>(c));
        scales += std::string(scales.empty() ? "" : ", ") + significant_plain(unit.per_count, 3) + " " + unit.name +
                  " on " + kChannelNames[c];
    }
    if (!scales.empty()) md << "The plots are in physical units; one count is " << scales << ".\n\n";
    const bool plots = report::gnuplot_available();
    if (!plots) md << "(gnuplot not found: plots skipped)\n";
    const std::vector<std::size_t> edges = time_bins(log.size());
    std::vector<double> bin_t(edges.size() - 1);
    for (std::size_t b = 0; b + 1 < edges.size(); ++b) bin_t[b] = 0.5 * (log.t_s[edges[b]] + log.t_s[edges[b + 1] - 1]);
    for (std::size_t c = 0; c < kChannelCount && plots; ++c) {
        if (!r.channels[c]) continue;
        const std::size_t max_m = std::max<std::size_t>(1, log.size() / 8);
        const auto residual = fit::fit_drift(log.t_s, log.counts[c]).residual;
        const auto real = octave_oadev(residual, max_m);
        CodeRange range;
        if (r.raw_codes[c]) {
            range.real = &log.optional_columns.at(std::string("raw_") + kChannelNames[c]);
            const auto [lo, hi] = std::minmax_element(range.real->begin(), range.real->end());
            range.lowest = static_cast<int>(std::lround(*lo));
            range.highest = static_cast<int>(std::lround(*hi));
        }
        const ReplicateBands base = replicate_bands(r.base, log, c, max_m, edges, range, options.seed);
        const ReplicateBands after = replicate_bands(r.final_model, log, c, max_m, edges, range, options.seed);
        const ReplicateBands* added = r.accepted.empty() ? nullptr : &after;
        std::vector<double> tau(real.size());
        for (std::size_t j = 0; j < tau.size(); ++j)
            tau[j] = r.base.smoothing.sample_period_s * std::ldexp(1.0, static_cast<int>(j));
        const std::string channel = kChannelNames[c];
        const PhysicalUnit unit = display_unit(r.base, static_cast<Channel>(c));
        const auto band_in_unit = [&](const Band& b) { return scaled(b, unit.per_count); };
        const Band base_adev = band_in_unit(base.adev), base_mean = band_in_unit(base.mean);
        const Band after_adev = band_in_unit(after.adev), after_mean = band_in_unit(after.mean);
        md << plot_bands("Residual ADEV, " + channel, "tau [s]",
                         std::string("ADEV of the eq. 1 residual [") + unit.name + "]", true, tau,
                         scaled(real, unit.per_count), base_adev, added ? &after_adev : nullptr, dir,
                         plot_name("adev", channel));
        md << plot_bands("Residual mean over time, " + channel, "t [s]",
                         std::string("mean of the eq. 1 residual per bin [") + unit.name + "]", false, bin_t,
                         scaled(binned_mean(residual, edges), unit.per_count), base_mean, added ? &after_mean : nullptr,
                         dir, plot_name("mean", channel));
        if (range.real) {
            std::vector<double> code(static_cast<std::size_t>(range.highest - range.lowest + 1));
            for (std::size_t j = 0; j < code.size(); ++j) code[j] = range.lowest + static_cast<double>(j);
            md << plot_bands("Raw codes, " + channel, "code", "share of rows on the code", false, code,
                             code_shares(*range.real, range.lowest, range.highest), base.codes,
                             added ? &added->codes : nullptr, dir, plot_name("codes", channel));
        }
    }
    std::ofstream out(dir + "/gap.md");
    out << md.str();
    if (!out) throw DeviceError(dir + "/gap.md", "cannot write the report");
}

}  // namespace driftlab::host::gap
