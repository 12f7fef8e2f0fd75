// A canonical log in memory: metadata, per-channel columns in A/D counts, optional columns, gap events.
// Spec: docs/log-format.md. Filled by read_log() (log_reader.hpp); written row by row by LogWriter.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/log/log_metadata.hpp"

namespace driftlab::host {

/// The format version this code reads and writes (`# driftlab-log: 1`).
inline constexpr int kLogFormatVersion = 1;

/// Required columns, in the order the writer puts them: t_s, seq, then the channels in Channel order.
inline constexpr std::array<const char*, 2 + kChannelCount> kRequiredLogColumns = {"t_s",     "seq",     "gyro",
                                                                                   "accel_x", "accel_y", "accel_z"};

/// Optional columns a reader keeps (by name) when present; any other column is ignored.
inline constexpr std::array<const char*, 10> kOptionalLogColumns = {
    "raw_gyro", "raw_accel_x", "raw_accel_y", "raw_accel_z", "tick",
    "flags",    "sat_flags",   "n_window",    "dropped",     "temp_c"};

/// What a raw-code column holds where the row's RAW frame was lost.
inline constexpr double kLostRawCode = -1.0;

/// What temp_c holds where the board had no temperature reading (a schedule too fast for one): below absolute zero.
inline constexpr double kNoTemperatureC = -300.0;

/// What a converter of `bits` bits can put in a log (docs/log-format.md §4). Its channel values are the least-squares
/// estimate of codes 0..full: a fitted line (order 1) is read at the window's end, where its weights sum to at most
/// 4/3 above zero and -1/3 below, so the estimate reaches a third of full scale past either end; one count more for
/// Q8 rounding. Its raw codes are integral codes 0..full, or kLostRawCode.
struct ConverterRange {
    int bits = 0;
    double full = 0.0;  ///< the top code, 2^bits - 1
    double estimate_low() const { return -full / 3.0 - 1.0; }
    double estimate_high() const { return full * 4.0 / 3.0 + 1.0; }
    bool holds_estimate(double counts) const { return counts >= estimate_low() && counts <= estimate_high(); }
    bool holds_raw_code(double v) const { return v == kLostRawCode || (v >= 0.0 && v <= full && v == std::floor(v)); }
};

/// The range of a converter of `adc_bits` bits; none for a resolution outside 1..32 bits (no bound is known).
inline std::optional<ConverterRange> converter_range(std::int64_t adc_bits) {
    if (adc_bits < 1 || adc_bits > 32) return std::nullopt;
    return ConverterRange{static_cast<int>(adc_bits), static_cast<double>((std::int64_t{1} << adc_bits) - 1)};
}

/// A raw-code column: `raw_` and a channel name.
inline bool is_raw_code_column(const std::string& name) { return name.rfind("raw_", 0) == 0; }

/// A `# gap: text` line: the recorder lost the link; `before_row` is the index of the first row after it.
struct LogGap {
    std::size_t before_row = 0;
    std::uint64_t line = 0;  ///< line number in the file (1-based)
    std::string text;
};

/// Rows a user left out of the middle of a log (`driftlab gap --exclude`): the rows either side are adjacent in
/// LogData, while the time between them still passes (t_s is unchanged), so the step there is no lost frame.
struct LogCut {
    std::size_t before_row = 0;  ///< the index of the first row after the cut
    double from_s = 0.0;         ///< the window asked for [s since power-on]
    double to_s = 0.0;
    std::size_t rows = 0;  ///< rows it held
    std::string by;        ///< what asked for it (options, ", "-joined where windows merged), for messages
};

/// The whole log, column-major so the analysis can take a channel as one vector.
struct LogData {
    std::string source_name;  ///< file name, for messages
    LogMetadata metadata;
    std::vector<double> t_s;                                ///< [s] since power-on, strictly increasing
    std::vector<std::uint64_t> seq;                         ///< unwrapped frame sequence number
    std::array<std::vector<double>, kChannelCount> counts;  ///< [counts] per Channel
    /// Channels the source really has. A canonical log has all four; a log made from another logger's table
    /// (gap::log_from_table) fills the channels it has no column for at mid-scale, and these are false.
    std::array<bool, kChannelCount> recorded{true, true, true, true};
    std::map<std::string, std::vector<double>> optional_columns;  ///< e.g. "raw_gyro" -> [counts]
    std::vector<LogGap> gaps;
    std::vector<LogCut> cuts;  ///< in row order; none in a log as read
    /// Line number of an unterminated last line the reader dropped (ReadOptions::drop_truncated_tail); 0 = none.
    std::uint64_t dropped_cut_line = 0;

    std::size_t size() const { return t_s.size(); }
    const std::vector<double>& channel(Channel c) const { return counts[channel_index(c)]; }
    bool has_column(const std::string& name) const { return optional_columns.count(name) != 0; }
    /// Frames behind each row, so the step of `seq` between rows when none is lost: a SAMPLE, and a RAW frame too in
    /// a log with raw columns (docs/log-format.md §4).
    std::uint64_t frames_per_row() const {
        for (const auto& column : optional_columns)
            if (is_raw_code_column(column.first)) return 2;
        return 1;
    }
};

/// Whether a `sat_flags` value flags channel `c` (bit c: a conversion of the output's window at code 0 or the top
/// code).
inline bool flags_saturation(double sat_flags, std::size_t c) {
    return sat_flags >= 0.0 && ((static_cast<unsigned>(sat_flags) >> c) & 1u) != 0;
}

}  // namespace driftlab::host
