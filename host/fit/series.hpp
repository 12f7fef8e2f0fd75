// One time series to analyse (a log channel or a column of a plain table), with where it came from.
// docs/analysis.md §1.
#pragma once

#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "host/log/log_data.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/log_window.hpp"
#include "host/log/numeric_table.hpp"

namespace driftlab::host::fit {

struct Series {
    std::string name;                ///< channel or column name
    std::string source;              ///< file, for messages
    std::string unit;                ///< "counts" for log channels, else "" (the table's own unit)
    std::optional<Channel> channel;  ///< set for log channels: enables physical units
    std::vector<double> t_s;         ///< [s] strictly increasing (for tables without time: sample index x period)
    double index_period_s = 0.0;     ///< > 0 for a table without a time column: t_s is the row index x this
    std::vector<double> values;
    std::vector<double> raw_values;  ///< raw codes beside a smoothed channel (log column raw_<name>), or empty
};

/// The four channels of a canonical log, in Channel order (only `names` when not empty; unknown names
/// are a UsageError listing the channels).
std::vector<Series> series_from_log(const LogData& log, const std::vector<std::string>& names = {});

/// Columns of a plain table. Time: the column `time_column` if given, else the first of t_s, t, time, then
/// time_s, timestamp, timestamp_s and t/time/timestamp with _ms, _us or _ns, if present, else sample index x
/// `sample_period_s`. A time column whose name ends in _ms, _us or _ns is converted to seconds. Every other column
/// is a series unless `names` selects some. Time must increase strictly (DataError otherwise). The table is taken by
/// value: pass it with std::move where it is not needed after, and its columns move into the series.
std::vector<Series> series_from_table(NumericTable table, const std::vector<std::string>& names = {},
                                      const std::string& time_column = "", double sample_period_s = 1.0);

/// Reads `path` as a canonical log when it starts with the magic line, else as a plain table, and returns
/// its series (see the two functions above; `time_column` and `sample_period_s` apply to tables only).
std::vector<Series> load_series(const std::string& path, const std::vector<std::string>& names = {},
                                const std::string& time_column = "", double sample_period_s = 1.0);

/// How many of the rows at times `t_s` with t_min_s <= t <= t_max_s the window `w` holds (both ends included).
std::size_t rows_in(const std::vector<double>& t_s, const TimeWindow& w, double t_min_s, double t_max_s);

/// The rows of `s` with t_min_s <= t_s <= t_max_s and outside every window of `excluded` (both ends included), with
/// their raw values. Throws DataError naming the series and the window when a window holds none of the rows in range:
/// a mistaken time, not nothing to do.
Series rows_kept(Series s, double t_min_s, double t_max_s, const std::vector<TimeWindow>& excluded = {});

/// The quantum of the values of `s` where it is known: one converter code for a log channel's counts, else 0 (a plain
/// table's column), as lone_values() takes it.
double code_of(const Series& s);

/// Why the `kept` rows of `s` in the time range are too few for `who`, naming where its rows are, so that a range that
/// missed them can be moved; fit and allan word it alike: "series 'gx': 1 sample in the selected time range (the
/// series' rows run from 0 s to 2999 s); the fit needs at least 20".
std::string too_few_kept(const Series& s, std::size_t kept, const std::string& who, std::size_t needed);

/// What --from/--to and --exclude took from rows at times `t_s` (increasing; before any cut), one line each, for a
/// file whose series share their rows: "--from 100 --to 2000 kept 190000 of 360000 rows, t = 100.0086 s to
/// 1999.998 s" (none without those options, or when they keep no row: that is refused elsewhere, naming the rows'
/// span) and "--exclude 1233.5:1234.5 left out 1 row" (per window that takes a row in range). The analyses' tables
/// show only how many rows they used.
std::vector<std::string> selection_notes(const std::vector<double>& t_s, double t_min_s, double t_max_s,
                                         const std::vector<TimeWindow>& excluded);

/// True when the file starts with `# driftlab-log:` (a canonical log rather than a plain table). Throws DataError
/// naming the file when it cannot be opened, so that a missing file is not mistaken for a table missing its options.
/// A raw capture is refused there too, naming `driftlab decode`.
bool is_canonical_log(const std::string& path);

/// A file opened once for both the sniffing and the reading: whether it is a canonical log (is_canonical_log(), with
/// its errors), and the stream back at its start, for parse_log() or parse_numeric_table().
struct OpenedSource {
    std::ifstream in;
    bool canonical_log = false;
};
OpenedSource open_source(const std::string& path);

/// How a command with --drop-cut-line reads `source`: a canonical log with its cut last line dropped when asked (the
/// reader refuses it otherwise). UsageError naming `path` when it is asked for a plain table, which has no such line
/// to drop: it is read whole, a last line without newline being an ordinary table's end.
ReadOptions cut_line_options(const OpenedSource& source, const std::string& path, bool drop_cut_line);

/// load_series() of a source open_source() opened (a command that first asks what the file is reads it once).
std::vector<Series> load_series(OpenedSource source, const std::string& path,
                                const std::vector<std::string>& names = {}, const std::string& time_column = "",
                                double sample_period_s = 1.0);

}  // namespace driftlab::host::fit
