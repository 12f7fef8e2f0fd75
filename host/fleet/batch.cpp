// A fleet as a batch; see batch.hpp.
#include "host/fleet/batch.hpp"

#include <algorithm>
#include <cmath>

#include "host/fleet/standout_limit.hpp"
#include "host/stats/median.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::fleet {
namespace {

// One channel's parameter over the boards that know it.
struct Column {
    std::vector<std::size_t> board;
    std::vector<double> value, error;
};

Column column_of(const std::vector<BoardEntry>& boards, const std::string& channel, std::size_t p) {
    Column out;
    for (std::size_t b = 0; b < boards.size(); ++b) {
        if (!boards[b].result) continue;
        for (const ChannelResult& c : boards[b].result->channels) {
            if (c.channel != channel || !c.parameters[p].known) continue;
            out.board.push_back(b);
            out.value.push_back(c.parameters[p].value);
            out.error.push_back(c.parameters[p].std_error);
        }
    }
    return out;
}

std::vector<std::string> channels_of(const std::vector<BoardEntry>& boards) {
    std::vector<std::string> out;
    for (const BoardEntry& b : boards)
        if (b.result)
            for (const ChannelResult& c : b.result->channels)
                if (std::find(out.begin(), out.end(), c.channel) == out.end()) out.push_back(c.channel);
    return out;
}

double robust_sigma(const std::vector<double>& y, double centre) {
    std::vector<double> deviation;
    for (double v : y) deviation.push_back(std::fabs(v - centre));
    return kMadToSigma * stats::median(deviation);
}

std::string why(const Distribution& d, double value, double z) {
    const ParameterInfo& info = kParameters[d.parameter];
    std::string text = d.channel + " " + info.name + " = " + significant_plain(value, 4) + " " + info.unit + ", ";
    if (info.log_scale) {
        text += significant_plain(value / d.median, 3) + " x the batch median " + significant_plain(d.median, 4) +
                " (spread x/" + significant_plain(d.factor, 3) + ")";
    } else {
        text += significant_plain(std::fabs(value - d.median), 3) + (value > d.median ? " above" : " below") +
                " the batch median " + significant_plain(d.median, 4) + " (spread " + significant_plain(d.spread, 3) +
                ")";
    }
    return text + ", robust z " + fixed_point(z, 1) + " (limit " + fixed_point(d.limit, 1) + ")";
}

// The boards whose value lies beyond d.limit robust spreads, their own error counted.
void judge(const Column& col, Distribution& d, std::vector<Standout>& out) {
    const bool log_scale = kParameters[d.parameter].log_scale;
    std::vector<double> y, s;
    for (std::size_t i = 0; i < col.value.size(); ++i) {
        y.push_back(log_scale ? std::log(col.value[i]) : col.value[i]);
        const double e = log_scale ? col.error[i] / col.value[i] : col.error[i];
        s.push_back(std::isfinite(e) ? e : 0.0);
    }
    const double centre = stats::median(y);
    const double sigma = robust_sigma(y, centre);
    for (std::size_t i = 0; i < y.size(); ++i) {
        const double scale = std::hypot(sigma, s[i]);
        if (!(scale > 0.0)) continue;
        const double z = (y[i] - centre) / scale;
        d.judged_boards.push_back(col.board[i]);
        d.z.push_back(z);
        if (std::fabs(z) > d.limit)
            out.push_back({col.board[i], d.channel, kParameters[d.parameter].name, z, why(d, col.value[i], z)});
    }
}

Distribution distribution(const Column& col, const std::string& channel, std::size_t p) {
    Distribution d;
    d.channel = channel;
    d.parameter = p;
    d.boards = col.value.size();
    d.median = stats::median(col.value);
    d.spread = robust_sigma(col.value, d.median);
    d.low = *std::min_element(col.value.begin(), col.value.end());
    d.high = *std::max_element(col.value.begin(), col.value.end());
    if (kParameters[p].log_scale) {
        std::vector<double> ln;
        for (double v : col.value) ln.push_back(std::log(v));
        d.factor = std::exp(robust_sigma(ln, stats::median(ln)));
    }
    return d;
}

// The analyses that failed.
void add_failures(const std::vector<BoardEntry>& boards, Batch& batch) {
    for (std::size_t b = 0; b < boards.size(); ++b) {
        if (!boards[b].result) continue;
        const BoardResult& r = *boards[b].result;
        for (const ChannelResult& c : r.channels)
            if (!c.error.empty())
                batch.standouts.push_back({b, c.channel, "analysis", 0.0, c.channel + ": " + c.error});
        if (!r.gap_error.empty())
            batch.standouts.push_back({b, "", "analysis", 0.0, "gap could not diagnose it: " + r.gap_error});
    }
}

}  // namespace

Batch summarise(const std::vector<BoardEntry>& boards) {
    Batch batch;
    batch.boards = boards.size();
    for (std::size_t b = 0; b < boards.size(); ++b) {
        if (!boards[b].result) continue;
        ++batch.analysed;
        if (const std::string& verdict = boards[b].result->gap_verdict; !verdict.empty()) {
            batch.verdicts[verdict].push_back(b);
            ++batch.diagnosed;
        }
    }
    std::vector<Column> columns;
    std::size_t judged = 0;
    for (const std::string& channel : channels_of(boards))
        for (std::size_t p = 0; p < kParameterCount; ++p) {
            Column col = column_of(boards, channel, p);
            if (col.value.empty()) continue;
            batch.distributions.push_back(distribution(col, channel, p));
            if (col.value.size() >= kMinBoardsToJudge) ++judged;
            columns.push_back(std::move(col));
        }
    std::map<std::size_t, double> limits;  // by boards: a fleet's parameters mostly share one count
    for (std::size_t i = 0; i < columns.size(); ++i) {
        Distribution& d = batch.distributions[i];
        if (d.boards < kMinBoardsToJudge) continue;
        auto [at, fresh] = limits.try_emplace(d.boards, 0.0);
        if (fresh) at->second = standout_limit(d.boards, judged);
        d.limit = at->second;
        judge(columns[i], d, batch.standouts);
    }
    add_failures(boards, batch);
    std::stable_sort(batch.standouts.begin(), batch.standouts.end(),
                     [](const Standout& a, const Standout& b) { return a.board < b.board; });
    return batch;
}

}  // namespace driftlab::host::fleet
