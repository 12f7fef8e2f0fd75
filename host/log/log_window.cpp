// A stretch of a log by time; see log_window.hpp.
#include "host/log/log_window.hpp"

#include <algorithm>
#include <cstdio>
#include <type_traits>

#include "host/util/error.hpp"

namespace driftlab::host {

LogData rows_between(const LogData& log, double from_s, double to_s) {
    const auto first = static_cast<std::size_t>(std::lower_bound(log.t_s.begin(), log.t_s.end(), from_s) - log.t_s.begin());
    const auto last = static_cast<std::size_t>(std::upper_bound(log.t_s.begin(), log.t_s.end(), to_s) - log.t_s.begin());
    if (first >= last) {
        char text[200];
        if (log.t_s.empty())
            std::snprintf(text, sizeof text, "no row lies between %g s and %g s (the log has no rows)", from_s, to_s);
        else
            std::snprintf(text, sizeof text, "no row lies between %g s and %g s (its rows run from %g s to %g s)", from_s, to_s,
                          log.t_s.front(), log.t_s.back());
        throw DataError(log.source_name, 0, text);
    }
    const auto cut = [&](const auto& column) {
        using Column = std::decay_t<decltype(column)>;
        const std::size_t end = std::min(last, column.size());
        return first < end ? Column(column.begin() + static_cast<std::ptrdiff_t>(first), column.begin() + static_cast<std::ptrdiff_t>(end))
                           : Column{};
    };
    LogData out;
    out.source_name = log.source_name;
    out.metadata = log.metadata;
    out.recorded = log.recorded;
    out.truncated_tail_dropped = log.truncated_tail_dropped && last == log.size();
    out.t_s = cut(log.t_s);
    out.seq = cut(log.seq);
    for (std::size_t c = 0; c < kChannelCount; ++c) out.counts[c] = cut(log.counts[c]);
    for (const auto& [name, column] : log.optional_columns) out.optional_columns[name] = cut(column);
    for (const LogGap& g : log.gaps)
        if (g.before_row > first && g.before_row < last) out.gaps.push_back({g.before_row - first, g.line, g.text});
    return out;
}

}  // namespace driftlab::host
