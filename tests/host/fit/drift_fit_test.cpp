// Eq. 1 fit on simulated data with known parameters: convergence from the automatic start, recovery of
// Table 1-like parameters, and the coverage of the 95 % intervals (plain on white noise, widened on AR(1)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/intervals.hpp"
#include "host/fit/lm_fit.hpp"
#include "host/util/error.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::fit {
namespace {

struct Truth {
    double c1, c2, t_s;
};

/// Eq. 1 sampled every `period_s` from t = period_s, plus AR(1) noise (phi = 0: white) of marginal sd sigma.
Series simulate(const Truth& truth, std::size_t n, double period_s, double sigma, double phi, std::uint64_t seed) {
    sim::Rng rng(seed, 7);
    Series s;
    s.name = "sim";
    s.source = "simulated";
    const double innovation = sigma * std::sqrt(1.0 - phi * phi);
    double e = sigma * rng.normal();
    for (std::size_t k = 0; k < n; ++k) {
        const double t = period_s * static_cast<double>(k + 1);
        s.t_s.push_back(t);
        s.values.push_back(truth.c1 * (1.0 - std::exp(-t / truth.t_s)) + truth.c2 + e);
        e = phi * e + innovation * rng.normal();
    }
    return s;
}

bool covers(const Estimate& e, double truth) { return e.ci95[0] <= truth && truth <= e.ci95[1]; }

TEST(DriftFit, RisingAndFallingDriftsConvergeFromTheAutomaticStart) {
    const Truth cases[] = {{3.0, 505.0, 411.0},  {-3.0, 505.0, 411.0}, {28.0, 622.0, 1050.0},
                           {-40.0, 470.0, 50.0}, {2.0, 470.0, 3000.0}, {-0.5, 10.0, 20.0}};
    std::uint64_t seed = 1;
    for (const Truth& truth : cases) {
        const Series s = simulate(truth, 4000, 1.0, 0.05 * std::fabs(truth.c1), 0.0, seed++);
        const FitResult fit = fit_drift(s.t_s, s.values);
        EXPECT_EQ(fit.status, FitStatus::converged) << truth.c1 << " " << truth.t_s << ": " << fit.solver_stop;
        EXPECT_NEAR(fit.parameters.c1, truth.c1, 0.05 * std::fabs(truth.c1));
        EXPECT_NEAR(fit.parameters.c2, truth.c2, 0.05 * std::fabs(truth.c1));
        EXPECT_NEAR(fit.parameters.t_s, truth.t_s, 0.1 * truth.t_s);
        // The start alone must already be close: LM refines, it does not search.
        EXPECT_NEAR(fit.start.parameters.t_s, truth.t_s, 0.3 * truth.t_s);
    }
}

TEST(DriftFit, TableOneParametersAreRecoveredWithinTheirIntervals) {
    // Paper Table 1 (A/D counts, T in s), 4000 samples every 1 s, smoothed-output noise of 0.25 count.
    const Truth rows[] = {{3, 505, 411}, {2, 470, 953}, {23, 474, 937}, {28, 622, 1050}};
    std::uint64_t seed = 100;
    for (const Truth& truth : rows) {
        const DriftAnalysis a = analyse_drift(simulate(truth, 4000, 1.0, 0.25, 0.0, seed++));
        EXPECT_EQ(a.fit.status, FitStatus::converged);
        // 4.5 standard errors: a failure here is a bias, not bad luck (p < 1e-5 per parameter).
        EXPECT_NEAR(a.plain.c1.value, truth.c1, 4.5 * a.plain.c1.stderr_);
        EXPECT_NEAR(a.plain.c2.value, truth.c2, 4.5 * a.plain.c2.stderr_);
        EXPECT_NEAR(a.plain.t_s.value, truth.t_s, 4.5 * a.plain.t_s.stderr_);
        EXPECT_NEAR(a.fit.rms, 0.25, 0.02);
    }
}

TEST(DriftFit, PlainIntervalsCoverTheTruthAboutNinetyFivePercentOnWhiteNoise) {
    // Paper gyro row and its smoothed-output noise: 0.045 deg/s = 0.256 count (Fig. 2). 400 runs on the first seeds
    // of their block: a coverage of 95 % gives 380 hits with a binomial sd of 4.36, and the bounds are 4 sd either side
    // (over 2400 runs, seeds 2000..4399, the T interval covered 94.7 %: asymptotic intervals of a nonlinear fit).
    const Truth truth{3.0, 505.0, 411.0};
    const double sigma_counts = 0.045 / (90.0 / 512.0);
    const int runs = 400;
    int c1 = 0, c2 = 0, t = 0, white = 0;
    for (int r = 0; r < runs; ++r) {
        const DriftAnalysis a =
            analyse_drift(simulate(truth, 4000, 1.0, sigma_counts, 0.0, 1000 + static_cast<std::uint64_t>(r)));
        ASSERT_EQ(a.fit.status, FitStatus::converged);
        c1 += covers(a.plain.c1, truth.c1);
        c2 += covers(a.plain.c2, truth.c2);
        t += covers(a.plain.t_s, truth.t_s);
        white += a.whiteness.white;
    }
    std::printf(
        "coverage of the plain 95 %% intervals over %d white-noise runs: C1 %.3f, C2 %.3f, T %.3f; "
        "residual judged white in %.3f\n",
        runs, c1 / double(runs), c2 / double(runs), t / double(runs), white / double(runs));
    for (int hits : {c1, c2, t}) {
        EXPECT_GE(hits, 363) << "coverage below 90.7 %";
        EXPECT_LE(hits, 397) << "coverage above 99.3 %";
    }
}

TEST(DriftFit, WidenedIntervalsRestoreCoverageOnAr1Residuals) {
    // AR(1) with phi = 0.5: integrated autocorrelation time (1 + phi) / (1 - phi) = 3, so plain intervals are
    // sqrt(3) too narrow (coverage about 74 %) and the widened ones should be near 95 %.
    const Truth truth{3.0, 505.0, 411.0};
    const int runs = 200;
    int plain = 0, widened = 0, rejected = 0;
    for (int r = 0; r < runs; ++r) {
        const DriftAnalysis a =
            analyse_drift(simulate(truth, 4000, 1.0, 0.5, 0.5, 5000 + static_cast<std::uint64_t>(r)));
        plain += covers(a.plain.c1, truth.c1);
        widened += covers(a.widened.c1, truth.c1);
        rejected += !a.whiteness.white;
    }
    std::printf("AR(1) phi=0.5, %d runs: C1 coverage plain %.3f, widened %.3f; whiteness rejected in %.3f\n", runs,
                plain / double(runs), widened / double(runs), rejected / double(runs));
    EXPECT_LT(plain, 176);    // clearly below 88 %
    EXPECT_GE(widened, 176);  // 88 %..99 %
    EXPECT_LE(widened, 198);
    EXPECT_GE(rejected, 198);
}

TEST(DriftFit, DataWithoutCurvatureIsFlaggedNotMisreported) {
    // A straight ramp: T is not identifiable, only the slope C1/T.
    Series s;
    s.name = "ramp";
    s.source = "simulated";
    sim::Rng rng(3, 1);
    for (int k = 1; k <= 2000; ++k) {
        s.t_s.push_back(k);
        s.values.push_back(500.0 + 1e-3 * k + 0.1 * rng.normal());
    }
    const DriftAnalysis a = analyse_drift(s);
    ASSERT_FALSE(a.warnings.empty());
    EXPECT_NE(a.warnings.front().find("beyond the record"), std::string::npos) << a.warnings.front();
    EXPECT_NEAR(a.fit.parameters.c1 / a.fit.parameters.t_s, 1e-3, 1e-4);
}

// A fit whose evaluation budget runs out reads as such in fit's table; the JSON keeps the key's spelling. The
// table had printed iteration_limit, a name rather than words.
TEST(DriftFit, AnExhaustedBudgetReadsNotConvergedInWordsAndIterationLimitInJson) {
    const Series s = simulate({-28.0, 622.0, 1050.0}, 3000, 1.0, 0.5, 0.0, 5);
    FitOptions two_evaluations;
    two_evaluations.max_function_evaluations = 2;
    const FitResult f = fit_drift(s.t_s, s.values, two_evaluations);
    ASSERT_EQ(f.status, FitStatus::iteration_limit) << f.solver_stop;
    EXPECT_STREQ(fit_status_words(f.status), "not converged (iteration limit)");
    EXPECT_STREQ(fit_status_name(f.status), "iteration_limit");
    // The other statuses are words already, the same in both.
    for (const FitStatus other : {FitStatus::converged, FitStatus::singular})
        EXPECT_STREQ(fit_status_words(other), fit_status_name(other));
}

// Time stamps far from power-on (Unix time, or a clock started long before) leave the columns of J dependent to
// ~1e-12 and below: the fit is singular with unbounded intervals. Computed from J^T J, the condition number had
// topped out near 1e8: status converged, and standard errors of a few counts (or exactly 0) where the exact ones
// are 1e9 and more.
TEST(DriftFit, TimeStampsFarFromPowerOnGiveASingularFitWithUnboundedIntervals) {
    Series epoch = simulate({3.0, 505.0, 411.0}, 2000, 1.0, 0.25, 0.0, 12);
    for (double& t : epoch.t_s) t += 1.7e9;
    Series alternating;
    for (int k = 0; k < 100; ++k) {
        alternating.t_s.push_back(1e6 + k);
        alternating.values.push_back(k % 2);
    }
    for (const Series* s : {&epoch, &alternating}) {
        const FitResult f = fit_drift(s->t_s, s->values);
        EXPECT_EQ(f.status, FitStatus::singular) << s->t_s.size();
        EXPECT_GT(f.condition_number, 1e9) << s->t_s.size();
        const ParameterIntervals i = parameter_intervals(f, 1.0);
        EXPECT_TRUE(std::isinf(i.c1.stderr_) && std::isinf(i.c2.stderr_) && std::isinf(i.t_s.stderr_)) << s->t_s.size();
    }
}

// A well-posed fit's standard errors against an independent computation in long double: J^T J accumulated and
// inverted by cofactors. They agree, and none is 0 while the residual is not.
TEST(DriftFit, StandardErrorsMatchALongDoubleInverseOfTheNormalMatrix) {
    const Series s = simulate({-28.0, 622.0, 1050.0}, 3000, 1.0, 0.5, 0.0, 5);
    const FitResult f = fit_drift(s.t_s, s.values);
    ASSERT_EQ(f.status, FitStatus::converged);
    long double a[3][3] = {};
    for (double t : s.t_s) {
        const long double e = std::exp(-static_cast<long double>(t) / f.parameters.t_s);
        const long double j[3] = {
            1.0L - e, 1.0L, -f.parameters.c1 * e * t / (static_cast<long double>(f.parameters.t_s) * f.parameters.t_s)};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) a[r][c] += j[r] * j[c];
    }
    const auto cof = [&](int r, int c) {
        const int r0 = (r + 1) % 3, r1 = (r + 2) % 3, c0 = (c + 1) % 3, c1 = (c + 2) % 3;
        return a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0];
    };
    const long double det = a[0][0] * cof(0, 0) + a[0][1] * cof(0, 1) + a[0][2] * cof(0, 2);
    const long double s2 = static_cast<long double>(f.rss()) / (static_cast<long double>(s.t_s.size()) - 3.0L);
    const ParameterIntervals i = parameter_intervals(f, 1.0);
    const double expected[3] = {static_cast<double>(std::sqrt(s2 * cof(0, 0) / det)),
                                static_cast<double>(std::sqrt(s2 * cof(1, 1) / det)),
                                static_cast<double>(std::sqrt(s2 * cof(2, 2) / det))};
    EXPECT_NEAR(i.c1.stderr_ / expected[0], 1.0, 1e-9);
    EXPECT_NEAR(i.c2.stderr_ / expected[1], 1.0, 1e-9);
    EXPECT_NEAR(i.t_s.stderr_ / expected[2], 1.0, 1e-9);
    EXPECT_GT(i.c1.stderr_, 0.0);
    // C1/T by the delta method: g^T (J^T J)^-1 g with g = (1/T, 0, -C1/T^2), the inverse by cofactors (symmetric).
    const long double g[3] = {
        1.0L / f.parameters.t_s, 0.0L,
        -static_cast<long double>(f.parameters.c1) / (static_cast<long double>(f.parameters.t_s) * f.parameters.t_s)};
    long double quad = 0.0L;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) quad += g[r] * cof(r, c) / det * g[c];
    EXPECT_NEAR(i.initial_slope.value, f.parameters.c1 / f.parameters.t_s, 1e-15);
    EXPECT_NEAR(i.initial_slope.stderr_ / static_cast<double>(std::sqrt(s2 * quad)), 1.0, 1e-9);
}

