// Per-file drift analysis; see file_analysis.hpp.
#include "host/fit/file_analysis.hpp"

#include <algorithm>
#include <thread>
#include <utility>
#include <vector>

#include "host/log/compensation.hpp"
#include "host/log/log_reader.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/parallel_for.hpp"

namespace driftlab::host::fit {
namespace {

std::string own_time_of(const FileAnalysis& out) {
    return out.canonical_log ? "a driftlab log, timed by its own t_s column" : "a table timed by its own time column";
}

/// An option that sets a table's time given for a file that carries its own (`own_time`) had been dropped without a
/// word (fit LOG --sample-period 7 fitted the log's 1 s rows as if nothing was said; --time-column seq likewise):
/// one that contradicts the file is refused, saying what it is `for_what`, one that agrees is noted as unused.
void refuse_or_note_unused(const std::string& option, bool agrees, const std::string& own_time,
                           const std::string& for_what, FileAnalysis& out) {
    if (!agrees)
        throw UsageError(option + " contradicts " + out.path + ": it is " + own_time +
                         "; leave the option out (it is for " + for_what + ")");
    out.notes.push_back(option + " is not used: " + out.path + " is " + own_time);
}

/// `series` share the file's time axis.
void check_sample_period(const std::vector<Series>& series, double period_s, FileAnalysis& out) {
    if (series.empty() || series.front().index_period_s > 0.0) return;  // the period times the rows: used
    const std::vector<double>& t_s = series.front().t_s;
    refuse_or_note_unused(
        "--sample-period/--tau0 " + significant(period_s, 6) + " s", stats::period_agrees(t_s, period_s),
        own_time_of(out) + ", whose rows are " + stats::spacing_text(t_s), "tables without a time column", out);
}

/// A table is timed by the column named; a log only ever by its t_s.
void check_time_column(const std::string& column, FileAnalysis& out) {
    if (out.canonical_log)
        refuse_or_note_unused("--time-column " + column, column == "t_s", own_time_of(out), "plain tables", out);
}

LogOverview overview_of(const LogData& log) {
    LogOverview o;
    o.metadata = log.metadata;
    o.rows = log.size();
    o.first_t_s = log.t_s.front();  // a log has rows (read_log refuses one without)
    o.last_t_s = log.t_s.back();
    o.gap_events = log.gaps.size();
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (log.recorded[c]) o.channels.emplace_back(kChannelNames[c]);
    for (const auto& column : log.optional_columns) o.raw_codes |= is_raw_code_column(column.first);
    return o;
}

}  // namespace

std::vector<std::string> saturation_notes(const LogData& log) {
    std::vector<std::string> notes;
    const auto column = log.optional_columns.find("sat_flags");
    if (column == log.optional_columns.end()) return notes;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        std::size_t rows = 0, first = 0, last = 0;
        for (std::size_t k = 0; k < column->second.size(); ++k) {
            if (!flags_saturation(column->second[k], c)) continue;
            if (rows++ == 0) first = k;
            last = k;
        }
        if (rows == 0) continue;
        notes.push_back(std::string(kChannelNames[c]) + " saturated (sat_flags) in " + std::to_string(rows) +
                        (rows == 1 ? " row" : " rows") + " from t = " + significant(log.t_s[first], 6) + " s to " +
                        significant(log.t_s[last], 6) +
                        " s: the rail is read there, not the sensor (--exclude FROM:TO leaves such rows out)");
    }
    return notes;
}

std::size_t FileAnalysis::failures() const {
    std::size_t n = 0;
    for (const auto& s : series) n += !s.analysis;
    return n;
}

std::string FileAnalysis::failure_summary() const {
    // One reason shared by several series (a time range that holds none of them) is said once, naming them all:
    // a log's four channels had repeated the same sentence four times.
    std::vector<std::pair<std::string, std::string>> by_reason;  // (reason, "series 'a', 'b'")
    for (const auto& s : series) {
        if (s.analysis) continue;
        const std::string own = "series '" + s.name + "': ";
        const bool named = s.error.rfind(own, 0) == 0;
        const std::string reason = named ? s.error.substr(own.size()) : s.error;
        const auto same =
            std::find_if(by_reason.begin(), by_reason.end(), [&](const auto& r) { return named && r.first == reason; });
        if (same != by_reason.end())
            same->second += ", '" + s.name + "'";
        else
            by_reason.emplace_back(reason, named ? "series '" + s.name + "'" : "");
    }
    std::string out;
    for (const auto& [reason, names] : by_reason)
        out += (out.empty() ? "" : "; ") + (names.empty() ? reason : names + ": " + reason);
    return out;
}

FileAnalysis analyse_file(const FileAnalysisRequest& request) {
    FileAnalysis out;
    out.path = request.path;
    // Opened once: sniffed, then (after the options are checked against what it is) read from the same stream.
    OpenedSource source = open_source(request.path);
    out.canonical_log = source.canonical_log;
    if (!request.time_column.empty()) check_time_column(request.time_column, out);
    const ReadOptions read = cut_line_options(source, request.path, request.drop_cut_line);
    std::vector<Series> all;
    if (out.canonical_log) {
        // Read here rather than through load_series: the report shows the log as a whole beside the analysis.
        const LogData log = parse_log(source.in, request.path, read);
        if (const std::string note = dropped_cut_line_note(log); !note.empty()) out.notes.push_back(note);
        out.log = overview_of(log);
        for (std::string& note : saturation_notes(log)) out.notes.push_back(std::move(note));
        if (const std::optional<std::string> compensated = compensated_on_board(log.metadata))
            out.notes.push_back(*compensated + ": what is fitted here is the drift the compensation left");
        all = series_from_log(log, request.names);
    } else {
        all = series_from_table(parse_numeric_table(source.in, request.path), request.names, request.time_column,
                                request.sample_period_s.value_or(1.0));
    }
    if (request.sample_period_s) check_sample_period(all, *request.sample_period_s, out);
    // The series are independent: one to a core (a million rows of four channels took 1.4 s one after another).
    out.series.resize(all.size());
    const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    parallel_for(all.size(), threads, [&](std::size_t i) {
        SeriesOutcome& o = out.series[i];
        o.name = all[i].name;
        try {
            o.analysis = analyse_drift(all[i], request.options);
        } catch (const DataError& e) {
            // The caller reports the file once; keep the series' own message.
            o.error = e.what();
            const std::string prefix = request.path + ": ";
            if (o.error.rfind(prefix, 0) == 0) o.error.erase(0, prefix.size());
        }
    });
    // Said once for the file: its series share their rows.
    if (!all.empty())
        for (std::string& note : selection_notes(all.front().t_s, request.options.t_min_s, request.options.t_max_s,
                                                 request.options.excluded))
            out.notes.push_back(std::move(note));
    return out;
}

}  // namespace driftlab::host::fit
