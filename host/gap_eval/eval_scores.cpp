// Benchmark scores; see eval_scores.hpp.
#include "host/gap_eval/eval_scores.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "host/gap/candidates.hpp"
#include "host/gap/link_loss.hpp"
#include "host/gap_eval/truth.hpp"
#include "host/stats/binomial_interval.hpp"
#include "host/stats/median.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::gap {

namespace {

std::optional<double> median(std::vector<double> v) {
    if (v.empty()) return std::nullopt;
    return stats::median(std::move(v));
}

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
    for (const char* effect : kLinkCandidates) s.verdicts.push_back(effect);
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

}  // namespace driftlab::host::gap
