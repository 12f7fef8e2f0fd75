// The readable report of `driftlab gap --report DIR`: DIR/gap.md with the verdict and why, the explanation (the
// effects added, their parameters, the shrink at each step, close calls and the experiment that settles them),
// located cells, candidates, and plots (gnuplot through host/report) of the real log's residual against the
// replicate bands of the base simulator and of the simulator with the added effects: its Allan deviation and its
// mean over time. docs/gap.md §Report.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "host/gap/diagnose.hpp"
#include "host/gap/verdict_stability.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::gap {

/// A level step's size in counts with its value in the channel's unit (deg/s, mg) through `model`'s converter,
/// "1.50 counts (0.264 deg/s)": a plain table's counts are its own LSB, which a reader should not have to convert.
std::string step_size_text(const GapModel& model, Channel c, double counts, int decimals);

/// One sentence on why the verdict is what it is (the rule that decided it).
std::string verdict_reason(const GapResult& result, const GapOptions& options);

/// For a `none` verdict, the analysed channels whose calibrated eq. 1 time constant T is at least half the log's span
/// (e^-2, 14 % of the rise, still to come at its end), in one sentence: eq. 1 still bends across the whole log there,
/// so an effect this slow is taken up by the drift fit and leaves no gap to find. "" for any other verdict, or when
/// every T is shorter.
std::string slow_drift_sentence(const GapResult& result, const LogData& log);

/// The model file's own effects in the base (`gap --model` with effects), one sentence: those refitted to the log
/// with their parameters, and those kept as the file gives them; "" when the model has none.
std::string given_effects_sentence(const GivenEffects& given);

/// An estimated parameter where no spread says how far to trust it: four significant digits (a DNL transition,
/// 507.4 counts, needs them), without an exponent (t2_s=11910, k_g_per_sqrt_s=0.00009776).
std::string parameter_text(double value);

/// "k=v k=v ...", each value as parameter_text() writes it: a candidate's parameters.
std::string parameter_list(const std::vector<std::pair<std::string, double>>& params);

/// An added effect's parameters: "k=v ..." as estimated on the whole log, then "(whole log; fitting part: k=v ...)"
/// with those the held-out part judged; the fitting part's alone where nothing was estimated again. A second time
/// constant beyond the record (ending at `record_end_s`) is said to be one, with the slope the log does tell.
std::string estimate_text(const Explanation& e, double record_end_s);

/// The recorded channels left out because they never change, and why that matters; "" when there are none.
std::string constant_channels_sentence(const GapResult& result);

/// The varying channels left out because the simulator cannot spread them (NoiseFreeChannel); "" when none.
std::string noise_free_sentence(const GapResult& result);

/// The analysed channels with rows flagged saturated, and what that can do to the comparison; "" when none.
std::string saturated_channels_sentence(const GapResult& result);

/// The stretches --exclude left out, with their rows and why the join is fair; "" when none.
std::string left_out_sentence(const GapResult& result);

/// What the shrink of a held-out score is, where one is shown: "shrink = (before - after) / (before - 1)", the share
/// of the score's excess over 1 (a consistent simulator's score) that an effect removes.
inline constexpr const char* kShrinkDefinition = "shrink = (before - after) / (before - 1)";

/// Said of an added effect where Explanation::within_bound_before(): a step on a gap the model could have left by
/// chance, on weaker evidence than the first (docs/gap.md §Stepwise has how often such steps were right).
inline constexpr const char* kWithinBoundNote = "added with the held-out score already within its bound";

/// The candidates tried as the terminal and the report list them: the added effects in step order, then the others
/// by step (within a step as GapResult::tried holds them: those that passed first, then by held-out shrink).
std::vector<const Explanation*> candidates_in_table_order(const GapResult& result);

/// A located cell's ratio (log-scale statistics) or difference and its 95 % interval, to the digits the interval
/// warrants: "ratio 173 [27, 1109]", "diff 0.306 [0.296, 0.317]".
std::string located_value_text(const LocatedCell& cell);

/// located_value_text() as the terminal and the report show it: a `mean` cell's difference, in counts, also in the
/// channel's unit ("diff 0.783 [0.744, 0.823] counts (0.138 deg/s)"); other cells' values have no unit.
std::string located_cell_text(const GapResult& result, const LocatedCell& cell);

/// Every file write_gap_report() may write into `dir`, whichever channels it plots: an input among them is refused.
std::vector<std::string> report_files(const std::string& dir);

/// Writes DIR/gap.md, DIR/gap_adev_<channel>.png and DIR/gap_mean_<channel>.png (plots skipped with a note when
/// gnuplot is missing); with `stability` (--stability), the verdict's stability under the verdict.
void write_gap_report(const GapResult& result, const LogData& log, const std::string& dir, const GapOptions& options,
                      const VerdictStability* stability = nullptr);

}  // namespace driftlab::host::gap
