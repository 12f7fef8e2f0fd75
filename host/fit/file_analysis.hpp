// Drift analysis of every selected series of one file (canonical log or plain table); the common path of
// `driftlab fit`, `whiteness` and `report`. A series that cannot be analysed keeps its reason, so the
// others are still reported; callers turn the failures into a non-zero exit.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "host/fit/drift_analysis.hpp"

namespace driftlab::host::fit {

struct FileAnalysisRequest {
    std::string path;
    std::vector<std::string> names;  ///< channels / columns; empty = all
    std::string time_column;         ///< plain tables only; "" = t_s, t or time if present
    double sample_period_s = 1.0;    ///< plain tables without a time column
    AnalysisOptions options;
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
    /// Number of series without a result.
    std::size_t failures() const;
    /// "file: series 'x': why; series 'y': why" for the failures.
    std::string failure_summary() const;
};

/// Reads the file (DataError when unreadable or malformed) and analyses each series.
FileAnalysis analyse_file(const FileAnalysisRequest& request);

}  // namespace driftlab::host::fit
