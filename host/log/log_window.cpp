// Stretches of a log by time; see log_window.hpp.
#include "host/log/log_window.hpp"

#include <algorithm>
#include <cstdio>
#include <type_traits>

#include "host/util/error.hpp"

namespace driftlab::host {
namespace {

struct RowRun {
    std::size_t first = 0, last = 0;  ///< rows [first, last)
};

// The rows of `runs` (in order, disjoint) in every column. Gap events and cuts are kept where both rows around
// them are in one run, renumbered; new cuts are the caller's.
LogData keep_runs(const LogData& log, const std::vector<RowRun>& runs) {
    const auto cut = [&](const auto& column) {
        std::decay_t<decltype(column)> out;
        for (const RowRun& r : runs)
            for (std::size_t i = r.first; i < std::min(r.last, column.size()); ++i) out.push_back(column[i]);
        return out;
    };
    LogData out;
    out.source_name = log.source_name;
    out.metadata = log.metadata;
    out.recorded = log.recorded;
    out.dropped_cut_line = !runs.empty() && runs.back().last == log.size() ? log.dropped_cut_line : 0;
    out.t_s = cut(log.t_s);
    out.seq = cut(log.seq);
    for (std::size_t c = 0; c < kChannelCount; ++c) out.counts[c] = cut(log.counts[c]);
    for (const auto& [name, column] : log.optional_columns) out.optional_columns[name] = cut(column);
    std::size_t offset = 0;  // rows kept before the run
    for (const RowRun& r : runs) {
        const auto inside = [&](std::size_t before_row) { return before_row > r.first && before_row < r.last; };
        for (const LogGap& g : log.gaps)
            if (inside(g.before_row)) out.gaps.push_back({offset + g.before_row - r.first, g.line, g.text});
        for (const LogCut& c : log.cuts)
            if (inside(c.before_row))
                out.cuts.push_back({offset + c.before_row - r.first, c.from_s, c.to_s, c.rows, c.by});
        offset += r.last - r.first;
    }
    return out;
}

std::string span_of(const LogData& log) {
    char text[120];
    if (log.t_s.empty()) return "the log has no rows";
    std::snprintf(text, sizeof text, "its rows run from %g s to %g s", log.t_s.front(), log.t_s.back());
    return text;
}

// The rows with from_s <= t_s <= to_s.
RowRun rows_of(const LogData& log, double from_s, double to_s) {
    const auto first =
        static_cast<std::size_t>(std::lower_bound(log.t_s.begin(), log.t_s.end(), from_s) - log.t_s.begin());
    const auto last =
        static_cast<std::size_t>(std::upper_bound(log.t_s.begin(), log.t_s.end(), to_s) - log.t_s.begin());
    if (first >= last) {
        char text[200];
        std::snprintf(text, sizeof text, "no row lies between %g s and %g s (%s)", from_s, to_s, span_of(log).c_str());
        throw DataError(log.source_name, 0, text);
    }
    return {first, last};
}

}  // namespace

LogData rows_between(const LogData& log, double from_s, double to_s) {
    return keep_runs(log, {rows_of(log, from_s, to_s)});
}

LogData rows_outside(const LogData& log, std::vector<TimeWindow> windows) {
    // Each window on its own: one that misses (or is reversed) is a mistake even where another overlaps it.
    for (const TimeWindow& w : windows) rows_of(log, w.from_s, w.to_s);
    std::sort(windows.begin(), windows.end(),
              [](const TimeWindow& a, const TimeWindow& b) { return a.from_s < b.from_s; });
    std::vector<RowRun> kept;
    std::vector<LogCut> cuts;
    std::size_t next = 0, offset = 0;  // the first row not yet placed; rows kept so far
    for (std::size_t w = 0; w < windows.size();) {
        TimeWindow merged = windows[w];
        for (++w; w < windows.size() && windows[w].from_s <= merged.to_s; ++w) {
            merged.to_s = std::max(merged.to_s, windows[w].to_s);
            // Whole names: "--exclude" is a part of "--exclude-saturated".
            if ((", " + merged.by + ", ").find(", " + windows[w].by + ", ") == std::string::npos)
                merged.by += ", " + windows[w].by;
        }
        const RowRun out = rows_of(log, merged.from_s, merged.to_s);
        if (out.first > next) kept.push_back({next, out.first});
        offset += out.first - next;
        cuts.push_back({offset, merged.from_s, merged.to_s, out.last - out.first, merged.by});
        next = out.last;
    }
    if (next < log.size()) kept.push_back({next, log.size()});
    if (kept.empty())
        throw DataError(log.source_name, 0, "no row is left once the windows are left out (" + span_of(log) + ")");
    LogData out = keep_runs(log, kept);
    out.cuts.insert(out.cuts.end(), cuts.begin(), cuts.end());
    std::sort(out.cuts.begin(), out.cuts.end(),
              [](const LogCut& a, const LogCut& b) { return a.before_row < b.before_row; });
    return out;
}

std::vector<TimeWindow> saturated_stretches(const LogData& log, const std::array<bool, kChannelCount>& channels,
                                            double margin_s) {
    const auto column = log.optional_columns.find("sat_flags");
    if (column == log.optional_columns.end())
        throw DataError(log.source_name, 0,
                        "no sat_flags column, so no row is known to be saturated (record and hil write it)");
    const auto flagged = [&](std::size_t k) {
        for (std::size_t c = 0; c < kChannelCount; ++c)
            if (channels[c] && flags_saturation(column->second[k], c)) return true;
        return false;
    };
    std::vector<TimeWindow> out;
    const std::size_t rows = std::min(log.size(), column->second.size());
    for (std::size_t k = 0; k < rows;) {
        if (!flagged(k)) {
            ++k;
            continue;
        }
        const std::size_t first = k;
        while (k < rows && flagged(k)) ++k;
        out.push_back({log.t_s[first] - margin_s, log.t_s[k - 1] + margin_s, "--exclude-saturated"});
    }
    return out;
}

}  // namespace driftlab::host
