// The report DIR/gap.md of a gap result; see gap_view.hpp.
#include <cctype>
#include <fstream>
#include <sstream>

#include "host/gap/candidates.hpp"
#include "host/log/log_reader.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/output_folder.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_plots.hpp"
#include "host/view/gap_view.hpp"

namespace driftlab::host::view {

using gap::ExplainOptions;
using gap::Explanation;
using gap::GapOptions;
using gap::GapResult;
using gap::VerdictStability;

namespace {

// What was analysed, the verdict and why, and how stable it is.
void md_verdict(std::ostream& md, const GapResult& r, const LogData& log, const GapOptions& options,
                const VerdictStability* stability) {
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
}

// The words the tables below use, for a reader who has not read docs/gap.md.
void md_reading_guide(std::ostream& md, const GapOptions& options) {
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
}

// What was left out and the gap scores before and after.
void md_scores(std::ostream& md, const GapResult& r, const LogData& log, const GapOptions& options) {
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
}

// The effects added, in order, and the paths followed beside them.
void md_explanation(std::ostream& md, const GapResult& r, const LogData& log, const GapOptions& options) {
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
}

void md_located(std::ostream& md, const GapResult& r, const GapOptions& options) {
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
}

void md_candidates(std::ostream& md, const GapResult& r, const GapOptions& options) {
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
}

// Level steps, and what a static log cannot tell.
void md_limits(std::ostream& md, const GapResult& r) {
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
    for (const auto& n : gap::not_identifiable_list()) md << "- " << n.effect << ": " << n.reason << "\n";
    if (!r.not_tried.empty()) md << "\nNot tried on this log:\n\n";
    for (const auto& n : r.not_tried) md << "- " << n.effect << ": " << n.reason << "\n";
}

}  // namespace

std::vector<std::string> report_files(const std::string& dir) {
    std::vector<std::string> out{dir + "/gap.md"};
    const std::vector<std::string> plots = residual_plot_files(dir);
    out.insert(out.end(), plots.begin(), plots.end());
    return out;
}

void write_gap_report(const GapResult& r, const LogData& log, const std::string& dir, const GapOptions& options,
                      const VerdictStability* stability) {
    make_output_folder(dir, "report");
    std::ostringstream md;
    md_verdict(md, r, log, options, stability);
    md_reading_guide(md, options);
    md_scores(md, r, log, options);
    md_explanation(md, r, log, options);
    md_located(md, r, options);
    md_candidates(md, r, options);
    write_link_markdown(md, r);
    write_common_markdown(md, r);
    md_limits(md, r);
    write_residual_plots(md, r, log, dir, options);
    std::ofstream out(dir + "/gap.md");
    out << md.str();
    if (!out) throw DeviceError(dir + "/gap.md", "cannot write the report");
}

}  // namespace driftlab::host::view
