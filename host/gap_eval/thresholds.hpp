// The decision thresholds of the withheld-effect benchmark: what a case's diagnosis decides under a set of them,
// whether that is right, and the set tuned on the tuning seeds (kept at the shipped one unless the best does
// significantly better). docs/gap.md §Evaluation.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host/gap/explain.hpp"
#include "host/gap_eval/evaluate.hpp"

namespace driftlab::host::gap {

/// The decision thresholds gap-eval tunes; the defaults are the ones `driftlab gap` ships (ExplainOptions).
struct Thresholds {
    double penalty_per_param = ExplainOptions{}.penalty_per_param;
    double min_heldout_shrink = ExplainOptions{}.min_heldout_shrink;
    double step_alpha = ExplainOptions{}.step_alpha;
    InformationCriterion information_criterion = ExplainOptions{}.information_criterion;
};

/// What the diagnosis says of a case under some thresholds.
struct Decision {
    std::string verdict;         ///< "none", "unexplained" or the best passing candidate
    std::string ambiguous_with;  ///< a passing runner-up not separated from the best (close_call), else ""
};

/// The decision a case gets under `th` (ambiguity as ExplainOptions::ambiguity_z).
Decision decide(const EvalCase& c, const Thresholds& th);

/// Whether the decision is right: the truth's effect (with `pair_ok`, also a declared close call holding it);
/// "none" for a clean log; for an out-of-library log anything but a library effect.
bool is_correct(const EvalCase& c, const Decision& d, bool pair_ok);

/// Whether the best thresholds beat the shipped ones on the tuning logs: `only_best` logs right under the best only,
/// `only_shipped` under the shipped only; an exact one-sided McNemar (sign) test at 5 %.
bool significantly_better(std::size_t only_best, std::size_t only_shipped);

/// Thresholds (penalty per parameter, minimum held-out shrink, level of the level-step test, information criterion)
/// maximising top-1 accuracy on the tuning cases with a false-positive rate <= 5 %; the shipped ones (Thresholds{})
/// are kept unless the best is significantly better on the same cases (significantly_better()) or they
/// break the false-positive bound.
Thresholds tune(const std::vector<EvalCase>& cases);

}  // namespace driftlab::host::gap
