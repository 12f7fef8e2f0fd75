// The debiased Whittle machinery against closed forms and against Monte Carlo: the expected periodogram of a
// masked, tapered series is what the average periodogram of many realisations converges to.
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "host/gap/mean_shapes.hpp"
#include "host/gap/whittle.hpp"

namespace driftlab::host::gap {
namespace {

TEST(Whittle, WhiteFloorAutocovarianceFollowsTheSmootherKernel) {
    // Order 0, window = conversions per output: independent outputs of variance 1/N.
    auto r = white_floor_autocovariance({1.0, 8, 8, 0});
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NEAR(r[0], 1.0 / 8.0, 1e-15);
    // Window 8 over 4 conversions per output: neighbouring outputs share 4 of their 8 conversions.
    r = white_floor_autocovariance({1.0, 4, 8, 0});
    ASSERT_EQ(r.size(), 2u);
    EXPECT_NEAR(r[0], 1.0 / 8.0, 1e-15);
    EXPECT_NEAR(r[1], 4.0 / 64.0, 1e-15);
    // Order 1 evaluated at the newest conversion: sum h^2 = 2(2N - 1) / (N (N + 1)) (gap-method §1: 0.42 at N = 8).
    r = white_floor_autocovariance({1.0, 8, 8, 1});
    EXPECT_NEAR(r[0], 2.0 * 15.0 / 72.0, 1e-12);
}

// Polled rows slower than the outputs (a board paced faster than the recorder) are outputs_per_row x D conversions
// apart: ten outputs of 4 conversions leave no conversion two rows of window 8 share; 1.5 outputs (6 conversions)
// leave 2 of 8.
TEST(Whittle, WhiteFloorOfPolledRowsStepsByTheConversionsBetweenRows) {
    auto r = white_floor_autocovariance({10.0, 4, 8, 0, 10.0});
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NEAR(r[0], 1.0 / 8.0, 1e-15);
    r = white_floor_autocovariance({1.5, 4, 8, 0, 1.5});
    ASSERT_EQ(r.size(), 2u);
    EXPECT_NEAR(r[1], 2.0 / 64.0, 1e-15);
}

// Order 0 with D conversions per output over a window of N = kD: k outputs share each conversion, so the long-run
// variance of the outputs is k times their variance.
TEST(Whittle, LongRunFactorCountsTheOutputsThatShareAConversion) {
    EXPECT_NEAR(white_floor_long_run_factor({1.0, 8, 8, 0}), 1.0, 1e-12);
    EXPECT_NEAR(white_floor_long_run_factor({1.0, 4, 8, 0}), 2.0, 1e-12);
    EXPECT_NEAR(white_floor_long_run_factor({1.0, 1, 8, 0}), 8.0, 1e-12);
}

TEST(Whittle, DifferencedAutocovarianceOfAnAr1IsTheDifferenceOfItsAutocovariances) {
    OutputSpectrum m;
    m.ar1.push_back({2.5, 0.9});
    const auto c = differenced_autocovariance(m, {0.0}, 40);
    auto gamma = [](int k) { return 2.5 * std::pow(0.9, std::abs(k)); };
    for (int k = 0; k < 40; ++k)
        EXPECT_NEAR(c[static_cast<std::size_t>(k)], 2.0 * gamma(k) - gamma(k - 1) - gamma(k + 1), 1e-12) << k;
    // A random walk's increments are white; the white floor's differences are an MA(1).
    OutputSpectrum w;
    w.white = 3.0;
    w.walk_increment_variance = 0.5;
    const auto cw = differenced_autocovariance(w, {1.0}, 5);
    EXPECT_NEAR(cw[0], 6.5, 1e-12);
    EXPECT_NEAR(cw[1], -3.0, 1e-12);
    EXPECT_NEAR(cw[2], 0.0, 1e-12);
}

TEST(Whittle, CovarianceTimesAVectorIsTheToeplitzProduct) {
    OutputSpectrum m;
    m.white = 1.7;
    m.ar1 = {{2.5, 0.9}, {0.4, 0.3}};
    m.walk_increment_variance = 0.05;
    const std::vector<double> floor{0.125, 0.0625};  // window 8 over 4 conversions per output
    const std::size_t n = 60;
    std::vector<double> v(n);
    for (std::size_t t = 0; t < n; ++t) v[t] = std::sin(0.37 * static_cast<double>(t)) + (t == 17 ? 3.0 : 0.0);
    const auto c = differenced_autocovariance(m, floor, n);
    const auto fast = differenced_covariance_times(m, floor, v);
    for (std::size_t t = 0; t < n; ++t) {
        double direct = 0.0;
        for (std::size_t s2 = 0; s2 < n; ++s2) direct += c[t > s2 ? t - s2 : s2 - t] * v[s2];
        EXPECT_NEAR(fast[t], direct, 1e-12) << t;
    }
}

TEST(Whittle, DensityAveragesToTheDifferencesVariance) {
    // Parseval: the mean of the spectral density over the Fourier grid is c(0).
    OutputSpectrum m;
    m.white = 1.3;
    m.ar1.push_back({4.0, 0.95});
    m.walk_increment_variance = 0.01;
    const std::vector<double> floor{0.125};
    const auto s = differenced_density(m, floor, 2000);
    const double mean = std::accumulate(s.begin(), s.end(), 0.0) / 2000.0;
    EXPECT_NEAR(mean, differenced_autocovariance(m, floor, 1)[0], 1e-3);
}

// The interleaved design's fitting part: the even tenths of the log.
std::vector<bool> even_tenths(std::size_t n) {
    std::vector<bool> part(n);
    for (std::size_t i = 0; i < n; ++i) part[i] = (i * 10 / n) % 2 == 0;
    return part;
}

// The average periodogram on `part` of 1500 series drawn by `draw(rng, n01)`, and the first one's periodogram
// (which carries the part's mask and taper, and `absorbed`).
template <class Draw>
std::pair<std::vector<double>, PartPeriodogram> average_periodogram(const std::vector<bool>& part, std::uint64_t seed,
                                                                    const Eigen::MatrixXd* absorbed, Draw draw) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n01;
    const int runs = 1500;
    std::vector<double> average;
    PartPeriodogram first;
    for (int r = 0; r < runs; ++r) {
        const PartPeriodogram p = part_periodogram(draw(rng, n01), part, absorbed);
        if (average.empty()) average.assign(p.power.size(), 0.0), first = p;
        for (std::size_t j = 0; j < p.power.size(); ++j) average[j] += p.power[j] / runs;
    }
    return {average, first};
}

// Average over expected power in ordinates lo..lo + width - 1.
double band_ratio(const std::vector<double>& average, const std::vector<double>& expected, std::size_t lo,
                  std::size_t width) {
    double a = 0.0, e = 0.0;
    for (std::size_t j = lo; j < lo + width; ++j) a += average[j], e += expected[j];
    return a / e;
}

// The part is every other tenth of the log (the interleaved design): its masked, tapered periodogram averaged over
// many realisations of white + AR(1) + random walk matches the expected periodogram band by band.
TEST(Whittle, ExpectedPeriodogramOfAMaskedSeriesMatchesTheMonteCarloAverage) {
    const std::size_t n = 1500;
    const double phi = std::exp(-1.0 / 20.0);
    OutputSpectrum m;
    m.white = 1.0;
    m.ar1.push_back({4.0, phi});
    m.walk_increment_variance = 0.01;
    const auto [average, first] = average_periodogram(even_tenths(n), 3, nullptr, [&](auto& rng, auto& n01) {
        std::vector<double> e(n);
        double x = 2.0 * n01(rng), walk = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            x = phi * x + std::sqrt(4.0 * (1.0 - phi * phi)) * n01(rng);
            walk += 0.1 * n01(rng);
            e[i] = x + walk + n01(rng);
        }
        return e;
    });
    const auto expected = expected_periodogram(m, {1.0}, first);
    // Bands of 16 ordinates: the average of 1500 x 16 (correlated) exponentials is within a few per cent.
    for (std::size_t lo = 0; lo + 16 <= expected.size(); lo += 16)
        EXPECT_NEAR(band_ratio(average, expected, lo, 16), 1.0, 0.06) << "ordinates " << lo << "..";
}

