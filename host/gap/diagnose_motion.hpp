// `driftlab gap LOG --truth TRUTH`: a log in motion. The known input (known_input.hpp) is taken out first; the
// errors only motion shows are judged on what is left (motion_terms.hpp) and the accepted ones taken out too; the
// rest is diagnosed as a log at rest (diagnose.hpp). docs/gap.md §A log in motion.
#pragma once

#include "host/gap/diagnose.hpp"
#include "host/log/truth_file.hpp"

namespace driftlab::host::gap {

/// Diagnoses `log`, whose rows match `truth` (match_truth_rows()), on `unit`. The verdict is the diagnosis at
/// rest's, or, where that is "none", the accepted motion term of largest |z|.
GapResult diagnose_in_motion(const LogData& log, const TruthFile& truth, const sim::SimModel& unit,
                             const GapOptions& options);

}  // namespace driftlab::host::gap