// A warm start (the gap diagnosis's replicates start at the model's parameters) where J is degenerate, C1 at 0 and
// T so far beyond the record that the columns of C1 and T are exactly zero, can move only C2; it is fitted again
// cold, to the cold fit's result. A sound warm start keeps its own, equally good fit.
TEST(DriftFit, AWarmStartWhereTheJacobianIsDegenerateIsFittedAgainCold) {
    const Truth truth{-28.0, 622.0, 1050.0};
    const Series s = simulate(truth, 3000, 1.0, 0.5, 0.0, 9);
    const FitResult cold = fit_drift(s.t_s, s.values);
    ASSERT_EQ(cold.status, FitStatus::converged);
    FitOptions stuck;
    stuck.start = DriftParameters{0.0, 622.0, 1e300};
    const FitResult retried = fit_drift(s.t_s, s.values, stuck);
    EXPECT_EQ(retried.start.parameters.t_s, cold.start.parameters.t_s);  // the automatic start's, not 1e300
    EXPECT_EQ(retried.status, FitStatus::converged);
    EXPECT_DOUBLE_EQ(retried.parameters.c1, cold.parameters.c1);
    EXPECT_DOUBLE_EQ(retried.parameters.t_s, cold.parameters.t_s);
    FitOptions sound;
    sound.start = DriftParameters{truth.c1, truth.c2, truth.t_s};
    const FitResult warm = fit_drift(s.t_s, s.values, sound);
    EXPECT_EQ(warm.status, FitStatus::converged);
    EXPECT_NEAR(warm.parameters.c1 / cold.parameters.c1, 1.0, 1e-6);
    EXPECT_NEAR(warm.parameters.t_s / cold.parameters.t_s, 1.0, 1e-6);
    EXPECT_NEAR(warm.rss() / cold.rss(), 1.0, 1e-12);
}

