// Benchmark scores; see eval_scores.hpp.
#include "host/gap/eval_scores.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "host/gap/candidates.hpp"
#include "host/gap/truth.hpp"
#include "host/report/json_out.hpp"
#include "host/stats/binomial_interval.hpp"
#include "host/stats/median.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::gap {

namespace {

std::optional<double> median(std::vector<double> v) {
    if (v.empty()) return std::nullopt;
    return stats::median(std::move(v));
}

// A median over no logs is "-" in its cell.
std::string fixed_or_dash(const std::optional<double>& v) { return v ? fixed_point(*v, 2) : "-"; }

nlohmann::json number(const std::optional<double>& v) { return v ? report::json_number(*v) : nlohmann::json(nullptr); }

TargetScore target(std::string name, std::size_t count, std::size_t logs, double bound, bool at_most) {
    TargetScore t{std::move(name), count, logs};
    t.rate = static_cast<double>(count) / static_cast<double>(logs);
    const auto ci = stats::clopper_pearson(count, logs);
    t.low = ci.lower, t.high = ci.upper;
    t.bound = bound, t.at_most = at_most;
    t.met = at_most ? t.rate <= bound : t.rate >= bound;
    t.settled = t.high < bound || t.low > bound;
    return t;
}

// The targets of docs/gap.md read on the scores: the false-positive rate, and at kTargetLevel the top-1 rate of each
// library effect and the attributed share of each out-of-library generator (that one over all sizes too).
std::vector<TargetScore> read_targets(const EvalScores& s) {
    std::vector<TargetScore> out;
    const std::string at_level = " at " + fixed_point(kTargetLevel, 0) + " x a_50";
    if (s.clean)
        out.push_back(target("false positives: clean logs given a verdict", s.clean_flagged, s.clean, 0.05, true));
    for (const auto& z : s.by_size) {
        if (z.generator == "none" || z.level != kTargetLevel || z.logs == 0) continue;
        if (!z.truth.empty()) {
            out.push_back(target("top-1: " + z.generator + " -> " + z.truth + at_level,
                                 static_cast<std::size_t>(z.top1), static_cast<std::size_t>(z.logs), 0.8, false));
            continue;
        }
        const std::size_t wrong = static_cast<std::size_t>(z.logs - z.top1);
        out.push_back(target("attributed: " + z.generator + " (out of library)" + at_level, wrong,
                             static_cast<std::size_t>(z.logs), 0.2, true));
        std::size_t all = 0, all_wrong = 0;
        for (const auto& y : s.by_size)
            if (y.generator == z.generator)
                all += static_cast<std::size_t>(y.logs), all_wrong += static_cast<std::size_t>(y.logs - y.top1);
        if (all > static_cast<std::size_t>(z.logs))
            out.push_back(
                target("attributed: " + z.generator + " (out of library), all sizes", all_wrong, all, 0.2, true));
    }
    return out;
}

std::string percent(double v) { return fixed_point(100.0 * v, 1) + " %"; }

// Each log's added effects as a set against its truth effects (one or two), pooled over the logs of each pair.
std::vector<PairScore> score_pairs(const std::vector<PairCase>& cases) {
    std::vector<PairScore> out;
    std::vector<std::vector<double>> shrinks;
    for (const auto& c : cases) {
        auto it = std::find_if(out.begin(), out.end(), [&](const PairScore& z) {
            return z.first == c.first && z.second == c.second && z.level == c.level;
        });
        if (it == out.end()) {
            PairScore z;
            z.first = c.first, z.second = c.second, z.level = c.level;
            z.first_effect = truth_info(c.first).effect;
            z.second_effect = c.second == "none" ? "" : truth_info(c.second).effect;
            out.push_back(z);
            shrinks.emplace_back();
            it = out.end() - 1;
        }
        const auto in = [&](const std::vector<std::string>& list, const std::string& e) {
            return std::find(list.begin(), list.end(), e) != list.end();
        };
        std::vector<std::string> truths{it->first_effect};
        if (!it->second_effect.empty()) truths.push_back(it->second_effect);
        const auto is_truth = [&](const std::string& e) { return in(truths, e); };
        ++it->logs;
        it->detected += c.detected;
        it->verdict_one += is_truth(c.verdict);
        it->unexplained += c.verdict == "unexplained";
        it->added += static_cast<int>(c.added.size());
        it->truths += static_cast<int>(truths.size());
        int found = 0, found_or_pair = 0;
        for (const std::string& e : truths) {
            found += in(c.added, e);
            found_or_pair += in(c.added, e) || in(c.close_calls, e);
        }
        it->found += found;
        it->found_or_pair += found_or_pair;
        const bool all = found == static_cast<int>(truths.size());
        it->all += all;
        it->wrong += !std::all_of(c.added.begin(), c.added.end(), is_truth);
        for (std::size_t k = 0; k < c.added.size(); ++k)
            if (c.within_bound.at(k)) {
                ++it->within_bound_added;
                it->within_bound_true += is_truth(c.added[k]);
            }
        if (all && c.heldout_before > 1.0)
            shrinks[static_cast<std::size_t>(it - out.begin())].push_back((c.heldout_before - c.heldout_after) /
                                                                          (c.heldout_before - 1.0));
    }
    for (std::size_t k = 0; k < out.size(); ++k) {
        PairScore& z = out[k];
        z.precision = z.added > 0 ? static_cast<double>(z.found) / z.added : 0.0;
        z.recall = static_cast<double>(z.found) / z.truths;
        z.recall_or_pair = static_cast<double>(z.found_or_pair) / z.truths;
        z.f1 = z.precision + z.recall > 0.0 ? 2.0 * z.precision * z.recall / (z.precision + z.recall) : 0.0;
        z.shrink = median(shrinks[k]);
    }
    return out;
}

}  // namespace