// A least-squares fit of the mean takes a walk's lowest frequencies with it: the residual of a fixed linear span (eq.
// 1's tangent at T = 400 s) from white + random walk, on the interleaved part, averages to the expected periodogram
// that knows the span, also in the lowest ordinates, whose shape the plain one misses.
TEST(Whittle, ExpectedPeriodogramOfAFittedResidualKnowsWhatTheFitAbsorbed) {
    const std::size_t n = 1500;
    OutputSpectrum m;
    m.white = 1.0;
    m.walk_increment_variance = 0.04;
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i + 1);
    const Eigen::MatrixXd x = eq1_tangent(t, 400.0);
    const Eigen::MatrixXd projector = x * (x.transpose() * x).ldlt().solve(x.transpose());
    const auto [average, first] = average_periodogram(even_tenths(n), 5, &x, [&](auto& rng, auto& n01) {
        Eigen::VectorXd e(static_cast<Eigen::Index>(n));
        double walk = 0.0;
        for (Eigen::Index i = 0; i < e.size(); ++i) {
            walk += 0.2 * n01(rng);
            e(i) = walk + n01(rng);
        }
        e -= projector * e;
        return std::vector<double>(e.data(), e.data() + e.size());
    });
    const auto expected = expected_periodogram(m, {1.0}, first);
    PartPeriodogram plain = first;
    plain.absorbed.reset();
    const auto unaware = expected_periodogram(m, {1.0}, plain);
    for (std::size_t lo = 0; lo + 4 <= 64; lo += 4)
        EXPECT_NEAR(band_ratio(average, expected, lo, 4), 1.0, 0.08) << "ordinates " << lo << "..";
    for (std::size_t lo = 64; lo + 16 <= expected.size(); lo += 16)
        EXPECT_NEAR(band_ratio(average, expected, lo, 16), 1.0, 0.06) << "ordinates " << lo << "..";
    // In the lowest ordinates the fit reshapes the part's expected power by up to a fifth either way; the plain
    // expectation misses that shape, the one that knows the span follows it.
    double aware = 0.0, plain_misfit = 0.0;
    for (std::size_t j = 0; j < 12; ++j) {
        aware += std::pow(std::log(average[j] / expected[j]), 2);
        plain_misfit += std::pow(std::log(average[j] / unaware[j]), 2);
    }
    EXPECT_LT(aware, 0.25 * plain_misfit) << aware << " vs " << plain_misfit;
}

