// Whittle fits of the Gaussian candidates on logs from the replicate chain with the library's own effect planted:
// the parameters come back, and the spectral BIC prefers the process that made the log.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/fit/lm_fit.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/spectral_fit.hpp"

namespace driftlab::host::gap {
namespace {

// The eq. 1 residual of a 4000-sample paper-gyro log with `effect` planted (parameters in physical units).
PartPeriodogram residual_of(const GapModel& m, const std::string& effect, const std::vector<double>& params,
                            std::uint64_t seed) {
    GapModel truth = m;
    if (!effect.empty()) truth.effects.push_back(make_candidate_effect(effect, Channel::gyro, params, truth));
    const LogData log = testing::gyro_log(truth, 4000, {}, seed);
    const auto fit = fit::fit_drift(log.t_s, log.counts[0]);
    return part_periodogram(fit.residual, std::vector<bool>(log.size(), true));
}

// BIC of a fit on its own periodogram (observations: the part's differences).
double bic(const SpectralFit& fit, const PartPeriodogram& p) {
    return 2.0 * fit.nll + fit.free_parameters * std::log(p.count);
}

std::string preferred(const GapModel& m, const PartPeriodogram& p) {
    std::string best;
    double best_bic = INFINITY;
    for (const std::string e : {"", "gauss_markov", "flicker", "rate_random_walk"}) {
        const double b = bic(
            fit_spectral(e.empty() ? std::vector<std::string>{} : std::vector<std::string>{e}, Channel::gyro, m, p), p);
        if (b < best_bic) best_bic = b, best = e.empty() ? "none" : e;
    }
    return best;
}

TEST(SpectralFit, GaussMarkovParametersComeBack) {
    const GapModel m = testing::paper_gyro_model(8);
    // sigma 0.05 deg/s (0.28 counts, about the output's white deviation), correlation time 30 s.
    const auto p = residual_of(m, "gauss_markov", {0.05, 30.0}, 21);
    const SpectralFit f = fit_spectral({"gauss_markov"}, Channel::gyro, m, p);
    EXPECT_NEAR(f.params[0] / 0.05, 1.0, 0.25);
    EXPECT_NEAR(std::log(f.params[1] / 30.0), 0.0, std::log(1.5));
    // The white floor: sigma_n^2 + 1/12 per conversion (the additive quantiser reading, sigma_n = 1.05); one fit
    // scatters by 0.03 (seeds 21..40), 4 of that.
    EXPECT_NEAR(f.white, 1.05 * 1.05 + 1.0 / 12.0, 0.12);
    EXPECT_EQ(f.free_parameters, 3);
}

// Over eight logs the floor's mean is known to 0.03 / sqrt(8) = 0.011: 4 of that tells sigma_n^2 + 1/12 (1.186) from a
// floor that forgot the quantiser's twelfth (1.103).
TEST(SpectralFit, TheWhiteFloorIsTheNoiseVariancePlusTheQuantisersTwelfth) {
    const GapModel m = testing::paper_gyro_model(8);
    double sum = 0.0;
    for (std::uint64_t seed = 41; seed < 49; ++seed)
        sum +=
            fit_spectral({"gauss_markov"}, Channel::gyro, m, residual_of(m, "gauss_markov", {0.05, 30.0}, seed)).white;
    EXPECT_NEAR(sum / 8.0, 1.05 * 1.05 + 1.0 / 12.0, 0.045);
}

TEST(SpectralFit, RandomWalkStepComesBack) {
    const GapModel m = testing::paper_gyro_model(8);
    const auto p = residual_of(m, "rate_random_walk", {0.002}, 22);
    const SpectralFit f = fit_spectral({"rate_random_walk"}, Channel::gyro, m, p);
    EXPECT_NEAR(f.params[0] / 0.002, 1.0, 0.3);
}

TEST(SpectralFit, BicPrefersTheProcessThatMadeTheLog) {
    const GapModel m = testing::paper_gyro_model(8);
    EXPECT_EQ(preferred(m, residual_of(m, "", {}, 23)), "none");
    EXPECT_EQ(preferred(m, residual_of(m, "gauss_markov", {0.08, 15.0}, 24)), "gauss_markov");
    EXPECT_EQ(preferred(m, residual_of(m, "rate_random_walk", {0.003}, 25)), "rate_random_walk");
    EXPECT_EQ(preferred(m, residual_of(m, "flicker", {0.03}, 26)), "flicker");
}

TEST(SpectralFit, JointFitStartsEarlierEffectsFromTheirParameters) {
    const GapModel m = testing::paper_gyro_model(8);
    const auto p = residual_of(m, "gauss_markov", {0.05, 30.0}, 27);
    const SpectralFit f = fit_spectral({"gauss_markov", "rate_random_walk"}, Channel::gyro, m, p, {0.05, 30.0});
    ASSERT_EQ(f.params.size(), 3u);
    EXPECT_EQ(f.free_parameters, 4);
    // Nothing of a random walk in the log: the joint fit keeps the Gauss-Markov process and no better likelihood
    // than it alone by more than the extra parameter could buy by chance.
    const SpectralFit alone = fit_spectral({"gauss_markov"}, Channel::gyro, m, p);
    EXPECT_LE(f.nll, alone.nll + 1e-6);
    EXPECT_GT(bic(f, p), bic(alone, p));
}

// A process the model file states is held: it is in the spectrum as the candidate of the same name would put it, and
// beside it only the white floor is fitted. Held at the values that made the log, it describes the log about as
// well as the same process fitted freely (the likelihood-ratio statistic of two parameters), and far better than
// the floor alone.
TEST(SpectralFit, AHeldProcessIsInTheSpectrumAndOnlyTheFloorIsFittedBesideIt) {
    const GapModel m = testing::paper_gyro_model(8);
    GapModel held = m;
    hold_noise(held.held[0], make_candidate_effect("gauss_markov", Channel::gyro, {0.05, 30.0}, m), Channel::gyro, m);
    const OutputSpectrum a = model_spectrum({}, Channel::gyro, {}, held, 1.3);
    const OutputSpectrum b = model_spectrum({"gauss_markov"}, Channel::gyro, {0.05, 30.0}, m, 1.3);
    ASSERT_EQ(a.ar1.size(), 1u);
    ASSERT_EQ(b.ar1.size(), 1u);
    EXPECT_DOUBLE_EQ(a.ar1[0].variance, b.ar1[0].variance);
    EXPECT_DOUBLE_EQ(a.ar1[0].phi, b.ar1[0].phi);
    EXPECT_EQ(a.white, b.white);

    const auto p = residual_of(m, "gauss_markov", {0.05, 30.0}, 21);
    const SpectralFit with_held = fit_spectral({}, Channel::gyro, held, p);
    const SpectralFit free = fit_spectral({"gauss_markov"}, Channel::gyro, m, p);
    const SpectralFit floor_alone = fit_spectral({}, Channel::gyro, m, p);
    EXPECT_EQ(with_held.free_parameters, 1);
    EXPECT_TRUE(with_held.params.empty());
    EXPECT_NEAR(with_held.white, 1.05 * 1.05 + 1.0 / 12.0, 0.12);
    EXPECT_GT(with_held.nll, free.nll - 0.5);
    EXPECT_LT(2.0 * (with_held.nll - free.nll), 10.0);
    EXPECT_GT(2.0 * (floor_alone.nll - with_held.nll), 50.0);
}

}  // namespace
}  // namespace driftlab::host::gap
