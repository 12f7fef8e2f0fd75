// The noise truth generators of gap-eval (truth.hpp, truth_*.cpp) checked against what their documentation
// promises, with expectations derived independently of their code: 1/f noise, a wandering OU, a Student-t (nu = 4)
// walk and Laplace bursts of 1-3 outputs. burst_spikes does not quite do what truth.hpp says, and the test pins what
// it does: its size is the deviation of a burst's amplitude, not of the signal (0.115 x size).
//
// Statistical tolerances are about 4 standard deviations of the estimator's scatter (each derivation is stated
// where it is used) on a fixed, declared set of seeds; they are not tuned to those seeds.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap_eval/truth.hpp"
#include "truth_support.hpp"

namespace driftlab::host::gap {
namespace {

using truth_testing::eval_grid;
using truth_testing::kPi;
using truth_testing::mean_of;

// Two-sided tail P(|T| > x) of Student's t with nu = 4, from its closed-form CDF
// F(x) = 1/2 + (3/8) (x / s) (1 - x^2 / (12 s^2)), s = sqrt(1 + x^2/4).
double t4_two_sided_tail(double x) {
    const double s = std::sqrt(1.0 + x * x / 4.0);
    return 1.0 - 0.75 * (x / s) * (1.0 - x * x / (12.0 * s * s));
}

// Two-sided Gaussian tail P(|Z| > x).
double normal_two_sided_tail(double x) { return std::erfc(x / std::sqrt(2.0)); }

// ---------------------------------------------------------------------------------------------------------------
// kasdin_flicker: 1/f noise, scaled to standard deviation `size`.
// The spectral slope is read by log-periodogram regression (Geweke & Porter-Hudak) on the first difference, whose
// spectrum (proportional to f for 1/f noise) rises, so a rectangular window leaks nothing that matters; the
// difference's periodogram divided by |1 - e^{-2 pi i f}|^2 = 4 sin^2(pi f) estimates the noise's own spectrum.
// Each log-periodogram ordinate of a Gaussian series scatters with variance pi^2/6 (log of an exponential), nearly
// independently between Fourier frequencies, so one record's slope has standard deviation
// sqrt(pi^2/6 / sum (ln f_k - mean)^2) (about 0.047 for 1500 outputs), and the mean over M records 1/sqrt(M) of it.

double gph_slope_of_difference(const std::vector<double>& x) {
    const std::size_t m = x.size() - 1;
    std::vector<double> d(m), c(m), s(m);
    for (std::size_t j = 0; j < m; ++j) d[j] = x[j + 1] - x[j];
    for (std::size_t r = 0; r < m; ++r) c[r] = std::cos(2.0 * kPi * r / m), s[r] = std::sin(2.0 * kPi * r / m);
    std::vector<double> lx, ly;
    for (std::size_t k = 1; 2 * k < m; ++k) {
        double re = 0.0, im = 0.0;
        for (std::size_t j = 0; j < m; ++j) {
            const std::size_t r = (j * k) % m;
            re += d[j] * c[r], im -= d[j] * s[r];
        }
        const double f = static_cast<double>(k) / static_cast<double>(m);
        lx.push_back(std::log(f));
        ly.push_back(std::log(re * re + im * im) - std::log(4.0 * std::pow(std::sin(kPi * f), 2)));
    }
    const double mx = mean_of(lx), my = mean_of(ly);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < lx.size(); ++i) sxy += (lx[i] - mx) * (ly[i] - my), sxx += (lx[i] - mx) * (lx[i] - mx);
    return sxy / sxx;
}

double gph_slope_sd(std::size_t n) {
    const std::size_t m = n - 1;
    std::vector<double> lx;
    for (std::size_t k = 1; 2 * k < m; ++k) lx.push_back(std::log(static_cast<double>(k) / static_cast<double>(m)));
    const double mx = mean_of(lx);
    double sxx = 0.0;
    for (double v : lx) sxx += (v - mx) * (v - mx);
    return std::sqrt(kPi * kPi / 6.0 / sxx);
}

TEST(TruthKasdinFlicker, IsOneOverFNoiseOfTheRequestedDeviation) {
    constexpr std::uint64_t kSeeds = 16;  // noise seeds 1..16
    const std::vector<double> t = eval_grid();
    double slope_sum = 0.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const std::vector<double> v = make_truth("kasdin_flicker", t, 3.0, 7, seed);
        const double m = mean_of(v);
        double ss = 0.0;
        for (double x : v) ss += (x - m) * (x - m);
        EXPECT_NEAR(m, 0.0, 1e-9);
        EXPECT_NEAR(std::sqrt(ss / static_cast<double>(v.size())), 3.0, 1e-9);
        const double b = gph_slope_of_difference(v);
        slope_sum += b;
    }
    // (The estimator's own bias, from the segment's leakage, is under 0.01: -1.008 over 300 records of other seeds.)
    const double tol = 4.0 * gph_slope_sd(t.size()) / std::sqrt(static_cast<double>(kSeeds));  // about 0.047
    EXPECT_NEAR(slope_sum / kSeeds, -1.0, tol);
}

