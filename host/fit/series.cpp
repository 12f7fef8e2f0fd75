// Series from logs and tables; see series.hpp.
#include "host/fit/series.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "host/log/capture_file.hpp"
#include "host/log/log_reader.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/input_file.hpp"

namespace driftlab::host::fit {
namespace {

/// Time units per second named by a time column's suffix (_ms, _us, _ns); 1 for seconds or no suffix.
double units_per_second(const std::string& name) {
    if (name.ends_with("_ms")) return 1e3;
    if (name.ends_with("_us")) return 1e6;
    if (name.ends_with("_ns")) return 1e9;
    return 1.0;
}

/// " (the series' rows run from 0 s to 2999 s)", for a message saying a range or window missed them; empty without
/// rows.
std::string rows_span(const Series& s) {
    if (s.t_s.empty()) return "";
    return " (the series' rows run from " + format_double(s.t_s.front()) + " s to " + format_double(s.t_s.back()) +
           " s)";
}

}  // namespace

std::vector<Series> series_from_log(const LogData& log, const std::vector<std::string>& names) {
    for (const auto& name : names)
        if (!channel_named(name))
            throw UsageError("unknown channel '" + name + "' (channels: " + channel_name_list() + ")");
    std::vector<Series> out;
    for (std::uint8_t c = 0; c < kChannelCount; ++c) {
        const std::string name = kChannelNames[c];
        if (!names.empty() && std::find(names.begin(), names.end(), name) == names.end()) continue;
        Series s;
        s.name = name;
        s.source = log.source_name;
        s.unit = "counts";
        s.channel = static_cast<Channel>(c);
        s.t_s = log.t_s;
        s.values = log.counts[c];
        const auto raw = log.optional_columns.find("raw_" + name);
        if (raw != log.optional_columns.end()) s.raw_values = raw->second;
        out.push_back(std::move(s));
    }
    return out;
}

std::vector<Series> series_from_table(NumericTable table, const std::vector<std::string>& names,
                                      const std::string& time_column, double sample_period_s) {
    if (!(sample_period_s > 0.0)) throw UsageError("sample period must be > 0");
    std::optional<std::size_t> time_index;
    if (!time_column.empty()) {
        time_index = table.column_index(time_column);
    } else {
        // The first three were the only names once: a table holding several keeps the time it had.
        for (const char* candidate :
             {"t_s", "t", "time", "time_s", "timestamp", "timestamp_s", "t_ms", "time_ms", "timestamp_ms", "t_us",
              "time_us", "timestamp_us", "t_ns", "time_ns", "timestamp_ns"}) {
            const auto it = std::find(table.names.begin(), table.names.end(), candidate);
            if (it != table.names.end()) {
                time_index = static_cast<std::size_t>(it - table.names.begin());
                break;
            }
        }
    }
    // The table's columns and time are moved into the series, never copied: ten million rows are 80 MB a column.
    std::vector<double> t_s;
    double index_period_s = 0.0;
    if (time_index) {
        t_s = std::move(table.columns[*time_index]);
        for (std::size_t k = 1; k < t_s.size(); ++k)
            if (!(t_s[k] > t_s[k - 1]))
                throw DataError(table.source_name, table.line_of_row(k),
                                "time column '" + table.names[*time_index] + "' does not increase at row " +
                                    std::to_string(k + 1) + " (" + format_double(t_s[k - 1]) + " then " +
                                    format_double(t_s[k]) + ")");
        // Milliseconds taken as seconds had stretched every time constant a thousandfold.
        const double per_second = units_per_second(table.names[*time_index]);
        for (double& t : t_s) t /= per_second;
        std::vector<std::uint64_t>().swap(table.row_lines);  // no message names a line from here on
    } else {
        std::vector<std::uint64_t>().swap(table.row_lines);
        t_s.resize(table.rows());
        for (std::size_t k = 0; k < t_s.size(); ++k) t_s[k] = static_cast<double>(k) * sample_period_s;
        index_period_s = sample_period_s;
    }
    for (const auto& name : names) {
        table.column_index(name);  // throws with the list of columns
        if (time_index && name == table.names[*time_index])
            throw UsageError("'" + name + "' is the time column of " + table.source_name + ", not a series to analyse");
    }
    std::vector<std::size_t> chosen;
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        if (time_index && c == *time_index) continue;
        if (!names.empty() && std::find(names.begin(), names.end(), table.names[c]) == names.end()) continue;
        chosen.push_back(c);
    }
    std::vector<Series> out;
    for (std::size_t c : chosen) {
        Series s;
        s.name = table.names[c];
        s.source = table.source_name;
        s.t_s = c == chosen.back() ? std::move(t_s) : t_s;
        s.index_period_s = index_period_s;
        s.values = std::move(table.columns[c]);
        out.push_back(std::move(s));
    }
    return out;
}

