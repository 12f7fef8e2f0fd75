// The terminal's text of a gap result; see gap_view.hpp.
#include <cstdio>
#include <string>

#include "host/gap/candidates.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/format_number.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"

namespace driftlab::host::view {

using gap::GapOptions;
using gap::GapResult;

namespace {

// The verdict, the scores, what was left out and the located cells.
void print_where(const GapResult& r, const GapOptions& options, const LogData& log) {
    std::printf("verdict: %s (%s)\n", r.verdict.c_str(), verdict_reason(r, options).c_str());
    if (const std::string slow = slow_drift_sentence(r, log); !slow.empty())
        std::printf("slow drift: %s\n", slow.c_str());
    std::printf(
        "gap (mean z^2 over its null; 1 = consistent)  before: fit %.2f heldout %.2f   after: fit %.2f heldout %.2f"
        " (held-out bound %.2f: %s)\n",
        r.gap_before_fit, r.gap_before_heldout, r.gap_after_fit, r.gap_after_heldout, r.gap_bound_after,
        r.gap_after_heldout <= r.gap_bound_after ? "closed" : "not closed");
    if (const std::string constant = constant_channels_sentence(r); !constant.empty())
        std::printf("not analysed: %s\n", constant.c_str());
    if (const std::string quiet = noise_free_sentence(r); !quiet.empty())
        std::printf("not analysed: %s\n", quiet.c_str());
    if (const std::string saturated = saturated_channels_sentence(r); !saturated.empty())
        std::printf("saturated: %s\n", saturated.c_str());
    for (const auto& l : r.lone_values)
        std::printf("warning: %s: %s\n", kChannelNames[channel_index(l.channel)], l.warning.c_str());
    if (const std::string left_out = left_out_sentence(r); !left_out.empty())
        std::printf("left out: %s\n", left_out.c_str());
    std::printf("located cells (|z| > %.2f and beyond the margin): %zu\n", r.before.threshold, r.located.size());
    if (r.diffuse_gap)
        std::printf(
            "diffuse gap: the held-out score %.2f exceeds its bound %.2f with no cell located (many cells a little "
            "off)%s\n",
            r.gap_before_heldout, r.gap_bound_before,
            r.diffuse_searched ? "; candidates searched on it"
            : options.explain  ? "; --search-diffuse tries the candidates on it"
                               : "; no candidate tried (--locate-only)");
    constexpr std::size_t kCellsShown = 15;  // the largest |z| first; a terminal, not a table
    for (std::size_t i = 0; i < r.located.size() && i < kCellsShown; ++i) {
        const auto& l = r.located[i];
        const auto& c = r.layout[l.index];
        std::printf("  %-5s %-16s %-28s %-7s z %7.1f  %s\n", c.statistic.c_str(), c.channel.c_str(), c.shown().c_str(),
                    gap::segment_name(c.segment), l.z, located_cell_text(r, l).c_str());
    }
    if (r.located.size() > kCellsShown)
        std::printf("  ... and %zu more with smaller |z| (--json and --report list them)\n",
                    r.located.size() - kCellsShown);
}

// The effects added, in order, and the paths followed beside them.
void print_explanation(const GapResult& r, const GapOptions& options, const LogData& log) {
    if (const std::string given = given_effects_sentence(r.given); !given.empty())
        std::printf("base: %s\n", given.c_str());
    if (!r.accepted.empty())
        std::printf(
            "explanation (effects added in order; heldout: the channel's held-out score before -> after the step, %s; "
            "parameters estimated on the whole log beside them all):\n",
            kShrinkDefinition);
    for (const auto& e : r.accepted) {
        const std::string within =
            e.within_bound_before() ? std::string("; ") + kWithinBoundNote + " " + fixed_point(e.heldout_bound, 2) : "";
        std::printf("  %d %-18s %-8s heldout %.2f -> %.2f (shrink %s%%%s)  %s", e.step, e.effect.c_str(),
                    e.channel.c_str(), e.heldout_before, e.heldout_after,
                    fixed_point(100 * e.heldout_shrink, 0).c_str(), within.c_str(),
                    estimate_text(e, log.t_s.back()).c_str());
        if (e.replaces_given) std::printf("  in place of the model's");
        std::printf("\n    %s%s\n",
                    e.ambiguous_with.empty() ? "to confirm: "
                                             : ("AMBIGUOUS with " + e.ambiguous_with + "; to settle: ").c_str(),
                    e.settle.c_str());
    }
    for (const auto& p : r.paths)
        std::printf(
            "  step %d on %s: %s first and %s first both followed; criterion at the end %.1f and %.1f (kept: %s first, "
            "a shape path needs %.0f less)\n",
            p.step, p.channel.c_str(), p.process.c_str(), p.shape.c_str(), p.criterion_process, p.criterion_shape,
            (p.shape_kept ? p.shape : p.process).c_str(), options.explain_options.shape_path_margin);
}

// Every candidate tried, added first.
void print_candidates(const GapResult& r, const GapOptions& options) {
    const gap::ExplainOptions& rules = options.explain_options;
    if (!r.tried.empty())
        std::printf(
            "candidates (fitted on the fitting part, judged on the held-out part; the added first, then by step; "
            "heldout and "
            "shrink as above; gain vs penalty: the likelihood gain against its parameters' price, passing needs gain > "
            "%s x penalty; "
            "dIC: the spectral criterion (%s) without it minus with it, > 0 favours it):\n",
            significant(rules.penalty_per_param, 3).c_str(), gap::criterion_name(rules.information_criterion));
    for (const gap::Explanation* candidate : candidates_in_table_order(r)) {
        const gap::Explanation& e = *candidate;
        std::printf("  %d %-18s %-8s %s  heldout %.2f -> %.2f (shrink %s%%)  gain %s vs penalty %s ", e.step,
                    e.effect.c_str(), e.channel.c_str(),
                    gap::was_added(r, e) ? "ADDED   "
                    : e.accepted         ? "passed  "
                                         : "rejected",
                    e.heldout_before, e.heldout_after, fixed_point(100 * e.heldout_shrink, 0).c_str(),
                    fixed_point(e.loss_gain, 1).c_str(), fixed_point(e.penalty, 1).c_str());
        if (gap::has_delta_ic(e))
            std::printf(" dIC %s", fixed_point(gap::delta_ic(e, rules.information_criterion), 1).c_str());
        if (!e.params.empty()) std::printf(" %s", parameter_list(e.params).c_str());
        if (!e.ambiguous_with.empty()) std::printf("  AMBIGUOUS with %s", e.ambiguous_with.c_str());
        std::printf("\n");
    }
}

// Level steps, what a static log cannot tell, and the log's timing.
void print_limits(const GapResult& r) {
    for (const auto& s : r.level_steps)
        std::printf(
            "level steps on %s: %s at t = %.1f s, %s at %.1f s; likelihood %.1f over the model (price %.1f), "
            "p = %.3f (%s)\n",
            kChannelNames[channel_index(s.channel)],
            step_size_text(r.base, s.channel, s.steps[0].size_counts, 2).c_str(), s.steps[0].t_s,
            step_size_text(r.base, s.channel, s.steps[1].size_counts, 2).c_str(), s.steps[1].t_s, s.statistic, s.margin,
            s.p_value, gap::step_reading(s));
    std::printf("not identifiable from a static log:");
    for (const auto& n : gap::not_identifiable_list())
        if (!tried_in_motion(r, n.effect)) std::printf(" %s", n.effect.c_str());
    std::printf("\n");
    for (const auto& n : r.not_tried) std::printf("not tried: %s (%s)\n", n.effect.c_str(), n.reason.c_str());
    // Always: clock_jitter's not-identifiable reason points here for the log's own timestamps. A spread below 1e-6 %
    // is the rounding of the times as written (1.51e-13 % on a hil log), not a timing to report.
    const double jitter_percent = 100.0 * r.timing.dt_jitter_rel;
    std::printf(
        "timing: %s (%s lost), %s; %s\n", counted(r.timing.sequence_jumps, "sequence jump").c_str(),
        counted(static_cast<std::size_t>(r.timing.lost_frames), "frame").c_str(),
        counted(r.timing.gap_events, "gap event").c_str(),
        jitter_percent < 1e-6
            ? "row spacing constant (its sd below 1e-6 % of the rows' period)"
            : ("row spacing varies by " + significant(jitter_percent, 3) + " % of the rows' period (sd)").c_str());
}

}  // namespace

void print_gap_text(const GapResult& r, const GapOptions& options, const LogData& log,
                    const gap::VerdictStability* stability) {
    print_where(r, options, log);
    print_explanation(r, options, log);
    print_candidates(r, options);
    print_motion_text(r);
    print_link_text(r);
    print_common_text(r);
    print_limits(r);
    if (stability)
        for (const std::string& line : stability_text(*stability, r.verdict)) std::printf("%s\n", line.c_str());
}

std::string model_file_comment(const GapResult& r, const std::string& source, const std::vector<std::string>& notes,
                               const gap::VerdictStability* stability) {
    std::string effects;
    for (const auto& e : r.accepted) effects += " " + e.effect + " (" + e.channel + ")";
    std::string comment = "driftlab gap " + source + ": verdict " + r.verdict +
                          "\ncalibrated eq. 1 and white noise of the analysed channels, the log's smoothing, effects "
                          "added:" +
                          (effects.empty() ? " none" : effects);
    if (const std::string given = given_effects_sentence(r.given); !given.empty()) comment += "\n" + given;
    for (const std::string& n : notes) comment += "\nnote: " + n;
    if (stability)
        for (const std::string& line : stability_text(*stability, r.verdict)) comment += "\n" + line;
    return comment;
}

}  // namespace driftlab::host::view