// ---------------------------------------------------------------------------------------------------------------
// wandering_ou: dx = -x/tau dt + sqrt(2/tau) dW, scaled by size: stationary variance size^2 whatever tau (the
// stationary variance of this OU does not depend on tau, so its wander leaves it alone), mean 0, and a correlation
// time tau(t) = tau0 (1 +- 0.3) with tau0 log-uniform in [L/200, L/30].
// Euler-Maruyama with step h holds the variance at 1 / (1 - h / (2 tau)) instead of 1: with h = 1/8 s and
// tau >= 0.7 L/200 = 5.2 s, at most 1.2 % more (a property of the documented scheme, allowed for below).
// Scatter over one record of an OU of correlation time tau over L: the record's mean has variance ~2 tau/L, its mean
// square (relative) also ~2 tau / L; with tau <= 1.3 L/30 that is at most 0.087. Averaged over M records: /M.

TEST(TruthWanderingOu, HasTheRequestedDeviationZeroMeanAndADocumentedCorrelationTime) {
    constexpr std::uint64_t kSeeds = 400;  // shape and noise seeds 1..400
    const double size = 2.0;
    const std::vector<double> t = eval_grid();
    const double span = t.back() - t.front();
    const double tau_min = 0.7 * span / 200.0, tau_max = 1.3 * span / 30.0;
    const double tau_median = span / std::sqrt(200.0 * 30.0);  // median of a log-uniform tau0 in [L/200, L/30]
    double sum_mean = 0.0, sum_ms = 0.0;
    int below_median = 0, outside = 0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const std::vector<double> v = make_truth("wandering_ou", t, size, seed, seed);
        const double m = mean_of(v);
        double ms = 0.0, c0 = 0.0, c1 = 0.0;
        for (std::size_t k = 0; k < v.size(); ++k) {
            ms += v[k] * v[k];
            c0 += (v[k] - m) * (v[k] - m);
            if (k) c1 += (v[k] - m) * (v[k - 1] - m);
        }
        sum_mean += m / size;
        sum_ms += ms / static_cast<double>(v.size()) / (size * size);
        const double tau_hat = -1.0 / std::log(std::max(1e-9, c1 / c0));  // lag-1 autocorrelation e^{-1 s / tau}
        below_median += tau_hat < tau_median;
        outside += tau_hat < tau_min || tau_hat > tau_max;
    }
    const double per_record_var = 2.0 * tau_max / span;
    const double tol = 4.0 * std::sqrt(per_record_var / kSeeds);  // about 0.059
    EXPECT_NEAR(sum_mean / kSeeds, 0.0, tol);
    const double em_excess = 1.0 / (1.0 - 0.125 / (2.0 * tau_min)) - 1.0;
    EXPECT_GE(sum_ms / kSeeds, 1.0 - tol);
    EXPECT_LE(sum_ms / kSeeds, 1.0 + em_excess + tol);
    // Correlation time, from each record's lag-1 autocorrelation. Half the records have a tau0 below the documented
    // median. The estimate reads tau short by about 10 %: mean subtraction biases r1 by -(1 + 3 r)/n (5.5 % in tau at
    // the median, d tau / tau = d r / (r |ln r|)) and r1 averages e^{-1/tau(t)} over the wander, i.e. 1/tau by
    // 1/sqrt(1 - 0.3^2) = 1.048 (4.8 %). With the log-uniform density 1/ln(200/30) = 0.53 per unit of ln tau, that
    // raises the fraction below the median to about 0.553. Its scatter (about 16 % at the median) is symmetric in
    // ln tau and moves the fraction little. Binomial scatter over 400 records: 4 sqrt(1/4/400) = 0.1.
    EXPECT_NEAR(below_median / static_cast<double>(kSeeds), 0.5 + 0.53 * 0.1, 0.1);
    // And few records read a tau outside the documented range with its wander (at the ends, by estimation error).
    EXPECT_LT(outside / static_cast<double>(kSeeds), 0.1);
}