OpenedSource open_source(const std::string& path) {
    // One open for both heads: the capture's magic is its first line, the log's the first line that is not blank.
    OpenedSource source{open_input_file(path)};
    std::ifstream& in = source.in;
    // Said first: a command would otherwise ask for the options of a plain table it cannot see is empty.
    const bool zero_bytes = in.peek() == std::ifstream::traits_type::eof();
    in >> std::ws;
    if (in.peek() == std::ifstream::traits_type::eof())
        throw DataError(path, 0, zero_bytes ? "empty file" : "empty file (blank lines only)");
    in.clear();
    in.seekg(0);
    // Read as a table, a capture failed on its header's second line ("field 1 'port:': not a number").
    if (starts_as_capture(in))
        throw DataError(path, 1,
                        "a raw capture from `driftlab record`, not a log: rebuild its log with `driftlab decode " +
                            path + " -o LOG.csv` and analyse that");
    in.clear();
    in.seekg(0);
    source.canonical_log = starts_as_log(in);
    in.clear();
    in.seekg(0);
    return source;
}

ReadOptions cut_line_options(const OpenedSource& source, const std::string& path, bool drop_cut_line) {
    if (drop_cut_line && !source.canonical_log)
        throw UsageError("--drop-cut-line is for driftlab logs; " + path +
                         " is a plain table, which is read whole (its last line needs no newline)");
    ReadOptions options;
    options.drop_truncated_tail = drop_cut_line;
    return options;
}

bool is_canonical_log(const std::string& path) { return open_source(path).canonical_log; }

std::vector<Series> load_series(OpenedSource source, const std::string& path, const std::vector<std::string>& names,
                                const std::string& time_column, double sample_period_s) {
    if (source.canonical_log) return series_from_log(parse_log(source.in, path), names);
    return series_from_table(parse_numeric_table(source.in, path), names, time_column, sample_period_s);
}

std::vector<Series> load_series(const std::string& path, const std::vector<std::string>& names,
                                const std::string& time_column, double sample_period_s) {
    return load_series(open_source(path), path, names, time_column, sample_period_s);
}

std::size_t rows_in(const std::vector<double>& t_s, const TimeWindow& w, double t_min_s, double t_max_s) {
    const double from_s = std::max(w.from_s, t_min_s), to_s = std::min(w.to_s, t_max_s);
    return static_cast<std::size_t>(
        std::count_if(t_s.begin(), t_s.end(), [&](double t) { return t >= from_s && t <= to_s; }));
}

std::vector<std::string> selection_notes(const std::vector<double>& t_s, double t_min_s, double t_max_s,
                                         const std::vector<TimeWindow>& excluded) {
    std::vector<std::string> notes;
    const bool from = std::isfinite(t_min_s), to = std::isfinite(t_max_s);
    if (from || to) {
        const auto first = std::lower_bound(t_s.begin(), t_s.end(), t_min_s);
        const auto end = std::upper_bound(first, t_s.end(), t_max_s);
        if (first != end)
            notes.push_back((from ? "--from " + format_double(t_min_s) : std::string()) + (from && to ? " " : "") +
                            (to ? "--to " + format_double(t_max_s) : std::string()) + " kept " +
                            std::to_string(end - first) + " of " + counted(t_s.size(), "row") +
                            ", t = " + format_double(*first) + " s" +
                            (end - first > 1 ? " to " + format_double(*(end - 1)) + " s" : ""));
    }
    for (const TimeWindow& w : excluded)
        if (const std::size_t taken = rows_in(t_s, w, t_min_s, t_max_s); taken > 0)
            notes.push_back(w.by + " " + format_double(w.from_s) + ":" + format_double(w.to_s) + " left out " +
                            counted(taken, "row"));
    return notes;
}

double code_of(const Series& s) { return s.channel ? 1.0 : 0.0; }

std::string too_few_kept(const Series& s, std::size_t kept, const std::string& who, std::size_t needed) {
    return "series '" + s.name + "': " + counted(kept, "sample") + " in the selected time range" + rows_span(s) + "; " +
           who + " needs at least " + std::to_string(needed);
}

Series rows_kept(Series s, double t_min_s, double t_max_s, const std::vector<TimeWindow>& excluded) {
    const auto kept = [&](double t) { return t >= t_min_s && t <= t_max_s; };
    const auto left_out = [&](double t) {
        return std::any_of(excluded.begin(), excluded.end(),
                           [t](const TimeWindow& w) { return t >= w.from_s && t <= w.to_s; });
    };
    // Each window on its own: one that holds no row is a mistaken time, as gap's --exclude says of a log.
    for (const TimeWindow& w : excluded) {
        if (rows_in(s.t_s, w, t_min_s, t_max_s) > 0) continue;
        throw DataError(s.source, 0,
                        "series '" + s.name + "': " + w.by + " " + format_double(w.from_s) + ":" +
                            format_double(w.to_s) + " holds no row" + rows_span(s));
    }
    // In place: a copy had doubled the memory of ten million rows.
    std::size_t w = 0;
    for (std::size_t k = 0; k < s.t_s.size(); ++k) {
        if (!kept(s.t_s[k]) || left_out(s.t_s[k])) continue;
        s.t_s[w] = s.t_s[k];
        s.values[w] = s.values[k];
        if (!s.raw_values.empty()) s.raw_values[w] = s.raw_values[k];
        ++w;
    }
    s.t_s.resize(w);
    s.values.resize(w);
    if (!s.raw_values.empty()) s.raw_values.resize(w);
    return s;
}

}  // namespace driftlab::host::fit
