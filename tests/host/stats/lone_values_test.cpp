// Lone values: a corrupt row is found at its place whatever its size, also in a series constant but for it, while
// Gaussian noise, steps, small spikes, single-code flips and the ends of a series are not; the warning needs the share
// of variance documented.
#include "host/stats/lone_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace driftlab::host::stats {
namespace {

// White noise of deviation `sigma` around mid-scale (512 counts).
std::vector<double> white_codes(std::size_t n, double sigma, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, sigma);
    std::vector<double> x(n);
    for (double& v : x) v = 512.0 + g(rng);
    return x;
}

std::vector<double> times(std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = 0.5 * static_cast<double>(k);
    return t;
}

TEST(LoneValues, ACorruptRowIsFoundAtItsPlaceWhateverItsSize) {
    for (double spike : {1e3, 1e30, 1e300, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()}) {
        std::vector<double> x = white_codes(4000, 0.01, 1);
        x[1500] = spike;
        const LoneValues found = lone_values(x);
        ASSERT_EQ(found.indices, std::vector<std::size_t>{1500}) << spike;
        // Its two differences are each about |spike - 512|, the other 3997 of variance 2 x 0.01^2: the share falls
        // short of 1 by 3997 x 2e-4 / (2 (spike - 512)^2), 1.7e-6 for the smallest.
        const double d = spike - 512.0;
        EXPECT_NEAR(1.0 - found.variance_share, std::min(1.0, 3997 * 2e-4 / (2.0 * d * d)), 3e-7) << spike;
        EXPECT_TRUE(std::isfinite(found.variance_share)) << spike;
    }
}

// Differences of white noise are normal with sigma sqrt(2) s; both neighbours of a sample 10 robust sigmas away have
// probability below 1e-20 per sample, so a million samples have none.
TEST(LoneValues, GaussianNoiseHasNone) {
    for (unsigned seed : {1u, 2u, 3u})
        EXPECT_TRUE(lone_values(white_codes(1'000'000, 3.0, seed)).indices.empty()) << seed;
}

TEST(LoneValues, AStepIsNotALoneValue) {
    std::vector<double> x = white_codes(2000, 0.01, 4);
    for (std::size_t k = 1000; k < x.size(); ++k) x[k] += 1e6;
    EXPECT_TRUE(lone_values(x).indices.empty());
    // Two rows out together are a short plateau, not a single corrupt value.
    std::vector<double> y = white_codes(2000, 0.01, 5);
    y[700] = y[701] = 1e6;
    EXPECT_TRUE(lone_values(y).indices.empty());
}

TEST(LoneValues, ASpikeBelowTheFactorIsNotLone) {
    std::vector<double> x = white_codes(20000, 1.0, 6);
    // 7 from its neighbours' mean is about 5 standard deviations of the differences (sqrt(2)) from each neighbour:
    // under kLoneFactor. 30 is about 21.
    x[5000] = x[4999] / 2.0 + x[5001] / 2.0 + 7.0;
    EXPECT_TRUE(lone_values(x).indices.empty());
    x[5000] = x[4999] / 2.0 + x[5001] / 2.0 + 30.0;
    EXPECT_EQ(lone_values(x).indices, std::vector<std::size_t>{5000});
}

// Mostly one code with single-code flips: the median difference is 0, so the step of one code is the scale, and a
// flip is one step from its neighbours, not ten. A jump of 100 codes is lone.
TEST(LoneValues, OnOneCodeTheStepIsTheScale) {
    std::vector<double> x(3000, 505.0);
    for (std::size_t k = 10; k < x.size(); k += 37) x[k] = 506.0;
    EXPECT_TRUE(lone_values(x).indices.empty());
    x[1201] = 605.0;
    EXPECT_EQ(lone_values(x).indices, std::vector<std::size_t>{1201});
    EXPECT_TRUE(lone_values(std::vector<double>(100, 3.0)).indices.empty());
}

// A series constant but for one row has no step to measure the row by but its own: the row is lone whatever its size
// (before, its own difference had been the scale, and a 0x7FFF in a stuck channel went unwarned). Two departing rows
// measure each other: the one more than ten times the other's size is lone.
TEST(LoneValues, OnAConstantSeriesOneDepartingRowIsLone) {
    for (double v : {513.0, 32767.0, -1e300}) {
        std::vector<double> x(1000, 512.0);
        x[400] = v;
        const LoneValues found = lone_values(x);
        EXPECT_EQ(found.indices, std::vector<std::size_t>{400}) << v;
        EXPECT_DOUBLE_EQ(found.variance_share, 1.0) << v;
        EXPECT_TRUE(lone_values_warning(times(x.size()), x).has_value()) << v;
    }
    std::vector<double> x(1000, 512.0);
    x[300] = 522.0;
    x[600] = 1512.0;
    EXPECT_EQ(lone_values(x).indices, std::vector<std::size_t>{600});
    x[600] = 562.0;  // five times: neither
    EXPECT_TRUE(lone_values(x).indices.empty());
}