// A unit already warm when the record starts: T far beyond it, C1 and T hardly separately determined, but the
// drift rate C1/T is, within its interval; its error is solved from R rather than summed from a covariance whose
// large entries cancel along it.
TEST(DriftFit, TheInitialSlopeIsDeterminedWhereC1AndTAreNot) {
    const Truth truth{-200.0, 4.5, 2.0e6};  // 1e-4 per s; the record shows 0.06 of drift under noise of 0.01
    int covered = 0;
    const int runs = 100;
    for (int run = 0; run < runs; ++run) {
        const Series s = simulate(truth, 6000, 0.1, 0.01, 0.0, 500 + static_cast<std::uint64_t>(run));
        const ParameterIntervals i = parameter_intervals(fit_drift(s.t_s, s.values), 1.0);
        // Noise bends some fits to a T of a few records, but every fit holds the slope to a few per cent, C1 at
        // least five times less well (relative errors; 12 times at the least over these runs).
        const double slope_error = i.initial_slope.stderr_ / std::fabs(i.initial_slope.value);
        EXPECT_LT(slope_error, 0.05) << run;
        EXPECT_GT(i.c1.stderr_ / std::fabs(i.c1.value), 5.0 * slope_error) << run;
        covered += covers(i.initial_slope, truth.c1 / truth.t_s);
    }
    // 95 % nominal, less 4 binomial standard deviations of 2.2 runs (98 measured; 100 is within 4 above).
    EXPECT_GE(covered, 86);
}

