// Verdict stability by parametric bootstrap; see verdict_stability.hpp.
#include "host/gap/verdict_stability.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "host/gap/gap_report.hpp"
#include "host/util/format_number.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {

VerdictStability verdict_stability(const GapResult& result, const LogData& log, const sim::SimModel& unit,
                                   const GapOptions& options, std::size_t logs) {
    VerdictStability out;
    for (const Explanation& e : result.accepted)
        for (const auto& [key, value] : e.estimate()) out.params.push_back({e.effect, e.channel, key, value, {}});
    GapOptions quiet = options;
    quiet.progress = nullptr;
    const bool any_raw = any_raw_codes(result);
    for (std::size_t b = 0; b < logs; ++b) {
        if (options.progress)
            options.progress("verdict stability: log " + std::to_string(b + 1) + " of " + std::to_string(logs));
        sim::OutputRequest request;
        request.t_s = &log.t_s;
        request.channels = result.channels;
        std::array<std::vector<double>, kChannelCount> raw;
        if (any_raw) request.raw_codes = &raw;
        // Seeds apart from the replicates' (which follow options.seed upward), one per log.
        const sim::Outputs sim =
            sim::simulate_outputs(result.whole_log_model, request, options.seed ^ (0x9e3779b97f4a7c15ULL * (b + 1)));
        LogData copy = log;
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (!result.channels[c]) continue;
            copy.counts[c] = sim[c];
            if (result.raw_codes[c]) copy.optional_columns[std::string("raw_") + kChannelNames[c]] = raw[c];
        }
        const GapResult r = diagnose(copy, unit, quiet);
        for (ParameterSpread& spread : out.params)
            for (const Explanation& e : r.accepted)
                if (e.effect == spread.effect && e.channel == spread.channel) {
                    ++spread.logs_added;
                    for (const auto& [key, value] : e.estimate())
                        if (key == spread.param) spread.values.push_back(value);
                }
        ++out.verdicts[r.verdict];
        out.same += r.verdict == result.verdict;
        ++out.logs;
    }
    for (ParameterSpread& spread : out.params) std::sort(spread.values.begin(), spread.values.end());
    return out;
}

double ParameterSpread::quantile(double q) const {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double pos = q * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(pos);
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

namespace {

// A value beside the simulated logs' middle 68 %: to the digits half that range warrants (their scatter is the
// estimate's), or as a lone parameter where the range is one value.
std::string within_spread(double value, const ParameterSpread& p) {
    const double half_width = 0.5 * (p.quantile(0.84) - p.quantile(0.16));
    return half_width > 0.0 ? to_precision_of(value, half_width) : parameter_text(value);
}

}  // namespace

std::vector<std::string> spread_lines(const VerdictStability& s) {
    std::vector<std::string> lines;
    for (std::size_t k = 0; k < s.params.size();) {
        // One line per added effect: its parameters are consecutive.
        std::size_t end = k;
        while (end < s.params.size() && s.params[end].effect == s.params[k].effect &&
               s.params[end].channel == s.params[k].channel)
            ++end;
        const ParameterSpread& first = s.params[k];
        std::string line = first.effect + " on " + first.channel;
        if (first.logs_added == 0) {
            line += ": added again in none of the " + std::to_string(s.logs) + " logs (";
            for (std::size_t i = k; i < end; ++i)
                line += (i > k ? ", " : "") + s.params[i].param + " " + parameter_text(s.params[i].estimate);
            lines.push_back(line + ")");
        } else {
            line += " (" + std::to_string(first.logs_added) + " of " + std::to_string(s.logs) + " logs):";
            for (std::size_t i = k; i < end; ++i) {
                const ParameterSpread& p = s.params[i];
                line += (i > k ? "; " : " ") + p.param + " ";
                if (p.values.empty())
                    line += parameter_text(p.estimate) + " -> not found again";
                else
                    line += within_spread(p.estimate, p) + " -> " + within_spread(p.quantile(0.16), p) + " to " +
                            within_spread(p.quantile(0.84), p) + " (median " + within_spread(p.quantile(0.5), p) + ")";
                if (!p.values.empty() && p.values.size() < p.logs_added)
                    line += " in " + std::to_string(p.values.size());
            }
            lines.push_back(line);
        }
        k = end;
    }
    return lines;
}

std::vector<std::string> stability_text(const VerdictStability& s, const std::string& verdict) {
    std::vector<std::string> text{"verdict stability: " + stability_sentence(s, verdict)};
    const std::vector<std::string> spread = spread_lines(s);
    if (!spread.empty()) text.emplace_back(kSpreadHeading);
    for (const std::string& line : spread) text.push_back("  " + line);
    return text;
}

std::string stability_sentence(const VerdictStability& s, const std::string& verdict) {
    char head[200];
    std::snprintf(head, sizeof head,
                  "of %zu logs simulated from the estimated model and diagnosed alike, %zu (%.0f %%) are called %s;",
                  s.logs, s.same, s.logs ? 100.0 * static_cast<double>(s.same) / static_cast<double>(s.logs) : 0.0,
                  verdict.c_str());
    std::string text = head;
    for (const auto& [v, n] : s.verdicts) text += " " + v + " " + std::to_string(n);
    return text;
}

}  // namespace driftlab::host::gap