// Without a fitted span the expected periodogram is the masked covariance's Fourier sum, sum over tau = -(n-1)..n-1 of
// mask_overlap(|tau|) c(|tau|) cos(w_j tau): summed directly here, where expected_periodogram() adds its components'
// FFTs.
TEST(Whittle, ExpectedPeriodogramIsTheMaskedCovariancesFourierSum) {
    const std::size_t n = 300;
    std::vector<double> e(n);
    std::mt19937_64 rng(11);
    std::normal_distribution<double> n01;
    for (double& v : e) v = n01(rng);
    const PartPeriodogram p = part_periodogram(e, even_tenths(n));
    const std::vector<double> floor = white_floor_autocovariance({1.0, 4, 8, 0});
    OutputSpectrum m;
    m.white = 2.0;
    m.ar1 = {{3.0, 0.9}, {0.5, 0.99}};
    m.walk_increment_variance = 0.02;
    const std::vector<double> c = differenced_autocovariance(m, floor, p.length);
    const auto expected = expected_periodogram(m, floor, p);
    ASSERT_EQ(expected.size(), p.power.size());
    for (std::size_t j = 0; j < expected.size(); ++j) {
        const double w = 2.0 * std::numbers::pi * static_cast<double>(j + 1) / static_cast<double>(p.length);
        double sum = c[0] * p.mask_overlap[0];
        for (std::size_t tau = 1; tau < p.length; ++tau)
            sum += 2.0 * c[tau] * p.mask_overlap[tau] * std::cos(w * static_cast<double>(tau));
        EXPECT_NEAR(expected[j], sum, 1e-10 * std::abs(sum) + 1e-12) << "ordinate " << j + 1;
    }
}

// A fit's evaluator keeps the unit components it has computed: after more Gauss-Markov correlation times than it
// keeps (some evicted, some kept), every model it evaluates is the same, to the bit, as a fresh evaluator's, on a
// fitted residual's part.
TEST(Whittle, AFitsEvaluatorGivesWhatAFreshOneGives) {
    const std::size_t n = 400;
    std::vector<double> e(n), t(n);
    std::mt19937_64 rng(12);
    std::normal_distribution<double> n01;
    for (std::size_t i = 0; i < n; ++i) e[i] = n01(rng), t[i] = static_cast<double>(i + 1);
    const Eigen::MatrixXd x = eq1_tangent(t, 150.0);
    const PartPeriodogram p = part_periodogram(e, even_tenths(n), &x);
    const std::vector<double> floor = white_floor_autocovariance({1.0, 8, 8, 1});
    ExpectedPeriodogram reused(floor, p);
    for (int k = 0; k < 40; ++k) {
        OutputSpectrum m;
        m.white = 1.0 + 0.01 * k;
        m.ar1 = {{0.3, 0.5}, {0.2 + 0.05 * k, std::exp(-1.0 / (2.0 + 3.0 * (k % 30)))}};
        m.walk_increment_variance = k % 3 == 0 ? 0.0 : 1e-3 * k;
        EXPECT_EQ(reused(m), expected_periodogram(m, floor, p)) << "model " << k;
    }
}

TEST(Whittle, TooFewDifferencesInThePartAreRefused) {
    std::vector<double> e(100, 1.0);
    std::vector<bool> part(100, false);
    for (std::size_t i = 0; i < 10; ++i) part[i] = true;
    EXPECT_THROW(part_periodogram(e, part), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::gap
