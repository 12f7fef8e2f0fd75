// Once the held-out part has judged an added effect, its parameters are estimated again on the whole log: the
// interleaved fitting part sees a slow process only inside blocks of 150-300 outputs, the whole log at all its
// frequencies. The estimate is what the result reports first and what --model-out writes; the held-out figures
// stay those of the fitting part's parameters.
#include <cmath>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/diagnose.hpp"
#include "host/view/gap_view.hpp"

namespace driftlab::host::gap {
namespace {

double param(const std::vector<std::pair<std::string, double>>& list, const std::string& key) {
    for (const auto& [k, v] : list)
        if (k == key) return v;
    ADD_FAILURE() << "no parameter " << key;
    return NAN;
}

// A Gauss-Markov process of 0.1 deg/s and 30 s (50 correlation times in the log) on the gyro of 1500-output logs:
// over eight logs the whole-log estimates of its correlation time and size lie nearer the truth (rms of the log
// ratio) than the fitting part's, and within a factor 1.6.
TEST(WholeLogEstimate, AProcessIsEstimatedNearerItsTruthOnTheWholeLogThanOnTheFittingPart) {
    constexpr double kSigma = 0.1, kTau = 30.0;
    const GapModel m = testing::paper_gyro_model(8);
    GapModel truth = m;
    truth.effects.push_back(make_candidate_effect("gauss_markov", Channel::gyro, {kSigma, kTau}, m));
    double part_tau = 0.0, whole_tau = 0.0, part_sigma = 0.0, whole_sigma = 0.0;
    int n = 0;
    for (std::uint64_t seed = 51; seed <= 58; ++seed) {
        const GapResult r =
            diagnose(testing::gyro_log(truth, 1500, {}, seed), sim::paper_model(), testing::small_options());
        ASSERT_EQ(r.accepted.size(), 1u) << "seed " << seed;
        const Explanation& e = r.accepted[0];
        if (e.effect != "gauss_markov") continue;  // read as flicker or a walk now and then (docs/gap.md)
        ASSERT_EQ(e.whole_log_params.size(), e.params.size());
        part_tau += std::pow(std::log(param(e.params, "tau_s") / kTau), 2);
        whole_tau += std::pow(std::log(param(e.whole_log_params, "tau_s") / kTau), 2);
        part_sigma += std::pow(std::log(param(e.params, "sigma_dps") / kSigma), 2);
        whole_sigma += std::pow(std::log(param(e.whole_log_params, "sigma_dps") / kSigma), 2);
        ++n;
        // The whole-log model holds the estimate; the final model (judged on the held-out part) the fitting part's.
        EXPECT_DOUBLE_EQ(file_process_params(r.whole_log_model.effects.back(), Channel::gyro).at(1),
                         param(e.whole_log_params, "tau_s"));
        EXPECT_DOUBLE_EQ(file_process_params(r.final_model.effects.back(), Channel::gyro).at(1),
                         param(e.params, "tau_s"));
        const auto j = view::gap_to_json(r, testing::small_options());
        EXPECT_DOUBLE_EQ(j["explanations"][0]["params_whole_log"]["tau_s"].get<double>(),
                         param(e.whole_log_params, "tau_s"));
    }
    ASSERT_GE(n, 5);
    const auto root = [n](double sum) { return std::sqrt(sum / n); };
    EXPECT_LT(root(whole_tau), root(part_tau));
    EXPECT_LT(root(whole_sigma), root(part_sigma));
    EXPECT_LT(root(whole_tau), std::log(1.6));
    EXPECT_LT(root(whole_sigma), std::log(1.6));
}

}  // namespace
}  // namespace driftlab::host::gap
