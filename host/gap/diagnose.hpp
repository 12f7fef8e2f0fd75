// `driftlab gap`: the whole diagnosis of one real log. Calibrate the base, simulate-and-refit R replicates,
// compare the battery cell by cell (where), fit candidate effects on the fitting part and judge them on the
// held-out part (which), and score the gap before and after (how far it shrinks). docs/gap.md.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "host/gap/candidates.hpp"
#include "host/gap/common_cause.hpp"
#include "host/gap/comparison.hpp"
#include "host/gap/explain.hpp"
#include "host/gap/gap_model.hpp"
#include "host/gap/level_step.hpp"
#include "host/gap/link_loss.hpp"
#include "host/gap/motion_terms.hpp"
#include "host/gap/statistics.hpp"
#include "host/gap/temperature_coupling.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::gap {

struct GapOptions {
    int replicates = 40;  ///< R of the comparison (>= 10)
    std::uint64_t seed = 1;
    double alpha = 0.05;                         ///< family-wise level of the located cells
    Holdout holdout = BatteryOptions{}.holdout;  ///< how the log is split into fitting and held-out parts
    double fit_fraction = 0.6;  ///< forecast: first part of the log used to fit candidates; the rest is held out
    std::array<bool, kChannelCount> channels{};  ///< all false = every channel whose values vary
    bool explain = true;                         ///< false: locate only
    /// Also search the candidates when no cell is located but the held-out gap score exceeds its bound (a diffuse
    /// gap); an accepted effect becomes the verdict, none accepted leaves it "none". Off by default: the
    /// false-positive rate gap-eval measures is without it.
    bool search_diffuse = false;
    ExplainOptions explain_options;
    int threads = 2;
    /// A log in motion less its known input (diagnose_in_motion()): its raw codes still carry the motion and its
    /// values have left the codes' lattice, so neither the raw codes nor the fraction-of-count cells are used.
    bool less_known_input = false;
    std::function<void(const std::string& stage)> progress;  ///< optional: told each stage as it starts
};

/// The log's own record of lost frames and sample-time irregularity (the simulation uses the log's instants,
/// so these are reported beside the battery, not inside it).
struct TimingCheck {
    std::size_t sequence_jumps = 0;  ///< places where seq advanced by more than 1
    std::uint64_t lost_frames = 0;   ///< frames missing by sequence number
    std::size_t gap_events = 0;      ///< `# gap:` lines
    double dt_jitter_rel = 0.0;      ///< standard deviation of the spacing over the nominal period [-]
};

/// A channel the log recorded whose value never changes: a stuck or unconnected sensor has no noise to compare, so
/// it is not analysed, and the result says so.
struct ConstantChannel {
    Channel channel = Channel::gyro;
    double counts = 0.0;  ///< its one value
};

/// A channel that varies but has no noise the simulator could match: its short-lag spread needs no white noise
/// beyond the converter's, and the calibrated model then simulates it alike for every seed (a generated or
/// heavily filtered signal, or a sensor far quieter than one count). Its replicates give no null: not analysed.
struct NoiseFreeChannel {
    Channel channel = Channel::gyro;
    double spread_counts = 0.0;  ///< the log's short-lag spread of the eq. 1 residual
};

/// An analysed channel whose firmware flagged saturation in some rows (the log's `sat_flags`, bit c: a conversion
/// of the row's window at code 0 or the top code). The replicates clip only where their own noise reaches a rail,
/// so a shock, or a rail the unit sits near, can read as a gap there.
struct SaturatedChannel {
    Channel channel = Channel::gyro;
    std::size_t rows = 0;
    double first_t_s = 0.0;  ///< the first such row's time
    double last_t_s = 0.0;   ///< the last one's
};

/// An analysed channel whose lone values carry enough of its sample-to-sample variance for a warning
/// (stats::lone_values_warning): a corrupt row reads as a gap in the tails, the variance and the Allan deviation at
/// every tau, which no effect closes; an impulse from the sensor is `spikes`' to explain.
struct LoneValueChannel {
    Channel channel = Channel::gyro;
    std::vector<double> t_s;      ///< the lone rows' times
    double variance_share = 0.0;  ///< their part of the sum of squared first differences
    std::string warning;          ///< names the rows and the --exclude windows that leave them out (not the channel)
};

