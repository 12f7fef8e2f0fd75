// The sentences and numbers in words that the gap result's text and its report (gap_view.hpp) share, so the terminal
// and gap.md never say one thing two ways. Internal to host/view.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "host/gap/diagnose.hpp"
#include "host/gap/verdict_stability.hpp"
#include "host/log/log_data.hpp"
#include "host/util/units.hpp"

namespace driftlab::host::view {

/// The unit plots and step sizes are shown in: the diagnosis's physical one (deg/s; g as mg, so an accelerometer's
/// noise does not read in thousandths), through the model's converter, so a plain table's are in its own unit.
PhysicalUnit display_unit(const gap::GapModel& model, Channel c);

/// An accepted effect's or a mean cell's channel: both are named from kChannelNames, so another name is a bug.
Channel explained_channel(const std::string& name);

/// A level step's size in counts with its value in the channel's unit (deg/s, mg) through `model`'s converter,
/// "1.50 counts (0.264 deg/s)": a plain table's counts are its own LSB, which a reader should not have to convert.
std::string step_size_text(const gap::GapModel& model, Channel c, double counts, int decimals);

/// One sentence on why the verdict is what it is (the rule that decided it).
std::string verdict_reason(const gap::GapResult& result, const gap::GapOptions& options);

/// For a `none` verdict, the analysed channels whose calibrated eq. 1 time constant T is at least half the log's span
/// (e^-2, 14 % of the rise, still to come at its end), in one sentence: eq. 1 still bends across the whole log there,
/// so an effect this slow is taken up by the drift fit and leaves no gap to find. "" for any other verdict, or when
/// every T is shorter.
std::string slow_drift_sentence(const gap::GapResult& result, const LogData& log);

/// The model file's own effects in the base (`gap --model` with effects), one sentence: those refitted to the log
/// with their parameters, and those kept as the file gives them; "" when the model has none.
std::string given_effects_sentence(const gap::GivenEffects& given);

/// An estimated parameter where no spread says how far to trust it: four significant digits (a DNL transition,
/// 507.4 counts, needs them), without an exponent (t2_s=11910, k_g_per_sqrt_s=0.00009776).
std::string parameter_text(double value);

/// "k=v k=v ...", each value as parameter_text() writes it: a candidate's parameters.
std::string parameter_list(const std::vector<std::pair<std::string, double>>& params);

/// An added effect's parameters: "k=v ..." as estimated on the whole log, then "(whole log; fitting part: k=v ...)"
/// with those the held-out part judged; the fitting part's alone where nothing was estimated again. A second time
/// constant beyond the record (ending at `record_end_s`) is said to be one, with the slope the log does tell.
std::string estimate_text(const gap::Explanation& e, double record_end_s);

/// The recorded channels left out because they never change, and why that matters; "" when there are none.
std::string constant_channels_sentence(const gap::GapResult& result);

/// The varying channels left out because the simulator cannot spread them (NoiseFreeChannel); "" when none.
std::string noise_free_sentence(const gap::GapResult& result);

/// The analysed channels with rows flagged saturated, and what that can do to the comparison; "" when none.
std::string saturated_channels_sentence(const gap::GapResult& result);

/// The stretches --exclude left out, with their rows and why the join is fair; "" when none.
std::string left_out_sentence(const gap::GapResult& result);

/// What the shrink of a held-out score is, where one is shown: "shrink = (before - after) / (before - 1)", the share
/// of the score's excess over 1 (a consistent simulator's score) that an effect removes.
inline constexpr const char* kShrinkDefinition = "shrink = (before - after) / (before - 1)";

/// Said of an added effect where Explanation::within_bound_before(): a step on a gap the model could have left by
/// chance, on weaker evidence than the first (docs/gap.md §Stepwise has how often such steps were right).
inline constexpr const char* kWithinBoundNote = "added with the held-out score already within its bound";

/// The candidates tried as the terminal and the report list them: the added effects in step order, then the others
/// by step (within a step as GapResult::tried holds them: those that passed first, then by held-out shrink).
std::vector<const gap::Explanation*> candidates_in_table_order(const gap::GapResult& result);

/// A located cell's ratio (log-scale statistics) or difference and its 95 % interval, to the digits the interval
/// warrants: "ratio 173 [27, 1109]", "diff 0.306 [0.296, 0.317]".
std::string located_value_text(const gap::LocatedCell& cell);

/// located_value_text() as the terminal and the report show it: a `mean` cell's difference, in counts, also in the
/// channel's unit ("diff 0.783 [0.744, 0.823] counts (0.138 deg/s)"); other cells' values have no unit.
std::string located_cell_text(const gap::GapResult& result, const gap::LocatedCell& cell);

/// The result of --stability in words the terminal and the report share: "of N logs ... k (p %) are called V; v1 n1
/// v2 n2".
std::string stability_sentence(const gap::VerdictStability& stability, const std::string& verdict);

/// What introduces spread_lines() wherever they are shown.
inline constexpr const char* kSpreadHeading =
    "estimates on those logs (middle 68 %, where each added the effect again):";

/// The middle 68 % of the simulated logs' estimates (about one standard deviation either side), one line per added
/// effect, each value to the digits half that range warrants (parameter_text() where there is no range):
/// "gauss_markov on gyro (19 of 20 logs): sigma_dps 0.0253 -> 0.0213 to 0.0291 (median 0.0248); ...".
std::vector<std::string> spread_lines(const gap::VerdictStability& stability);

/// The plain-text block the terminal and a model file's comments share: "verdict stability: " and the sentence, then
/// kSpreadHeading and the spread lines indented by two spaces when there are any.
std::vector<std::string> stability_text(const gap::VerdictStability& stability, const std::string& verdict);

}  // namespace driftlab::host::view
