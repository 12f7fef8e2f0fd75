// Drift analysis of every selected series of one file (canonical log or plain table); the common path of
// `driftlab fit`, `whiteness` and `report`. A series that cannot be analysed keeps its reason, so the
// others are still reported; callers turn the failures into a non-zero exit.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "host/fit/drift_analysis.hpp"
#include "host/log/log_data.hpp"
#include "host/log/log_metadata.hpp"

namespace driftlab::host::fit {

struct FileAnalysisRequest {
    std::string path;
    std::vector<std::string> names;  ///< channels / columns; empty = all
    /// Plain tables only; "" = t_s, t or time if present. A canonical log is refused any but its own t_s, which is
    /// noted as unused.
    std::string time_column;
    /// Plain tables without a time column; unset = 1 s per row. A file with its own time (a canonical log's t_s,
    /// a table's time column) is refused it when the rows' spacing disagrees, and told it is not used otherwise.
    std::optional<double> sample_period_s;
    AnalysisOptions options;
    /// Canonical logs: a cut last line (no newline) is dropped and noted rather than refused (--drop-cut-line).
    bool drop_cut_line = false;
};

/// A canonical log as a whole, before the time range and the channel choice: what the report's recording table
/// shows (host/view/recording_section.hpp).
struct LogOverview {
    LogMetadata metadata;
    std::size_t rows = 0;
    double first_t_s = 0.0;             ///< [s since power-on]
    double last_t_s = 0.0;              ///< [s since power-on]
    std::size_t gap_events = 0;         ///< `# gap:` lines: the recorder lost the link
    std::vector<std::string> channels;  ///< the channels the source really has, in Channel order
    bool raw_codes = false;             ///< raw_<channel> columns beside the smoothed values
};

struct SeriesOutcome {
    std::string name;
    std::optional<DriftAnalysis> analysis;  ///< set on success
    std::string error;                      ///< why not, when analysis is empty
};

struct FileAnalysis {
    std::string path;
    bool canonical_log = false;
    std::vector<SeriesOutcome> series;
    std::vector<std::string> notes;  ///< about the whole file (an option it does not use), printed once
    std::optional<LogOverview> log;  ///< set for a canonical log
    /// Number of series without a result.
    std::size_t failures() const;
    /// "file: series 'x': why; series 'y': why" for the failures.
    std::string failure_summary() const;
};

/// One note per channel that rows of `log` flag saturated (sat_flags: a conversion of the output's window on a
/// rail): there the rail is read, not the sensor, and a fit or a deviation through those rows says so only here.
std::vector<std::string> saturation_notes(const LogData& log);

/// Reads the file (DataError when unreadable or malformed) and analyses each series. UsageError when a sample period
/// is given for a file with its own time and the rows' spacing disagrees with it, or a time column other than t_s for
/// a canonical log.
FileAnalysis analyse_file(const FileAnalysisRequest& request);

}  // namespace driftlab::host::fit
