// Whiteness (paper eqs. 2–4, Fig. 4): biased autocovariance against the direct sum, the ensemble bounds, the
// autocorrelation time of AR(1), and the verdict's rates on white and AR(1) residuals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "host/stats/autocorrelation.hpp"
#include "host/stats/whiteness.hpp"
#include "host/util/error.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::stats {
namespace {

std::vector<double> ar1(std::size_t n, double phi, std::uint64_t seed) {
    sim::Rng rng(seed, 3);
    std::vector<double> w(n);
    double e = rng.normal() / std::sqrt(1.0 - phi * phi);
    for (auto& v : w) {
        v = e;
        e = phi * e + rng.normal();
    }
    return w;
}

// Every lag asked for, also where fewer lags than samples let the transform be shorter than 2N: a wrap-around into
// the largest lags would show there first.
TEST(Autocorrelation, BiasedAutocovarianceEqualsTheDirectSum) {
    for (std::size_t n : {1u, 2u, 7u, 64u, 1000u, 1459u}) {
        std::vector<double> w = ar1(n, 0.3, n);
        for (auto& v : w) v += 3.0;  // eq. 3 keeps the mean: check it is not removed
        for (std::size_t max_lag : {n + 5, n / 2, n / 8, std::size_t{1}}) {
            const std::vector<double> r = biased_autocovariance(w, max_lag);
            ASSERT_EQ(r.size(), std::min(max_lag, n - 1) + 1);
            for (std::size_t d = 0; d < r.size(); ++d) {
                long double direct = 0.0L;  // O(N^2) reference in extended precision
                for (std::size_t k = 0; k + d < n; ++k) direct += static_cast<long double>(w[k]) * w[k + d];
                EXPECT_NEAR(r[d], static_cast<double>(direct / n), 1e-11 * std::max(1.0, r[0]))
                    << "n " << n << " max_lag " << max_lag << " d " << d;
            }
        }
    }
}

TEST(Autocorrelation, Ar1AutocorrelationTimeMatchesTheory) {
    // tau = (1 + phi) / (1 - phi): 3 for phi = 0.5, 1 for white noise.
    const std::vector<double> w = ar1(200000, 0.5, 11);
    const std::vector<double> r = biased_autocovariance(w, 200);
    std::vector<double> rho(r.size());
    for (std::size_t d = 0; d < r.size(); ++d) rho[d] = r[d] / r[0];
    EXPECT_NEAR(rho[1], 0.5, 0.01);
    EXPECT_NEAR(rho[2], 0.25, 0.01);
    const AutocorrelationTime t = integrated_autocorrelation_time(rho);
    EXPECT_TRUE(t.window_found);
    EXPECT_NEAR(t.tau, 3.0, 0.15);
    const std::vector<double> white = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    EXPECT_EQ(integrated_autocorrelation_time(white).tau, 1.0);
}

TEST(Whiteness, EnsembleUsesTheRequestedSequencesAndTheirBounds) {
    const std::vector<double> w = ar1(4000, 0.0, 5);
    const WhitenessResult r = test_whiteness(w, 1.0);  // paper: M = 10, L = 50 s at 1 s
    EXPECT_EQ(r.sequences_used, 10u);
    EXPECT_EQ(r.sequence_samples, 50u);
    EXPECT_DOUBLE_EQ(r.bound, 2.0 / std::sqrt(500.0));
    EXPECT_DOUBLE_EQ(r.ensemble_rho[0], 1.0);
    EXPECT_TRUE(r.adaptation.empty());
    EXPECT_GE(r.fraction_inside, 0.9);
    EXPECT_EQ(r.ljung_box.lags, 20u);
}

// The test does not depend on the residual's scale: 1e-170 and 1e200 times a residual give the same result (the
// FFT's squares had underflowed to a "constant" residual, or overflowed).
TEST(Whiteness, IsTheSameAtAnyScale) {
    const std::vector<double> w = ar1(2000, 0.3, 11);
    const WhitenessResult base = test_whiteness(w, 1.0, WhitenessOptions{});
    for (const double scale : {1e-170, 1e200}) {
        std::vector<double> scaled = w;
        for (double& v : scaled) v *= scale;
        const WhitenessResult r = test_whiteness(scaled, 1.0, WhitenessOptions{});
        EXPECT_NEAR(r.ljung_box.statistic, base.ljung_box.statistic, 1e-9 * base.ljung_box.statistic) << scale;
        EXPECT_EQ(r.white, base.white) << scale;
        ASSERT_EQ(r.ensemble_rho.size(), base.ensemble_rho.size());
        for (std::size_t d = 0; d < r.ensemble_rho.size(); ++d)
            EXPECT_NEAR(r.ensemble_rho[d], base.ensemble_rho[d], 1e-12) << scale << " lag " << d;
    }
}

// At a 20 s sample period the paper's 50 s sequences are 3 samples (60 s), and the result says so.
TEST(Whiteness, ASequenceLengthMovedToWholeSamplesIsSaid) {
    const std::vector<double> w = ar1(400, 0.0, 8);
    const WhitenessResult coarse = test_whiteness(w, 20.0);
    EXPECT_EQ(coarse.sequence_samples, 3u);
    EXPECT_DOUBLE_EQ(coarse.sequence_length_s, 60.0);
    EXPECT_NE(coarse.adaptation.find("sequences of 60 s (3 samples of 20 s)"), std::string::npos) << coarse.adaptation;
    EXPECT_TRUE(test_whiteness(ar1(4000, 0.0, 8), 1.0).adaptation.empty());  // 10 x 50 samples fit
}

TEST(Whiteness, ShortResidualAdaptsAndSaysSo) {
    const std::vector<double> w = ar1(230, 0.0, 6);
    const WhitenessResult r = test_whiteness(w, 1.0);
    EXPECT_EQ(r.sequences_used, 4u);
    EXPECT_NE(r.adaptation.find("holds 4 sequences"), std::string::npos) << r.adaptation;
    const WhitenessResult one = test_whiteness(ar1(30, 0.0, 7), 1.0);
    EXPECT_EQ(one.sequences_used, 1u);
    EXPECT_EQ(one.sequence_samples, 30u);
    EXPECT_NE(one.adaptation.find("shorter than one sequence"), std::string::npos);
    EXPECT_THROW(test_whiteness(std::vector<double>(5, 1.0), 1.0), UsageError);
}

TEST(Whiteness, AcceptsWhiteNoiseAboutNinetyFivePercentAndRejectsAr1) {
    const int runs = 400;
    int accepted_white = 0, rejected_ar1 = 0;
    double fraction_sum = 0.0;
    for (int s = 0; s < runs; ++s) {
        const WhitenessResult white = test_whiteness(ar1(4000, 0.0, 100 + static_cast<std::uint64_t>(s)), 1.0);
        accepted_white += white.white;
        fraction_sum += white.fraction_inside;
        rejected_ar1 += !test_whiteness(ar1(4000, 0.5, 9000 + static_cast<std::uint64_t>(s)), 1.0).white;
    }
    std::printf(
        "white noise judged white in %.3f of %d runs (mean fraction inside %.3f); AR(1) phi=0.5 rejected in "
        "%.3f\n",
        accepted_white / double(runs), runs, fraction_sum / runs, rejected_ar1 / double(runs));
    // Test size 5 %: acceptance 95 % with binomial sd 1.1 points over 400 runs.
    EXPECT_GE(accepted_white, 368);
    EXPECT_LE(accepted_white, 392);
    EXPECT_EQ(rejected_ar1, runs);
}

}  // namespace
}  // namespace driftlab::host::stats