// ---------------------------------------------------------------------------------------------------------------
// student_walk: a walk whose steps are Student-t (nu = 4) scaled to a standard deviation of size / sqrt(n), so that
// size is the walk's standard deviation at the end of the log (truth_noise.cpp). Student-t(4) has an infinite fourth
// moment, so moment ratios (kurtosis, mean |step| / rms step, which is 1/sqrt(2) for t4) have no usable scatter;
// tail frequencies are binomial and have: P(|step| > c sd) = P(|T4| > c sqrt(2)) exactly.

TEST(TruthStudentWalk, StepsAreIndependentStudentT4OfTheDocumentedSize) {
    constexpr std::uint64_t kSeeds = 40;  // noise seeds 1..40
    const double size = 3.0;
    const std::vector<double> t = eval_grid();
    const double step_sd = size / std::sqrt(static_cast<double>(t.size()));
    const std::vector<double> c_list = {0.5, 1.0, 2.0, 3.0, 4.0};
    std::vector<double> beyond(c_list.size(), 0.0);
    double n = 0.0, lag0 = 0.0, lag1 = 0.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const std::vector<double> v = make_truth("student_walk", t, size, 11, seed);
        double prev_step = 0.0;
        for (std::size_t k = 0; k < v.size(); ++k) {
            const double step = v[k] - (k ? v[k - 1] : 0.0);
            for (std::size_t i = 0; i < c_list.size(); ++i) beyond[i] += std::abs(step) > c_list[i] * step_sd;
            lag0 += step * step;
            if (k) lag1 += step * prev_step;
            prev_step = step;
            n += 1.0;
        }
    }
    for (std::size_t i = 0; i < c_list.size(); ++i) {
        const double p = t4_two_sided_tail(c_list[i] * std::sqrt(2.0));
        const double tol = 4.0 * std::sqrt(p * (1.0 - p) / n);
        EXPECT_NEAR(beyond[i] / n, p, tol)
            << "beyond " << c_list[i] << " step deviations (a Gaussian: " << normal_two_sided_tail(c_list[i]) << ")";
    }
    // Independent steps: the lag-1 autocorrelation of iid steps of finite variance scatters by 1/sqrt(n).
    EXPECT_NEAR(lag1 / lag0, 0.0, 4.0 / std::sqrt(n));
}

// The end point is a sum of 1500 independent steps of deviation size/sqrt(1500): nearly Gaussian with deviation size
// (Berry-Esseen: E|T4|^3 = 8, i.e. 2.83 in step deviations, bounds the CDF error by 0.4748 x 2.83 / sqrt(1500) =
// 0.035 per side). So about P(|Z| > 1) = 0.317 of the walks end beyond +-size; binomial scatter over 400 walks
// sqrt(0.317 x 0.683 / 400) = 0.023.
TEST(TruthStudentWalk, EndsWithTheRequestedDeviation) {
    constexpr std::uint64_t kSeeds = 400;  // noise seeds 1..400
    const double size = 3.0;
    const std::vector<double> t = eval_grid();
    int beyond = 0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed)
        beyond += std::abs(make_truth("student_walk", t, size, 11, seed).back()) > size;
    const double p = normal_two_sided_tail(1.0);
    EXPECT_NEAR(beyond / static_cast<double>(kSeeds), p, 4.0 * std::sqrt(p * (1.0 - p) / kSeeds) + 2.0 * 0.035);
}