struct GapResult {
    std::array<bool, kChannelCount> channels{};
    std::vector<ConstantChannel> constant_channels;  ///< recorded (and, with GapOptions::channels, selected) ones
    std::vector<NoiseFreeChannel> noise_free;        ///< varying channels left out for want of noise to compare
    std::vector<SaturatedChannel> saturated;         ///< analysed channels with rows flagged saturated
    std::vector<LoneValueChannel> lone_values;       ///< analysed channels with lone values worth a warning
    std::array<bool, kChannelCount> raw_codes{};     ///< analysed channels whose raw codes (raw-mode log) were used
    std::array<bool, kChannelCount> output_codes{};  ///< analysed channels whose outputs are codes (window 1) and used
    std::vector<NotIdentifiable> not_tried;          ///< candidates this log could not have tried, with the reason
    GapModel base;                                   ///< the calibrated base (with the model file's effects: `given`)
    GivenEffects given;    ///< the model file's effects: refitted to this log (final parameters) or kept
    GapModel final_model;  ///< base plus the accepted effects (parameters of the fitting part)
    /// The same with the added shapes' and processes' parameters estimated again on the whole log
    /// (Explanation::whole_log_params): the unit's estimate, which --model-out writes.
    GapModel whole_log_model;
    std::vector<Cell> layout;
    std::vector<double> real_values;
    Comparison before, after;
    std::vector<LocatedCell> located, located_after;
    double gap_before_fit = 1.0, gap_before_heldout = 1.0;
    double gap_after_fit = 1.0, gap_after_heldout = 1.0;
    double gap_bound_before = 1.0, gap_bound_after = 1.0;  ///< level-alpha bounds of the held-out scores (closed gap)
    std::vector<Explanation> tried;                        ///< every candidate fit, accepted first
    std::vector<Explanation> accepted;                     ///< added stepwise, in order
    std::vector<PathChoice> paths;       ///< where a process and a mean shape were each followed as the next effect
    std::vector<LevelStep> level_steps;  ///< per channel with accepted effects: a step the model leaves unexplained?
    /// No cell located, yet the held-out gap score exceeds its bound: many cells a little off, none alone beyond
    /// the family-wise threshold. The verdict stays "none" unless the search (diffuse_searched) accepts an effect.
    bool diffuse_gap = false;
    /// The candidates were tried on the diffuse gap (--search-diffuse, not --locate-only)
    bool diffuse_searched = false;
    std::string verdict;  ///< an effect name, "none" or "unexplained" (also when a level step remains)
    TimingCheck timing;   ///< without the joins of left_out
    /// The log's frame loss against the unit's link; its added candidate is the verdict where the channels have none.
    LinkFindings link;
    /// Causes shared by channels: the channels read together against each alone. A shared reading that wins is the
    /// verdict, in place of the per-channel processes it explains (CommonFindings::replaced).
    CommonFindings common;
    /// The channels against the temperature the log measured (temp_c), taken out before they are read together; the
    /// verdict `temperature` where it couples and no shared reading wins.
    TemperatureCoupling temperature;
    std::vector<LogCut> left_out;  ///< stretches the user left out of the log (LogData::cuts)
    /// `gap --truth`: the known input taken out first and the motion terms judged (diagnose_in_motion()).
    std::optional<MotionFindings> motion;
};

/// Diagnoses `log` against the unit `unit` (front ends and converter). Throws DataError (naming the log) when it
/// is too short (< 200 samples) or no channel varies, UsageError on bad options.
GapResult diagnose(const LogData& log, const sim::SimModel& unit, const GapOptions& options);

/// Whether the diagnosis found a gap anywhere: a located cell of the channels or of the link.
bool gap_located(const GapResult& result);

/// True when some analysed channel of the log had raw codes (a raw-mode log): its simulations need them too.
bool any_raw_codes(const GapResult& result);

/// True when some analysed channel's codes were compared: a raw-mode log's, or outputs that are codes.
bool any_codes(const GapResult& result);

/// Channel `c`'s codes the diagnosis compared (its raw column, or its outputs where they are codes); null for none.
const std::vector<double>* code_column(const LogData& log, const GapResult& result, std::size_t c);

/// True when candidate fit `e` (of result.tried) is one of the effects added to the model, not only one that passed.
bool was_added(const GapResult& result, const Explanation& e);

/// The channels diagnose() analyses for these options.
std::array<bool, kChannelCount> analysed_channels(const LogData& log, const GapOptions& options);

/// The recorded channels these options select that never change (LogData::recorded; not analysed).
std::vector<ConstantChannel> constant_channels(const LogData& log, const GapOptions& options);

/// "gyro with a short-lag spread of 0.0012 counts, ..." ("" for none).
std::string noise_free_text(const std::vector<NoiseFreeChannel>& channels);

/// "accel_x at 512 counts in every row, ..." ("" for none).
std::string constant_channels_text(const std::vector<ConstantChannel>& channels);

}  // namespace driftlab::host::gap