// Where the values are converter codes, one code bounds the step: two corrupt rows on a stuck channel are each more
// than ten codes out and lone (without the code they measure each other), while a departure of one code is a flip,
// alone or among others, and not lone (without the code, alone, it is). A series that varies keeps its robust scale.
TEST(LoneValues, AKnownCodeBoundsTheStepOfAStuckChannel) {
    std::vector<double> x(1000, 512.0);
    x[300] = 1023.0;
    x[600] = 1023.0;
    EXPECT_TRUE(lone_values(x).indices.empty());
    const LoneValues found = lone_values(x, 1.0);
    EXPECT_EQ(found.indices, (std::vector<std::size_t>{300, 600}));
    EXPECT_DOUBLE_EQ(found.variance_share, 1.0);
    x[600] = 522.0;  // ten codes: not over ten
    EXPECT_EQ(lone_values(x, 1.0).indices, std::vector<std::size_t>{300});
    x[600] = 523.0;
    EXPECT_EQ(lone_values(x, 1.0).indices, (std::vector<std::size_t>{300, 600}));

    std::vector<double> flip(1000, 512.0);
    flip[400] = 513.0;
    EXPECT_EQ(lone_values(flip).indices, std::vector<std::size_t>{400});
    EXPECT_TRUE(lone_values(flip, 1.0).indices.empty());
    EXPECT_FALSE(lone_values_warning(times(flip.size()), flip, 1.0).has_value());
    for (std::size_t k = 10; k < flip.size(); k += 37) flip[k] = 511.0;
    flip[700] = 612.0;
    EXPECT_EQ(lone_values(flip, 1.0).indices, std::vector<std::size_t>{700});

    // Noise of 0.01 code: the robust scale, not the code, measures a row; a 1-code row is 70 of it from both sides.
    std::vector<double> quiet = white_codes(2000, 0.01, 9);
    quiet[900] += 1.0;
    EXPECT_EQ(lone_values(quiet, 1.0).indices, std::vector<std::size_t>{900});
}

TEST(LoneValues, TheEndsAreNeverLone) {
    std::vector<double> x = white_codes(500, 0.01, 7);
    x.front() = 1e9;
    x.back() = -1e9;
    EXPECT_TRUE(lone_values(x).indices.empty());
    EXPECT_TRUE(lone_values({1.0, 1e9}).indices.empty());
    EXPECT_TRUE(lone_values({}).indices.empty());
}

// A 30-sigma spike is lone wherever it is, but worth a warning only where its share reaches kLoneShare: two
// differences of about 30 sigma against n of sqrt(2) sigma each, a share of about 900 / (900 + n).
TEST(LoneValues, TheWarningNeedsItsShareOfTheVariance) {
    for (std::size_t n : {1000u, 100'000u}) {
        std::vector<double> x = white_codes(n, 1.0, 8);
        x[n / 2] = x[n / 2 - 1] / 2.0 + x[n / 2 + 1] / 2.0 + 30.0;
        const LoneValues found = lone_values(x);
        ASSERT_EQ(found.indices.size(), 1u) << n;
        const double expected = 900.0 / (900.0 + static_cast<double>(n));
        EXPECT_NEAR(found.variance_share, expected, 0.35 * expected) << n;
        EXPECT_EQ(found.variance_share >= kLoneShare, n == 1000u) << n;
        EXPECT_EQ(lone_values_warning(times(n), x).has_value(), n == 1000u) << n;
    }
    EXPECT_TRUE(lone_values_warning(times(1000), white_codes(1000, 1.0, 9)) == std::nullopt);
}

TEST(LoneValues, TheWarningNamesEachTimeAndValueUpToFive) {
    std::vector<double> x = white_codes(400, 0.01, 10);
    x[100] = 32767.0;
    const auto one = lone_values_warning(times(400), x);
    ASSERT_TRUE(one);
    EXPECT_EQ(one->rfind("1 lone value (t = 50 s: 32767) carries 100 % of the sample-to-sample variance", 0), 0u)
        << *one;
    // Rows 0.5 s apart: the shortest numbers between 49.5 and 50 and between 50 and 50.5 (49.75 and 50.25 rounded).
    EXPECT_TRUE(one->ends_with("correct that row, or leave it out with --exclude 49.8:50.2")) << *one;
    for (std::size_t k = 110; k <= 160; k += 10) x[k] = -32768.0;
    const auto seven = lone_values_warning(times(400), x);
    ASSERT_TRUE(seven);
    EXPECT_EQ(seven->rfind("7 lone values (t = 50 s: 32767, t = 55 s: -32768, t = 60 s: -32768, t = 65 s: -32768, "
                           "t = 70 s: -32768 and 2 more) carry 100 % of",
                           0),
              0u)
        << *seven;
    EXPECT_TRUE(
        seven->ends_with("leave them out with --exclude 49.8:50.2 --exclude 54.8:55.2 --exclude 59.8:60.2 "
                         "--exclude 64.8:65.2 --exclude 69.8:70.2 and so on"))
        << *seven;
}

// Rows 10 ms apart at Unix time: the time and the window have the digits that tell the row from its neighbours.
TEST(LoneValues, AnEpochTimeNamesOneRow) {
    std::vector<double> t(300), x = white_codes(300, 0.01, 12);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = 1.7e9 + 0.01 * static_cast<double>(k);
    x[123] = 99.0;
    const auto warning = lone_values_warning(t, x);
    ASSERT_TRUE(warning);
    EXPECT_EQ(warning->rfind("1 lone value (t = 1700000001.23 s: 99)", 0), 0u) << *warning;
    EXPECT_TRUE(warning->ends_with("--exclude 1700000001.225:1700000001.235")) << *warning;
}

}  // namespace
}  // namespace driftlab::host::stats
