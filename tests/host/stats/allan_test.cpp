// Allan-family deviations: closed-form shapes on simulated data, invariances, and gap handling.
#include <gtest/gtest.h>

#include "white_noise.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "host/stats/allan_analysis.hpp"
#include "host/stats/deviation.hpp"
#include "host/stats/edf.hpp"
#include "host/stats/phase_record.hpp"

namespace driftlab::host::stats {
namespace {

using testing::white;

double one(const PhaseRecord& r, Deviation d, std::int64_t m) {
    const std::int64_t ms[] = {m};
    const DeviationCurve c = compute_deviation(r, d, ms);
    return c.dev.empty() ? std::nan("") : c.dev[0];
}

TEST(AllanShapes, WhiteRateNoiseFallsAsSigmaOverRootM) {
    const double sigma = 0.37;
    const double tau0 = 0.01;
    const auto y = white(200000, sigma, 11);
    const PhaseRecord r = PhaseRecord::from_rate(y, tau0);
    const std::vector<std::int64_t> ms = {1, 2, 4, 8, 16, 32, 64, 128, 256};
    for (Deviation d : {Deviation::adev, Deviation::oadev, Deviation::mdev, Deviation::hdev, Deviation::ohdev}) {
        const AnalysedCurve a = analyse_deviation(r, d, ms, 0.9999);
        ASSERT_EQ(a.curve.m.size(), ms.size());
        for (std::size_t i = 0; i < ms.size(); ++i) {
            double expected = sigma / std::sqrt(static_cast<double>(ms[i]));
            if (d == Deviation::mdev) {
                // White FM, sampled: the MVAR term weights the rate samples by a triangle difference whose
                // squares sum to m^3 + m, so MVAR = sigma^2 (m^2 + 1) / (2 m^3) (-> AVAR / 2 for large m).
                const double m = static_cast<double>(ms[i]);
                expected *= std::sqrt((m * m + 1.0) / (2.0 * m * m));
            }
            EXPECT_GT(expected, a.ci_low[i]) << deviation_name(d) << " m=" << ms[i];
            EXPECT_LT(expected, a.ci_high[i]) << deviation_name(d) << " m=" << ms[i];
            EXPECT_NEAR(a.curve.tau_s[i], tau0 * static_cast<double>(ms[i]), 1e-12);
        }
    }
}

TEST(AllanShapes, WhiteRateNoiseIsIdentifiedAsWhiteFm) {
    const auto y = white(100000, 1.0, 12);
    const PhaseRecord r = PhaseRecord::from_rate(y, 1.0);
    const std::vector<std::int64_t> ms = {1, 8, 64};
    const AnalysedCurve a = analyse_deviation(r, Deviation::oadev, ms);
    for (std::size_t i = 0; i < ms.size(); ++i) {
        EXPECT_EQ(a.alpha[i], 0);
        EXPECT_TRUE(a.alpha_identified[i]);
    }
}

TEST(AllanShapes, GaussMarkovPeaksAt0618SigmaNear189CorrelationTimes) {
    const double sigma_b = 2.0;
    const double tc = 50.0;  // samples
    const double phi = std::exp(-1.0 / tc);
    auto w = white(2000000, sigma_b * std::sqrt(1.0 - phi * phi), 13);
    std::vector<double> y(w.size());
    double x = 0.0;
    for (std::size_t k = 0; k < w.size(); ++k) y[k] = x = phi * x + w[k];
    const PhaseRecord r = PhaseRecord::from_rate(y, 1.0);
    double peak = 0.0;
    std::int64_t at = 0;
    for (std::int64_t m = 40; m <= 160; m += 2) {
        const double d = one(r, Deviation::oadev, m);
        if (d > peak) {
            peak = d;
            at = m;
        }
    }
    EXPECT_NEAR(peak / (0.618 * sigma_b), 1.0, 0.02);
    EXPECT_NEAR(static_cast<double>(at) / (1.89 * tc), 1.0, 0.2);  // the peak is flat; its place is loose
}

TEST(AllanShapes, SinusoidPeaksAt0725AmplitudeAt0371OverFrequency) {
    const double amplitude = 3.0;
    const double period = 1000.0;  // samples
    std::vector<double> y(200000);
    for (std::size_t k = 0; k < y.size(); ++k) {
        y[k] = amplitude * std::sin(2.0 * std::numbers::pi * (static_cast<double>(k) + 0.5) / period);
    }
    const PhaseRecord r = PhaseRecord::from_rate(y, 1.0);
    double peak = 0.0;
    std::int64_t at = 0;
    for (std::int64_t m = 300; m <= 450; ++m) {
        const double d = one(r, Deviation::oadev, m);
        // Closed form: AVAR = A^2 sin^4(pi f0 tau) / (pi f0 tau)^2.
        const double u = std::numbers::pi * static_cast<double>(m) / period;
        EXPECT_NEAR(d / (amplitude * std::pow(std::sin(u), 2) / u), 1.0, 0.01) << m;
        if (d > peak) {
            peak = d;
            at = m;
        }
    }
    EXPECT_NEAR(peak / (0.725 * amplitude), 1.0, 0.005);
    EXPECT_NEAR(static_cast<double>(at), 371.0, 3.0);
}

TEST(AllanInvariance, LargeStaticOffsetChangesNothing) {
    // A 10-bit ADC at rest sits near code 512: the offset must not eat the mantissa.
    const auto y = white(100000, 0.3, 14);
    std::vector<double> shifted(y);
    for (double& v : shifted) v += 512.0;
    const PhaseRecord a = PhaseRecord::from_rate(y, 1.0);
    const PhaseRecord b = PhaseRecord::from_rate(shifted, 1.0);
    for (Deviation d : {Deviation::oadev, Deviation::mdev, Deviation::ohdev}) {
        for (std::int64_t m : {1, 10, 1000}) EXPECT_NEAR(one(b, d, m) / one(a, d, m), 1.0, 1e-10);
    }
}

TEST(AllanInvariance, PhaseInputOfTheIntegratedRateGivesTheSameCurve) {
    const double tau0 = 0.5;
    const auto y = white(5000, 1.0, 15);
    std::vector<double> x(y.size() + 1, 0.0);
    for (std::size_t k = 0; k < y.size(); ++k) x[k + 1] = x[k] + y[k] * tau0;
    const PhaseRecord from_rate = PhaseRecord::from_rate(y, tau0);
    const PhaseRecord from_phase = PhaseRecord::from_phase(x, tau0);
    for (Deviation d : {Deviation::adev, Deviation::oadev, Deviation::mdev, Deviation::hdev, Deviation::ohdev}) {
        for (std::int64_t m : {1, 3, 50}) EXPECT_NEAR(one(from_phase, d, m) / one(from_rate, d, m), 1.0, 1e-9);
    }
}

TEST(AllanInvariance, ScalingByAPowerOfTwoScalesEveryDeviationExactlyAtAnyMagnitude) {
    // Squared phase differences of 1e-169 rates (or of any rate at a tau0 of 1e-301) underflow a double, and of
    // 1e199 rates overflow it; a power of two changes no bit of a deviation, so the result must follow it exactly.
    const auto y = white(3000, 1.0, 16);
    const double tau0 = 0.25;
    const PhaseRecord base = PhaseRecord::from_rate(y, tau0);
    for (int k : {-560, 660}) {
        std::vector<double> scaled(y);
        for (double& v : scaled) v = std::ldexp(v, k);
        const PhaseRecord r = PhaseRecord::from_rate(scaled, tau0);
        for (Deviation d : {Deviation::adev, Deviation::oadev, Deviation::mdev, Deviation::hdev, Deviation::ohdev}) {
            for (std::int64_t m : {1, 7, 300}) {
                EXPECT_DOUBLE_EQ(one(r, d, m), std::ldexp(one(base, d, m), k)) << deviation_name(d) << " 2^" << k;
            }
        }
    }
    // Rate input: the deviation of the rate does not depend on tau0.
    const PhaseRecord tiny_tau0 = PhaseRecord::from_rate(y, std::ldexp(1.0, -1000));
    for (std::int64_t m : {1, 7, 300})
        EXPECT_DOUBLE_EQ(one(tiny_tau0, Deviation::oadev, m), one(base, Deviation::oadev, m));
    // Phase input of 1e199: the differences are formed before anything is squared.
    std::vector<double> x(y.size() + 1, 0.0);
    for (std::size_t i = 0; i < y.size(); ++i) x[i + 1] = x[i] + std::ldexp(y[i] * tau0, 660);
    const PhaseRecord from_phase = PhaseRecord::from_phase(x, tau0);
    for (std::int64_t m : {1, 7, 300}) {
        EXPECT_NEAR(one(from_phase, Deviation::oadev, m) / std::ldexp(one(base, Deviation::oadev, m), 660), 1.0, 1e-9);
    }
}

// ---- gaps ------------------------------------------------------------------------------------------------

// Pooled variance of two independent pieces, as the gap rule specifies: sum of squared terms over all terms.
double pooled(const PhaseRecord& a, const PhaseRecord& b, Deviation d, std::int64_t m, std::int64_t* n_total) {
    const std::int64_t ms[] = {m};
    const DeviationCurve ca = compute_deviation(a, d, ms);
    const DeviationCurve cb = compute_deviation(b, d, ms);
    const double n1 = static_cast<double>(ca.n.at(0));
    const double n2 = static_cast<double>(cb.n.at(0));
    *n_total = ca.n[0] + cb.n[0];
    return std::sqrt((n1 * ca.dev[0] * ca.dev[0] + n2 * cb.dev[0] * cb.dev[0]) / (n1 + n2));
}

TEST(AllanGaps, NanRateSampleSkipsTheTermsThatTouchItAndPoolsTheHalves) {
    const std::size_t n = 4001;
    const std::size_t gap = 1700;
    auto y = white(n, 1.0, 16);
    std::vector<double> with_gap(y);
    with_gap[gap] = std::nan("");
    const PhaseRecord r = PhaseRecord::from_rate(with_gap, 1.0);
    ASSERT_TRUE(r.has_gaps());
    ASSERT_EQ(r.gap_samples(), 1u);
    const PhaseRecord first = PhaseRecord::from_rate(std::span<const double>(y.data(), gap), 1.0);
    const PhaseRecord second = PhaseRecord::from_rate(std::span<const double>(y.data() + gap + 1, n - gap - 1), 1.0);
    for (std::int64_t m : {1, 5, 64}) {
        const std::int64_t ms[] = {m};
        // OADEV on rate data: each term spans 2m rate samples, so 2m terms touch the gap.
        const DeviationCurve c = compute_deviation(r, Deviation::oadev, ms);
        EXPECT_EQ(c.n[0], static_cast<std::int64_t>(n + 1) - 2 * m - 2 * m);
        EXPECT_EQ(c.n_skipped[0], 2 * m);
        for (Deviation d : {Deviation::oadev, Deviation::mdev, Deviation::ohdev, Deviation::adev, Deviation::hdev}) {
            const DeviationCurve cd = compute_deviation(r, d, ms);
            std::int64_t n_expected = 0;
            const double expected = pooled(first, second, d, m, &n_expected);
            EXPECT_EQ(cd.n[0], n_expected) << deviation_name(d) << " m=" << m;
            EXPECT_NEAR(cd.dev[0] / expected, 1.0, 1e-12) << deviation_name(d) << " m=" << m;
        }
    }
}

TEST(AllanGaps, MaskedSampleActsLikeNan) {
    auto y = white(3000, 1.0, 17);
    std::vector<std::uint8_t> mask(y.size(), 0);
    mask[100] = 1;
    mask[2000] = 1;
    std::vector<double> nans(y);
    nans[100] = nans[2000] = std::nan("");
    const PhaseRecord a = PhaseRecord::from_rate(y, 1.0, mask);
    const PhaseRecord b = PhaseRecord::from_rate(nans, 1.0);
    for (std::int64_t m : {1, 7, 30}) {
        EXPECT_DOUBLE_EQ(one(a, Deviation::oadev, m), one(b, Deviation::oadev, m));
        EXPECT_DOUBLE_EQ(one(a, Deviation::mdev, m), one(b, Deviation::mdev, m));
    }
}

TEST(AllanGaps, NanPhaseSampleBreaksBothNeighbouringIntervals) {
    const std::size_t n = 3000;
    const std::size_t gap = 1234;
    auto x = white(n, 1.0, 18);
    std::vector<double> with_gap(x);
    with_gap[gap] = std::nan("");
    const PhaseRecord r = PhaseRecord::from_phase(with_gap, 1.0);
    const std::int64_t m = 10;
    const std::int64_t ms[] = {m};
    const DeviationCurve c = compute_deviation(r, Deviation::oadev, ms);
    // Segments of gap and n - gap - 1 phase samples: 2m + 1 terms fewer than the unbroken record.
    EXPECT_EQ(c.n[0], static_cast<std::int64_t>(n) - 2 * m - (2 * m + 1));
    const PhaseRecord first = PhaseRecord::from_phase(std::span<const double>(x.data(), gap), 1.0);
    const PhaseRecord second = PhaseRecord::from_phase(std::span<const double>(x.data() + gap + 1, n - gap - 1), 1.0);
    std::int64_t n_expected = 0;
    EXPECT_NEAR(c.dev[0] / pooled(first, second, Deviation::oadev, m, &n_expected), 1.0, 1e-12);
    EXPECT_EQ(c.n[0], n_expected);
}

TEST(AllanGaps, PooledEdfIsBelowTheUnbrokenRecordsEdf) {
    auto y = white(20000, 1.0, 19);
    const PhaseRecord whole = PhaseRecord::from_rate(y, 1.0);
    y[10000] = std::nan("");
    const PhaseRecord broken = PhaseRecord::from_rate(y, 1.0);
    const std::int64_t ms[] = {64};
    const AnalysedCurve a = analyse_deviation(whole, Deviation::oadev, ms);
    const AnalysedCurve b = analyse_deviation(broken, Deviation::oadev, ms);
    EXPECT_LT(b.edf[0], a.edf[0]);
    EXPECT_GT(b.edf[0], 0.9 * a.edf[0]);
}

TEST(AllanGaps, AllGapsGivesAnEmptyCurve) {
    std::vector<double> y(100, std::nan(""));
    const PhaseRecord r = PhaseRecord::from_rate(y, 1.0);
    const std::int64_t ms[] = {1, 2};
    EXPECT_TRUE(compute_deviation(r, Deviation::oadev, ms).m.empty());
}

// The factors shared among threads give every figure of the curve to the last digit, gaps and all: each factor's
// sum is one thread's, whichever.
TEST(AllanThreads, ThreeThreadsGiveTheDigitsOfOne) {
    std::vector<double> y = white(50000, 0.8, 21);
    for (std::size_t i = 1000; i < 1100; ++i) y[i] = std::nan("");
    const PhaseRecord r = PhaseRecord::from_rate(y, 0.01);
    const std::vector<std::int64_t> ms = {1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144, 233, 377, 610, 987, 1597, 2584};
    for (Deviation d : {Deviation::adev, Deviation::oadev, Deviation::mdev, Deviation::hdev, Deviation::ohdev}) {
        const AnalysedCurve one = analyse_deviation(r, d, ms, kOneSigmaConfidence, 1);
        const AnalysedCurve three = analyse_deviation(r, d, ms, kOneSigmaConfidence, 3);
        ASSERT_FALSE(one.curve.m.empty());
        EXPECT_EQ(three.curve.m, one.curve.m) << deviation_name(d);
        EXPECT_EQ(three.curve.dev, one.curve.dev) << deviation_name(d);
        EXPECT_EQ(three.curve.n, one.curve.n) << deviation_name(d);
        EXPECT_EQ(three.curve.n_skipped, one.curve.n_skipped) << deviation_name(d);
        EXPECT_EQ(three.alpha, one.alpha) << deviation_name(d);
        EXPECT_EQ(three.alpha_identified, one.alpha_identified) << deviation_name(d);
        EXPECT_EQ(three.ci_low, one.ci_low) << deviation_name(d);
        EXPECT_EQ(three.ci_high, one.ci_high) << deviation_name(d);
    }
}

TEST(PhaseRecordInput, RejectsBadTau0AndMaskLength) {
    std::vector<double> y(10, 1.0);
    std::vector<std::uint8_t> mask(9, 0);
    EXPECT_THROW(PhaseRecord::from_rate(y, 0.0), std::invalid_argument);
    EXPECT_THROW(PhaseRecord::from_rate(y, 1.0, mask), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::stats