// Eq. 1 is linear in C1 and C2: data a power of two apart give C1, C2, their errors and the residual that power
// apart, and T alike, at any magnitude. Beyond 2^+-100 the fit runs on data scaled back near 1, so data near
// 1e-180 or 1e200, whose squares under- or overflow, fit as the same data near 1 do (unscaled, at 2^-600 the fit
// had come out singular with C1 = C2 = 0).
TEST(DriftFit, ScalingTheDataByAPowerOfTwoScalesTheFitAtAnyMagnitude) {
    const Series s = simulate({-28.0, 622.0, 1050.0}, 3000, 1.0, 0.5, 0.0, 5);
    const FitResult ref = fit_drift(s.t_s, s.values);
    const ParameterIntervals ref_i = parameter_intervals(ref, 1.0);
    ASSERT_EQ(ref.status, FitStatus::converged);
    std::vector<FitResult> scaled;
    for (int k : {-600, -560, 600, 660}) {
        std::vector<double> y = s.values;
        for (double& v : y) v = std::ldexp(v, k);
        const FitResult f = fit_drift(s.t_s, y);
        ASSERT_EQ(f.status, FitStatus::converged) << k;
        const ParameterIntervals i = parameter_intervals(f, 1.0);
        // Against the unscaled fit: the same optimum, to the solver's tolerance.
        EXPECT_NEAR(std::ldexp(f.parameters.c1, -k) / ref.parameters.c1, 1.0, 1e-9) << k;
        EXPECT_NEAR(std::ldexp(f.parameters.c2, -k) / ref.parameters.c2, 1.0, 1e-9) << k;
        EXPECT_NEAR(f.parameters.t_s / ref.parameters.t_s, 1.0, 1e-9) << k;
        EXPECT_NEAR(std::ldexp(i.c1.stderr_, -k) / ref_i.c1.stderr_, 1.0, 1e-6) << k;
        EXPECT_NEAR(std::ldexp(i.c2.stderr_, -k) / ref_i.c2.stderr_, 1.0, 1e-6) << k;
        EXPECT_NEAR(i.t_s.stderr_ / ref_i.t_s.stderr_, 1.0, 1e-6) << k;
        EXPECT_NEAR(std::ldexp(f.rms, -k) / ref.rms, 1.0, 1e-9) << k;
        EXPECT_NEAR(std::ldexp(f.residual[17], -k), ref.residual[17], 1e-6) << k;
        scaled.push_back(f);
    }
    // Among the scaled fits the same data are fitted near 1: bit for bit a power of two apart.
    EXPECT_EQ(std::ldexp(scaled[0].parameters.c1, 1260), scaled[3].parameters.c1);
    EXPECT_EQ(std::ldexp(scaled[0].parameters.c2, 1260), scaled[3].parameters.c2);
    EXPECT_EQ(scaled[0].parameters.t_s, scaled[3].parameters.t_s);
    EXPECT_TRUE(std::isinf(scaled[3].rss()));  // (2^660)^2 is beyond a double; the scaled sum is kept
    EXPECT_TRUE(std::isfinite(scaled[3].scaled_rss));
}

