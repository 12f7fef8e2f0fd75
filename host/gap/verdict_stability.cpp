// Verdict stability by parametric bootstrap; see verdict_stability.hpp.
#include "host/gap/verdict_stability.hpp"

#include <algorithm>
#include <cstdio>

#include "host/gap/sim_chain.hpp"

namespace driftlab::host::gap {

VerdictStability verdict_stability(const GapResult& result, const LogData& log, const sim::SimModel& unit, const GapOptions& options,
                                   std::size_t logs) {
    VerdictStability out;
    GapOptions quiet = options;
    quiet.progress = nullptr;
    const bool any_raw = any_raw_codes(result);
    for (std::size_t b = 0; b < logs; ++b) {
        if (options.progress) options.progress("verdict stability: log " + std::to_string(b + 1) + " of " + std::to_string(logs));
        SimRequest request;
        request.t_s = &log.t_s;
        request.channels = result.channels;
        std::array<std::vector<double>, kChannelCount> raw;
        if (any_raw) request.raw_codes = &raw;
        // Seeds apart from the replicates' (which follow options.seed upward), one per log.
        const SimOutput sim = simulate(result.whole_log_model, request, options.seed ^ (0x9e3779b97f4a7c15ULL * (b + 1)));
        LogData copy = log;
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (!result.channels[c]) continue;
            copy.counts[c] = sim[c];
            if (result.raw_codes[c]) copy.optional_columns[std::string("raw_") + kChannelNames[c]] = raw[c];
        }
        const GapResult r = diagnose(copy, unit, quiet);
        ++out.verdicts[r.verdict];
        out.same += r.verdict == result.verdict;
        ++out.logs;
    }
    return out;
}

std::string stability_sentence(const VerdictStability& s, const std::string& verdict) {
    char head[200];
    std::snprintf(head, sizeof head, "of %zu logs simulated from the estimated model and diagnosed alike, %zu (%.0f %%) are called %s;", s.logs,
                  s.same, s.logs ? 100.0 * static_cast<double>(s.same) / static_cast<double>(s.logs) : 0.0, verdict.c_str());
    std::string text = head;
    for (const auto& [v, n] : s.verdicts) text += " " + v + " " + std::to_string(n);
    return text;
}

}  // namespace driftlab::host::gap
