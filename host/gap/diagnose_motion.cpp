// A log in motion; see diagnose_motion.hpp.
#include "host/gap/diagnose_motion.hpp"

#include "host/gap/calibrate.hpp"
#include "host/gap/known_input.hpp"
#include "host/gap/motion_terms.hpp"

namespace driftlab::host::gap {

GapResult diagnose_in_motion(const LogData& log, const TruthFile& truth, const sim::SimModel& unit,
                             const GapOptions& options) {
    if (options.progress) options.progress("taking the known input out");
    const KnownInput known = known_input(log, truth, unit);
    LogData rest = log;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const std::vector<double> m = known.counts(static_cast<Channel>(c));
        for (std::size_t k = 0; k < rest.size(); ++k) rest.counts[c][k] -= m[k];
    }
    const std::array<bool, kChannelCount> channels = analysed_channels(rest, options);
    if (options.progress) options.progress("judging the motion terms");
    const GapModel base = calibrate_base(rest, unit, channels, options.seed);
    MotionFindings motion = fit_motion_terms(rest, known, base, channels, options);
    motion.truth_path = truth.path;

    GapOptions at_rest = options;
    at_rest.less_known_input = true;
    GapResult result = diagnose(without_accepted(rest, known, motion), unit, at_rest);
    if (result.verdict == "none")
        if (const MotionTermFit* strongest = motion.strongest()) result.verdict = strongest->term.effect;
    result.motion = std::move(motion);
    return result;
}

}  // namespace driftlab::host::gap