// Noise with a negative lag-1 correlation (MA(1), theta = -0.8: rho_1 = -0.49) fails the whiteness test, but its
// integrated autocorrelation time is below 1: the warning says there is nothing to widen by, not "too narrow by
// about x1.00; use the widened intervals".
TEST(DriftFit, ANegativelyCorrelatedResidualIsNotWidenedByOne) {
    Series s;
    s.name = "ma1";
    s.source = "simulated";
    sim::Rng rng(21, 3);
    double previous = rng.normal();
    for (int k = 1; k <= 3000; ++k) {
        const double innovation = rng.normal();
        s.t_s.push_back(k);
        s.values.push_back(3.0 * (1.0 - std::exp(-k / 411.0)) + 505.0 + 0.25 * (innovation - 0.8 * previous));
        previous = innovation;
    }
    const DriftAnalysis a = analyse_drift(s);
    ASSERT_FALSE(a.whiteness.white);
    bool said = false;
    for (const std::string& w : a.warnings) {
        said = said || w.find("nothing to widen the intervals by") != std::string::npos;
        EXPECT_EQ(w.find("too narrow by about x1.00"), std::string::npos) << w;
    }
    EXPECT_TRUE(said);
}

std::size_t warnings_saying(const DriftAnalysis& a, const std::string& words) {
    std::size_t n = 0;
    for (const std::string& w : a.warnings) n += w.find(words) != std::string::npos;
    return n;
}

