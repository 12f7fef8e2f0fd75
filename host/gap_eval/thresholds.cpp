// The benchmark's decision thresholds; see thresholds.hpp.
#include "host/gap_eval/thresholds.hpp"

#include <algorithm>
#include <cmath>

namespace driftlab::host::gap {

bool is_correct(const EvalCase& c, const Decision& d, bool pair_ok) {
    if (c.truth.empty()) return d.verdict == "unexplained" || d.verdict == "none";
    return d.verdict == c.truth || (pair_ok && d.ambiguous_with == c.truth);
}

Decision decide(const EvalCase& c, const Thresholds& th) {
    if (!c.detected) return {"none", ""};
    // Only the link's cells located: its own explanation (judged at the shipped thresholds), as `gap` says it.
    if (c.link_only) return {c.link_verdict.empty() ? "unexplained" : c.link_verdict, ""};
    // The channels read together: a shared reading is the verdict whatever each channel's candidates say.
    if (!c.common_verdict.empty()) return {c.common_verdict, ""};
    std::vector<const Explanation*> passing;
    for (const auto& e : c.tried)
        if (passes(e, th.penalty_per_param, th.min_heldout_shrink)) passing.push_back(&e);
    const Choice choice = choose(passing, th.information_criterion);
    if (!choice.best || !closes_gap(*choice.best, th.step_alpha)) return {"unexplained", ""};
    const bool close = choice.runner_up && close_call(*choice.best, *choice.runner_up, ExplainOptions{}.ambiguity_z,
                                                      th.information_criterion);
    return {choice.best->effect, close ? choice.runner_up->effect : ""};
}

bool significantly_better(std::size_t only_best, std::size_t only_shipped) {
    // Exact one-sided sign test (McNemar's, conditioned on the discordant logs): P(X >= only_best), X ~ Bin(n, 1/2).
    const std::size_t n = only_best + only_shipped;
    if (n == 0) return false;
    double tail = 0.0;
    for (std::size_t k = only_best; k <= n; ++k)
        tail += std::exp(std::lgamma(static_cast<double>(n) + 1.0) - std::lgamma(static_cast<double>(k) + 1.0) -
                         std::lgamma(static_cast<double>(n - k) + 1.0) - static_cast<double>(n) * std::log(2.0));
    return tail < 0.05;
}

Thresholds tune(const std::vector<EvalCase>& cases) {
    std::vector<const EvalCase*> tuning;
    for (const auto& c : cases)
        if (c.tune) tuning.push_back(&c);
    const auto right_of = [&](const Thresholds& th) {
        std::vector<bool> right;
        for (const EvalCase* c : tuning) right.push_back(is_correct(*c, decide(*c, th), false));
        return right;
    };
    const auto score = [&](const Thresholds& th) {
        std::size_t none = 0, fp = 0, right = 0;
        for (const EvalCase* c : tuning) {
            const Decision d = decide(*c, th);
            if (c->truth == "none") {
                ++none;
                fp += d.verdict != "none";
            }
            right += is_correct(*c, d, false);
        }
        const double fpr = none ? static_cast<double>(fp) / static_cast<double>(none) : 0.0;
        return static_cast<double>(right) / static_cast<double>(std::max<std::size_t>(1, tuning.size())) -
               (fpr > 0.05 ? 1.0 : 0.0);
    };
    const Thresholds shipped;
    const double shipped_score = score(shipped);
    Thresholds best = shipped;
    double best_score = shipped_score;
    for (double pen : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0}) {
        for (double shrink : {0.3, 0.4, 0.5, 0.6, 0.7}) {  // a clear margin: at least 30 % of the excess
            // The level-step test's level trades out-of-library logs called unexplained against library effects
            // wrongly called so; among the rest, the conventional 5 % comes first, so it wins ties.
            for (double step_alpha : {0.05, 0.02, 0.1, 0.2}) {
                for (InformationCriterion ic : {InformationCriterion::bic, InformationCriterion::aic}) {
                    const Thresholds th{pen, shrink, step_alpha, ic};
                    const double s = score(th);
                    if (s > best_score) best_score = s, best = th;
                }
            }
        }
    }
    // The shipped thresholds change only when the best does significantly better on the same logs: a one-sided
    // McNemar test of the logs one gets right and the other wrong (or when the shipped ones break the
    // false-positive bound). With a few hundred tuning logs the best of 280 threshold sets beats any fixed one by a
    // log or two by chance alone, and such a choice does not carry over to other seeds.
    if (shipped_score < 0.0 && best_score >= 0.0) return best;
    const std::vector<bool> a = right_of(shipped), b = right_of(best);
    std::size_t only_best = 0, only_shipped = 0;
    for (std::size_t k = 0; k < a.size(); ++k) only_best += b[k] && !a[k], only_shipped += a[k] && !b[k];
    return significantly_better(only_best, only_shipped) ? best : shipped;
}

}  // namespace driftlab::host::gap
