// The gap battery: the statistics computed with the same code on the real log and on every replicate, after
// refitting eq. 1 to each channel exactly as the real log is fitted. Each value is one cell
// (statistic x channel x window/band/octave) on the fitting part or the held-out part of the log.
// docs/gap.md §Statistics.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/fit/drift_model.hpp"

namespace driftlab::host::gap {

/// Which part of the log a cell is computed on.
enum class Segment { fit, heldout };

/// "fit" or "heldout".
const char* segment_name(Segment s);

/// One cell of the battery.
struct Cell {
    std::string statistic;   ///< mean, var, adev, psd, acf, frac, tail, jump, codes, corr, coh
    std::string channel;     ///< channel name, or "a~b" for a pair
    int channel_index = -1;  ///< index of the channel; -1 for a pair
    std::string cell;        ///< window, band or octave, e.g. "tau=16s"
    Segment segment = Segment::fit;
    bool log_scale = false;  ///< the value is a logarithm (compare as a ratio)
    double margin = 0.0;     ///< smallest practically relevant difference of the value
    /// The cell as the terminal and the report show it where that differs from `cell`, the JSON's stable key (whose
    /// three significant digits read t=1.2e+03s, and a one-lag band lag=1s..1s): see shown().
    std::string text{};

    const std::string& shown() const { return text.empty() ? cell : text; }
};

/// How the log is split into the part candidates are fitted on and the part they are judged on.
enum class Holdout {
    forecast,     ///< the first fit_fraction of the log by time, then the rest: tests extrapolation (E1 vs E4)
    interleaved,  ///< interleaved tenths of the log: also judges effects confined to the warm-up or rare in time
};

/// "forecast" or "interleaved"; nothing for any other name.
std::optional<Holdout> holdout_from_name(const std::string& name);

/// One sentence saying which part of the log candidates are fitted on and which they are judged on.
std::string holdout_description(Holdout holdout, double fit_fraction);

/// Options shared by the real log and its replicates.
struct BatteryOptions {
    std::array<bool, kChannelCount> channels{true, true, true, true};
    Holdout holdout = Holdout::interleaved;
    double fit_fraction = 0.6;     ///< forecast: first part of the log (by time) used to fit candidates
    double sample_period_s = 1.0;  ///< for cell labels [s]
    /// Per channel, where the eq. 1 fit starts: empty for a real log (the automatic start); a replicate of a model
    /// starts at the model's drift, which is the same optimum reached in a few iterations instead of a search.
    std::array<std::optional<fit::DriftParameters>, kChannelCount> fit_start{};
    /// Channels whose raw codes (a raw-mode log's raw column) get the `codes` cells: the log and every replicate
    /// then pass them to compute_battery.
    std::array<bool, kChannelCount> raw_codes{};
    /// Channels whose outputs are themselves codes (one conversion each: window 1) and that have no raw column: their
    /// `codes` cells take the outputs as the codes, each against its neighbours' mean (neighbour_level()), on the log
    /// and on every replicate alike. Disjoint from raw_codes.
    std::array<bool, kChannelCount> output_codes{};
    /// The fraction-of-count cells; off for a log in motion less its known input, whose values have left the
    /// lattice of the codes' averages that the cells compare.
    bool frac_cells = true;
};

/// Per sample of `t_s`: true where it belongs to the fitting part. Interleaved: tenths 0, 4, 5, 7, 9 by index
/// (an aperiodic pattern: no alias of a periodic effect), the same tenths as the windowed cells, so each window lies
/// wholly in one part.
std::vector<bool> fitting_mask(const std::vector<double>& t_s, const BatteryOptions& options);

/// The battery's values for one log, plus the base fit and residual of each channel.
struct BatteryResult {
    std::vector<double> values;
    std::array<fit::DriftParameters, kChannelCount> drift{};
    std::array<std::vector<double>, kChannelCount> residual;  ///< [counts]
};

/// Raw codes per channel (null where the log has none).
using RawCodes = std::array<const std::vector<double>*, kChannelCount>;

/// Computes the battery of `y` (per channel, [counts]) at instants `t_s`. When `layout` is not null it is
/// filled with one Cell per value (identical for every log of the same length and options). `raw` must hold the
/// raw codes of every channel in options.raw_codes (std::invalid_argument otherwise).
BatteryResult compute_battery(const std::vector<double>& t_s,
                              const std::array<const std::vector<double>*, kChannelCount>& y,
                              const BatteryOptions& options, std::vector<Cell>* layout = nullptr,
                              const RawCodes& raw = {});

}  // namespace driftlab::host::gap