// ---------------------------------------------------------------------------------------------------------------
// burst_spikes: at each output a burst starts with probability p = 1/150; it covers 1, 2 or 3 whole outputs (equally
// likely) with one Laplace amplitude of standard deviation `size` (Laplace scale size/sqrt(2)); zero elsewhere.

// Expected runs of nonzero outputs and of uncovered outputs on `n` outputs, for one seed. A run starts at k when a
// burst starts there and output k-1 is not covered: no burst at k-1, none of length >= 2 at k-2, none of length 3
// at k-3.
std::pair<double, double> expected_runs_and_zeros(std::size_t n, double p) {
    double expected_runs = 0.0, expected_zeros = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        double q = 1.0;  // P(k-1 not covered)
        if (k >= 1) q *= 1.0 - p;
        if (k >= 2) q *= 1.0 - 2.0 * p / 3.0;
        if (k >= 3) q *= 1.0 - p / 3.0;
        expected_runs += p * q;
        double z = 1.0 - p;  // P(k not covered)
        if (k >= 1) z *= 1.0 - 2.0 * p / 3.0;
        if (k >= 2) z *= 1.0 - p / 3.0;
        expected_zeros += z;
    }
    return {expected_runs, expected_zeros};
}

struct BurstTally {
    double runs = 0.0, zeros = 0.0, sum_sq = 0.0;
    std::vector<double> amps;
    std::array<double, 4> by_length{};  // clean runs (one amplitude, zeros either side) of length 1..3
};

void tally_bursts(const std::vector<double>& v, std::uint64_t seed, BurstTally& tally) {
    const std::size_t n = v.size();
    for (double x : v) tally.zeros += x == 0.0, tally.sum_sq += x * x;
    // No output period holds part of a burst: every stretch of one nonzero value is 1-3 outputs long (two bursts
    // cannot share an amplitude).
    for (std::size_t k = 0; k < n;) {
        if (v[k] == 0.0) {
            ++k;
            continue;
        }
        std::size_t e = k;
        while (e < n && v[e] == v[k]) ++e;
        EXPECT_LE(e - k, 3u) << "seed " << seed << " at " << k;
        k = e;
    }
    for (std::size_t k = 0; k < n;) {
        if (v[k] == 0.0) {
            ++k;
            continue;
        }
        std::size_t e = k;
        bool one_value = true;
        while (e < n && v[e] != 0.0) one_value = one_value && v[e] == v[k], ++e;
        tally.runs += 1.0;
        if (one_value && e < n && e - k <= 3) {
            tally.by_length[e - k] += 1.0;
            tally.amps.push_back(v[k]);
        }
        k = e;
    }
}