EvalScores score(const std::vector<EvalCase>& cases, const Thresholds& th, const EvalOptions& options,
                 const std::vector<DetectionSize>& sizes, const std::vector<PairCase>& pairs) {
    EvalScores s;
    s.options = options;
    s.thresholds = th;
    s.sizes = sizes;
    for (const auto& info : candidate_list()) s.verdicts.push_back(info.effect);
    s.verdicts.push_back("none");
    s.verdicts.push_back("unexplained");
    std::vector<std::string> rows{"none"};
    for (const auto& c : cases)
        if (c.generator != "none" && std::find(rows.begin(), rows.end(), c.generator) == rows.end())
            rows.push_back(c.generator);
    for (const auto& c : cases)
        if (!c.tune && c.generator == "none") ++s.clean, s.clean_flagged += decide(c, th).verdict != "none";
    if (s.clean) {
        const auto ci = stats::clopper_pearson(s.clean_flagged, s.clean);
        s.fpr_low = ci.lower, s.fpr_high = ci.upper;
    }
    for (const auto& row : rows) {
        std::map<std::string, int> count;
        for (const auto& c : cases)
            if (!c.tune && c.generator == row) ++count[decide(c, th).verdict];
        s.confusion.emplace_back(row, count);
        std::vector<double> levels;
        for (const auto& c : cases)
            if (!c.tune && c.generator == row && std::find(levels.begin(), levels.end(), c.level) == levels.end())
                levels.push_back(c.level);
        for (double level : levels) {
            SizeScore z;
            z.generator = row;
            z.level = level;
            std::vector<double> pred, check, oracle, error;
            for (const auto& c : cases) {
                if (c.tune || c.generator != row || c.level != level) continue;
                z.truth = c.truth;
                ++z.logs;
                z.detected += c.detected;
                const Decision d = decide(c, th);
                z.top1 += is_correct(c, d, false);
                z.or_pair += is_correct(c, d, true);
                if (c.has_oracle) oracle.push_back(c.oracle_shrink);
                for (const auto& e : c.tried) {
                    if (e.effect != c.truth || d.verdict != c.truth) continue;
                    pred.push_back(e.heldout_shrink);
                    if (c.has_oracle) error.push_back(std::abs(e.heldout_shrink - c.oracle_shrink));
                }
                if (c.has_shrink_check && d.verdict == c.truth) check.push_back(c.shrink_check);
            }
            z.predicted = median(pred), z.remeasured = median(check), z.oracle = median(oracle),
            z.abs_error = median(error);
            s.by_size.push_back(z);
        }
    }
    s.targets = read_targets(s);
    s.pairs = score_pairs(pairs);
    return s;
}

