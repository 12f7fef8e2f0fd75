// One self-contained HTML report of a log (docs/analysis.md §6): Table 1 equivalent, intervals, whiteness
// verdicts, the Allan analysis, and the paper's figures as inline SVG. No external resources.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host/fit/file_analysis.hpp"

namespace driftlab::host::view {

struct ReportOptions {
    bool plots = true;  ///< render figures (needs gnuplot; without it the report says so and goes on)
    /// `report --nav`: what nav --json printed, for a navigation section (null: none), and its file.
    const nlohmann::json* nav = nullptr;
    std::string nav_path;
};

/// The HTML document for `file`.
std::string render_html_report(const fit::FileAnalysis& file, const ReportOptions& options = {});

}  // namespace driftlab::host::view