TEST(TruthBurstSpikes, BurstsOfOneToThreeOutputsAtTheDocumentedRateWithLaplaceAmplitudes) {
    constexpr std::uint64_t kSeeds = 400;  // noise seeds 1..400
    const double size = 2.0, p = 1.0 / 150.0;
    const std::vector<double> t = eval_grid();
    const std::size_t n = t.size();
    auto [expected_runs, expected_zeros] = expected_runs_and_zeros(n, p);
    expected_runs *= kSeeds, expected_zeros *= kSeeds;
    BurstTally tally;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed)
        tally_bursts(make_truth("burst_spikes", t, size, 13, seed), seed, tally);
    const auto& [runs, zeros, sum_sq, amps, by_length] = tally;
    // Runs: a sum of rare, locally exclusive indicators (a run cannot start at k and k+1): variance at most its mean.
    EXPECT_NEAR(runs, expected_runs, 4.0 * std::sqrt(expected_runs));
    // Covered outputs: a compound Poisson count, variance n p E[len^2] = n p 14/3.
    EXPECT_NEAR(zeros, expected_zeros, 4.0 * std::sqrt(kSeeds * n * p * 14.0 / 3.0));
    // Lengths 1, 2, 3 alike among the clean runs (multinomial, 1/3 each; overlaps, which spoil a longer burst a
    // little more often, bias this by about p x len, under 2 %).
    const double clean = by_length[1] + by_length[2] + by_length[3];
    for (int len = 1; len <= 3; ++len)
        EXPECT_NEAR(by_length[static_cast<std::size_t>(len)] / clean, 1.0 / 3.0,
                    4.0 * std::sqrt(2.0 / 9.0 / clean) + 0.02 / 3.0)
            << "length " << len;
    // Laplace amplitudes: |a| is exponential, E|a| / rms(a) = 1/sqrt(2) (a Gaussian: sqrt(2/pi) = 0.80); by the delta
    // method on (E|a|, E a^2) with |a|/b ~ Exp(1) (moments 1, 2, 6, 24) the ratio's variance is 0.125 / N. Its rms is
    // `size`: the mean square's relative variance is (E a^4 - (E a^2)^2) / (E a^2)^2 = 5, so the rms's is 5/4 / N.
    double abs_sum = 0.0, sq_sum = 0.0, sum = 0.0;
    for (double a : amps) abs_sum += std::abs(a), sq_sum += a * a, sum += a;
    const double na = static_cast<double>(amps.size());
    const double rms = std::sqrt(sq_sum / na);
    EXPECT_NEAR(abs_sum / na / rms, 1.0 / std::sqrt(2.0), 4.0 * std::sqrt(0.125 / na));
    EXPECT_NEAR(rms / size, 1.0, 4.0 * std::sqrt(1.25 / na));
    EXPECT_NEAR(sum / na / size, 0.0, 4.0 / std::sqrt(na));
    // So the signal's own mean square is 2 p size^2 (each output is covered by a burst started at it, or a burst of
    // length >= 2 one before, or of length 3 two before: p (1 + 2/3 + 1/3)); its standard deviation is
    // sqrt(2/150) size = 0.115 size, NOT size: for this generator `size` is the deviation of a burst's amplitude.
    // Relative scatter: sum over bursts of len a^2, variance N p E[len^2] E[a^4] = N p 14/3 x 6 size^4 over the
    // mean 2 N p size^2: sqrt(7 / (N p)).
    const double np = kSeeds * n * p;
    EXPECT_NEAR(sum_sq / (kSeeds * n) / (size * size), 2.0 * p, 2.0 * p * 4.0 * std::sqrt(7.0 / np));
}

// ---------------------------------------------------------------------------------------------------------------
// supply_wander: a Gauss-Markov drive through a first-order lag, scaled to standard deviation `size`. Its form is
// second order, not the candidate's one Gauss-Markov: increments over 2 steps against 1 step have the variance ratio
// 2 (1 - rho(2)) / 2 (1 - rho(1)), which is 2 for a first-order process (white-like increments at lags far below
// tau) and tends to 4 for a smooth one (1 - rho(d) ~ d^2 below the lag's tau2 >= L/160 = 125 outputs here). Over
// 20 000 outputs the ratio's scatter is a few per cent.
TEST(TruthSupplyWander, IsSecondOrderWithTheSizeAsItsDeviation) {
    const auto t = eval_grid(20000);
    for (std::uint64_t seed : {3u, 4u, 5u}) {
        const auto x = truth_supply_wander(t, 0.002, seed, seed + 100);
        const double m = mean_of(x);
        double var = 0.0, d1 = 0.0, d2 = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) var += (x[k] - m) * (x[k] - m);
        for (std::size_t k = 2; k < x.size(); ++k) {
            d1 += (x[k] - x[k - 1]) * (x[k] - x[k - 1]);
            d2 += (x[k] - x[k - 2]) * (x[k] - x[k - 2]);
        }
        EXPECT_NEAR(std::sqrt(var / static_cast<double>(x.size())), 0.002, 1e-12);
        EXPECT_GT(d2 / d1, 3.5);
        EXPECT_LT(d2 / d1, 4.01);
    }
}

}  // namespace
}  // namespace driftlab::host::gap