std::string scores_markdown(const EvalScores& s) {
    const EvalOptions& o = s.options;
    const Thresholds& th = s.thresholds;
    std::ostringstream md;
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
        md << "\nFalse-positive rate on clean" << (o.raw_clean ? " raw-mode" : "") << " logs: " << s.clean_flagged
           << "/" << s.clean << " = "
           << fixed_point(100.0 * static_cast<double>(s.clean_flagged) / static_cast<double>(s.clean), 1)
           << " % (95 % Clopper-Pearson " << fixed_point(100.0 * s.fpr_low, 1) << "-"
           << fixed_point(100.0 * s.fpr_high, 1) << " %).\n";
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
    return md.str();
}

nlohmann::json scores_json(const EvalScores& s) {
    using nlohmann::json;
    const EvalOptions& o = s.options;
    json j;
    j["thresholds"] = {{"penalty_per_param", s.thresholds.penalty_per_param},
                       {"min_heldout_shrink", s.thresholds.min_heldout_shrink},
                       {"step_alpha", s.thresholds.step_alpha},
                       {"information_criterion", criterion_name(s.thresholds.information_criterion)}};
    j["tune_seeds"] = o.tune ? json{o.tune_first, o.tune_last} : json(nullptr);
    j["score_seeds"] = {o.score_first, o.score_last};
    j["samples"] = o.samples;
    j["replicates"] = o.replicates;
    json a50 = json::array();
    for (const auto& d : s.sizes) {
        json curve = json::array();
        for (const auto& p : d.curve) curve.push_back({{"size", p.size}, {"detected", p.detected}, {"logs", p.logs}});
        a50.push_back({{"generator", d.generator}, {"a50", report::json_number(d.a50)}, {"curve", curve}});
    }
    j["a50"] = a50;
    j["false_positive"] = {
        {"clean", s.clean},
        {"flagged", s.clean_flagged},
        {"rate", s.clean ? static_cast<double>(s.clean_flagged) / static_cast<double>(s.clean) : 0.0},
        {"interval", {s.fpr_low, s.fpr_high}},
        {"raw_mode", s.options.raw_clean}};
    json confusion = json::object();
    for (const auto& [row, count] : s.confusion) confusion[row] = count;
    j["confusion"] = confusion;
    json rows = json::array();
    for (const auto& z : s.by_size)
        rows.push_back({{"generator", z.generator},
                        {"truth", z.truth},
                        {"level", z.level},
                        {"logs", z.logs},
                        {"detected", z.detected},
                        {"top1", z.top1},
                        {"or_pair", z.or_pair},
                        {"shrink",
                         {{"predicted", number(z.predicted)},
                          {"remeasured", number(z.remeasured)},
                          {"oracle", number(z.oracle)},
                          {"abs_error", number(z.abs_error)}}}});
    j["by_size"] = rows;
    json targets = json::array();
    for (const auto& t : s.targets)
        targets.push_back({{"target", t.target},
                           {"count", t.count},
                           {"logs", t.logs},
                           {"rate", t.rate},
                           {"interval", {t.low, t.high}},
                           {"bound", t.bound},
                           {"at_most", t.at_most},
                           {"met", t.met},
                           {"settled", t.settled}});
    j["targets"] = targets;
    json pairs = json::array();
    for (const auto& z : s.pairs) {
        json effects = json::array({z.first_effect});
        if (!z.second_effect.empty()) effects.push_back(z.second_effect);
        pairs.push_back({{"generators", {z.first, z.second}},
                         {"effects", effects},
                         {"level", z.level},
                         {"logs", z.logs},
                         {"detected", z.detected},
                         {"verdict_one", z.verdict_one},
                         {"all", z.all},
                         {"wrong", z.wrong},
                         {"unexplained", z.unexplained},
                         {"added", z.added},
                         {"found", z.found},
                         {"truths", z.truths},
                         {"found_or_pair", z.found_or_pair},
                         {"within_bound_added", z.within_bound_added},
                         {"within_bound_true", z.within_bound_true},
                         {"precision", report::json_number(z.precision)},
                         {"recall", report::json_number(z.recall)},
                         {"recall_or_pair", report::json_number(z.recall_or_pair)},
                         {"f1", report::json_number(z.f1)},
                         {"shrink", number(z.shrink)}});
    }
    j["pairs"] = pairs;
    return j;
}

}  // namespace driftlab::host::gap
