// The parts of the explanation search that fit a candidate and judge it (candidate_fit.cpp, candidate_judge.cpp),
// shared with the search itself (explain.cpp). Internal to host/gap: explain.hpp is the interface.
// docs/gap.md §Candidates.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "host/gap/comparison.hpp"
#include "host/gap/explain.hpp"
#include "host/gap/level_step.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/spectral_fit.hpp"
#include "host/gap/statistics.hpp"
#include "host/gap/whittle.hpp"

namespace driftlab::host::gap::explain_parts {

// A held-out gap-score excess below this is no gap to shrink (the score is about 1 when the model explains the log).
inline constexpr double kMinHeldoutExcess = 0.2;

// One channel's data, battery, real values and replicate runner.
struct Judge {
    const std::vector<double>& t_s;
    const std::vector<double>& y;  ///< this channel's log values [counts]
    Channel channel;
    BatteryOptions battery;
    std::vector<Cell> layout;
    std::vector<double> real;
    std::vector<double> residual;  ///< eq. 1 residual of the whole log (the battery's)
    double target_spread = 0.0;
    std::vector<bool> fitting;  ///< per sample: in the fitting part
    std::uint64_t seed;
    int threads;
    const std::vector<double>* raw = nullptr;  ///< this channel's codes (raw-mode log, or y where outputs are codes)
    double alpha = 0.0;                        ///< ExplainOptions::alpha

    Comparison evaluate(const GapModel& m, int replicates) const {
        return compare(real, run_replicates(m, t_s, battery, replicates, seed, threads), alpha);
    }
};

// An accepted effect of this channel that is fitted again beside each new candidate.
struct AcceptedProcess {
    std::size_t accepted_index;  ///< into ExplainResult::accepted
    std::size_t slot;            ///< into GapModel::effects
    std::string effect;
    std::vector<double> params;
};

struct Fitted {
    GapModel model;
    std::vector<double> params;
    std::vector<std::pair<std::size_t, std::vector<double>>> refits;  ///< accepted index, new parameters
    std::vector<std::string> names;  ///< the parameters' names when they vary per fit (adc_dnl), else empty
};

CellFilter in_segment(Segment s);
// Diagonal synthetic negative log-likelihood (x2) of the real cells: sum z^2 + 2 ln sd (Wood 2010).
double synthetic_loss(const Comparison& cmp, const std::vector<Cell>& layout, Segment s);
// The judge's channel's white noise matched again to the log's short-lag spread, with `m`'s effects in place.
void match_channel_noise(GapModel& m, const Judge& judge, std::uint64_t seed);
// A mean-shape candidate fitted with eq. 1 by variable projection on the samples of `part`.
Fitted fit_deterministic(const std::string& effect, const GapModel& current, const Judge& judge,
                         const std::vector<bool>& part);
bool tails_differ(const Judge& judge, const Comparison& cmp);
PartPeriodogram residual_periodogram(const GapModel& m, const Judge& judge, const std::vector<bool>& part);
SpectralFit fit_noise(GapModel& m, const Judge& judge, const PartPeriodogram& p,
                      const std::vector<AcceptedProcess>& earlier, const std::string& extra,
                      std::vector<std::pair<std::size_t, std::vector<double>>>* refits);
bool holds(const GivenEffects* given, const std::string& effect, Channel c);
GapModel without_held(const GapModel& m, const GivenEffects& given, const std::string& effect, Channel c);
Fitted fit_spikes(const GapModel& current, const Judge& judge, const ExplainOptions& options);
Fitted fit_code_density(const GapModel& current, const Judge& judge);
Explanation judge_candidate(const std::string& effect, const Fitted& fitted, const Judge& judge,
                            const Comparison& base_cmp, const ExplainOptions& options);
void spectral_evidence(Explanation& ex, const GapModel& current, const Judge& judge,
                       const std::vector<AcceptedProcess>& earlier, double base_nll, int base_parameters);
LevelStep step_test(const GapModel& m, const Judge& judge, const std::vector<AcceptedProcess>& earlier,
                    const std::string& spectral, const std::vector<double>& params, const ExplainOptions& options);

}  // namespace driftlab::host::gap::explain_parts