// Ljung-Box divides by the residual's variance: one impulse holding most of it had called an AR(1) residual (phi =
// 0.8, rejected without the impulse) white. The verdict stands, as the test's, but is said to be the impulse's.
TEST(DriftFit, AWhiteVerdictThatOneLoneValueDecidesIsSaidToBeIts) {
    Series s = simulate({3, 505, 411}, 1200, 1.0, 0.2, 0.8, 31);
    const std::string theirs = "the verdict 'white' is that of the lone value above";
    const DriftAnalysis clean = analyse_drift(s);
    ASSERT_FALSE(clean.whiteness.white);
    EXPECT_EQ(warnings_saying(clean, theirs), 0u);
    s.values[600] += 200.0;
    const DriftAnalysis spiked = analyse_drift(s);
    ASSERT_TRUE(spiked.whiteness.white);
    EXPECT_EQ(warnings_saying(spiked, theirs), 1u);
    EXPECT_EQ(warnings_saying(spiked, "leave it out with --exclude to test the other rows"), 1u);
    // Left out, the row no longer decides: the residual is rejected again.
    AnalysisOptions without;
    without.excluded = {{s.t_s[600] - 0.5, s.t_s[600] + 0.5, "--exclude"}};
    EXPECT_FALSE(analyse_drift(s, without).whiteness.white);

    // White noise with an impulse too small to hold most of the variance: warned of as a lone value only.
    Series white = simulate({3, 505, 411}, 1200, 1.0, 0.2, 0.0, 32);
    white.values[600] += 4.0;  // about 10 robust sd from both neighbours; 16 of the 1200 x 0.08 summed squares
    const DriftAnalysis small = analyse_drift(white);
    ASSERT_TRUE(small.whiteness.white);
    EXPECT_EQ(warnings_saying(small, "1 lone value"), 1u);
    EXPECT_EQ(warnings_saying(small, "the verdict 'white'"), 0u);
}

TEST(DriftFit, TooShortOrConstantDataIsADataErrorNamingTheSeries) {
    Series s = simulate({3, 505, 411}, 100, 1.0, 0.1, 0.0, 9);
    AnalysisOptions only_a_few;
    only_a_few.t_max_s = 10.0;
    try {
        analyse_drift(s, only_a_few);
        FAIL() << "10 samples accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("series 'sim': 10 samples in the selected time range"), std::string::npos)
            << e.what();
    }
    AnalysisOptions only_one;
    only_one.t_max_s = s.t_s.front();
    try {
        analyse_drift(s, only_one);
        FAIL() << "1 sample accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("series 'sim': 1 sample in the selected time range ("), std::string::npos)
            << e.what();
    }
    s.values.assign(s.values.size(), 512.0);
    EXPECT_THROW(analyse_drift(s), DataError);
    // Times before power-on (a plain table's clock): refused, not fitted into NaN residuals.
    Series early = simulate({3, 505, 411}, 100, 1.0, 0.1, 0.0, 9);
    for (double& t : early.t_s) t -= 50.0;
    try {
        analyse_drift(early);
        FAIL() << "negative times accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("series 'sim': its time starts at -49 s, but eq. 1 counts from power-on"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace driftlab::host::fit
