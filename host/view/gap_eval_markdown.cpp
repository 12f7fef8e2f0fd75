// The markdown tables of a gap-eval run; see gap_eval_view.hpp.
#include <cmath>
#include <sstream>

#include "host/gap/candidates.hpp"
#include "host/util/format_number.hpp"
#include "host/view/gap_eval_view.hpp"

namespace driftlab::host::view {

using gap::EvalOptions;
using gap::EvalScores;
using gap::Thresholds;

namespace {

const char* clean_form_text(gap::CleanForm form) {
    switch (form) {
    case gap::CleanForm::raw_mode: return " raw-mode";
    case gap::CleanForm::codes: return " window-1 (outputs that are codes)";
    case gap::CleanForm::lossy_link: return " lossy-link";
    case gap::CleanForm::four_channels: return " four-channel";
    case gap::CleanForm::smoothed: break;
    }
    return "";
}

// A median over no logs is "-" in its cell.
std::string fixed_or_dash(const std::optional<double>& v) { return v ? fixed_point(*v, 2) : "-"; }

std::string percent(double v) { return fixed_point(100.0 * v, 1) + " %"; }

// The thresholds, the seeds, the detection thresholds a_50 and the false-positive rate.
void md_detection(std::ostream& md, const EvalScores& s) {
    const EvalOptions& o = s.options;
    const Thresholds& th = s.thresholds;
    if (o.tune)
        md << "Thresholds tuned on seeds " << o.tune_first << ".." << o.tune_last;
    else
        md << "Thresholds as `driftlab gap` ships them (not tuned)";
    md << ": penalty_per_param = " << th.penalty_per_param << ", min_heldout_shrink = " << th.min_heldout_shrink
       << ", step_alpha = " << th.step_alpha << ", information criterion = " << criterion_name(th.information_criterion)
       << ". Scored on seeds " << o.score_first << ".." << o.score_last << ", " << o.samples
       << "-sample logs, R = " << o.replicates << ".\n\n";
    if (!s.sizes.empty())
        md << "### Detection thresholds a_50 (tuning seeds, " << o.detection_logs
           << " logs per size; unit: the smoothed output's white-noise standard deviation)\n\n"
              "| generator | a_50 | size: detected/logs |\n|---|---|---|\n";
    for (const auto& d : s.sizes) {
        md << "| " << d.generator << " | " << fixed_point(d.a50, 2) << " |";
        // The search can reach one size twice (0.4 and 0.4000000000000001): one entry with both batches, where two
        // entries of the same size had read as two detection rates for it (the fit keeps them apart).
        for (std::size_t i = 0; i < d.curve.size();) {
            int detected = 0, logs = 0;
            std::size_t j = i;
            for (; j < d.curve.size() && std::abs(d.curve[j].size - d.curve[i].size) <= 1e-9 * d.curve[i].size; ++j)
                detected += d.curve[j].detected, logs += d.curve[j].logs;
            md << (i ? "; " : " ") << fixed_point(d.curve[i].size, 2) << ": " << detected << "/" << logs;
            i = j;
        }
        md << " |\n";
    }
    if (s.clean)
        md << "\nFalse-positive rate on clean" << clean_form_text(o.clean_form) << " logs: " << s.clean_flagged << "/"
           << s.clean << " = "
           << fixed_point(100.0 * static_cast<double>(s.clean_flagged) / static_cast<double>(s.clean), 1)
           << " % (95 % Clopper-Pearson " << fixed_point(100.0 * s.fpr_low, 1) << "-"
           << fixed_point(100.0 * s.fpr_high, 1) << " %).\n";
}

void md_confusion(std::ostream& md, const EvalScores& s) {
    md << "\n### Confusion (rows: truth generator -> library effect; columns: verdict), all sizes\n\n| truth |";
    for (const auto& v : s.verdicts) md << " " << v << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < s.verdicts.size(); ++i) md << "---|";
    md << "\n";
    for (const auto& [row, count] : s.confusion) {
        std::string truth = "none";
        for (const auto& z : s.by_size)
            if (z.generator == row) truth = z.truth.empty() ? "out of library" : z.truth;
        md << "| " << row << " (" << truth << ") |";
        for (const auto& v : s.verdicts) md << " " << (count.count(v) ? count.at(v) : 0) << " |";
        md << "\n";
    }
}

// Per generator and size, and the targets read on them.
void md_by_size(std::ostream& md, const EvalScores& s) {
    md << "\n### Per generator and size (scoring seeds)\n\n"
          "`top-1` counts the verdict alone; `or pair` also counts a declared ambiguous pair holding the truth. "
          "Held-out shrink: `predicted` by the diagnosis for the right candidate, `re-measured` on fresh replicates "
          "with the chosen model, `oracle` with the true model (truth base plus fresh realisations of the truth "
          "generator), and the median |predicted - oracle|.\n\n"
          "| truth | size x a_50 | n | detected | top-1 | or pair | predicted | re-measured | oracle | abs error |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& z : s.by_size)
        md << "| " << z.generator << " | " << z.level << " | " << z.logs << " | " << z.detected << " | " << z.top1
           << " | " << z.or_pair << " | " << fixed_or_dash(z.predicted) << " | " << fixed_or_dash(z.remeasured) << " | "
           << fixed_or_dash(z.oracle) << " | " << fixed_or_dash(z.abs_error) << " |\n";
    if (!s.targets.empty()) {
        md << "\n### Targets (scoring seeds; 95 % Clopper-Pearson intervals)\n\n"
              "`met` reads the estimate; `settled` says whether the interval lies wholly on one side of the bound.\n\n"
              "| target | count / logs | rate | 95 % interval | bound | met | settled "
              "|\n|---|---|---|---|---|---|---|\n";
        for (const auto& t : s.targets)
            md << "| " << t.target << " | " << t.count << " / " << t.logs << " | " << percent(t.rate) << " | "
               << percent(t.low) << " - " << percent(t.high) << " | " << (t.at_most ? "<= " : ">= ") << percent(t.bound)
               << " | " << (t.met ? "yes" : "no") << " | " << (t.settled ? "yes" : "no") << " |\n";
    }
}

void md_pairs(std::ostream& md, const EvalScores& s) {
    const EvalOptions& o = s.options;
    if (!s.pairs.empty()) {
        md << "\n### Two effects planted together, or one alone (scoring seeds; each at " << o.pair_level
           << " x its own a_50; diagnosed as `driftlab gap` runs, up to three effects added stepwise)\n\n"
              "Each log's added effects are a set scored against its truth effects (two, or one where the generator is "
              "planted alone), pooled over the logs: `precision`, added effects that are true; `recall`, true effects "
              "added (`or pair`: or declared as an added effect's close call); `F1`, their harmonic mean. `one`: "
              "verdicts (the first effect added) naming a truth effect; `all`: logs given every truth effect; `wrong`: "
              "logs given an effect no truth stands for. Held-out shrink: median (before - after) / (before - 1) of "
              "the final model on the logs given every truth effect. `within bound`: effects added with the channel's "
              "held-out score already within its Monte Carlo bound, true / added.\n\n"
              "| generators (effects) | n | detected | one | all | wrong | unexplained | precision | recall | or pair "
              "| F1 | within bound | held-out shrink |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const auto& z : s.pairs) {
            md << "| " << z.first;
            if (z.second == "none")
                md << " alone (" << z.first_effect << ")";
            else
                md << " + " << z.second << " (" << z.first_effect << " + " << z.second_effect << ")";
            md << " | " << z.logs << " | " << z.detected << " | " << z.verdict_one << " | " << z.all << " | " << z.wrong
               << " | " << z.unexplained << " | " << fixed_point(z.precision, 2) << " | " << fixed_point(z.recall, 2)
               << " | " << fixed_point(z.recall_or_pair, 2) << " | " << fixed_point(z.f1, 2) << " | "
               << z.within_bound_true << " / " << z.within_bound_added << " | " << fixed_or_dash(z.shrink) << " |\n";
        }
        int within_added = 0, within_true = 0, added = 0, found = 0;
        for (const auto& z : s.pairs) {
            within_added += z.within_bound_added, within_true += z.within_bound_true;
            added += z.added, found += z.found;
        }
        md << "\nOver these rows, effects added with the held-out score already within its bound: " << within_true
           << " of " << within_added << " true; the others: " << found - within_true << " of " << added - within_added
           << ".\n";
    }
}

}  // namespace

std::string scores_markdown(const EvalScores& s) {
    std::ostringstream md;
    md_detection(md, s);
    md_confusion(md, s);
    md_by_size(md, s);
    md_pairs(md, s);
    return md.str();
}

}  // namespace driftlab::host::view
