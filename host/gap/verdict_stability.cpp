// Verdict stability by parametric bootstrap; see verdict_stability.hpp.
#include "host/gap/verdict_stability.hpp"

#include <algorithm>
#include <limits>

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

}  // namespace driftlab::host::gap
