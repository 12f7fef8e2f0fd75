// E6 adc_dnl: code-density (histogram) test with a uniform input: missing codes never appear, the measured DNL
// has the configured rms, the SAR carry codes carry their extra width, and the pattern belongs to the device.
#include "sim/effects/adc_dnl.hpp"

#include <gtest/gtest.h>

#include "effect_test_support.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {
namespace {

// Histogram of codes for n inputs uniform on [0.5, 1022.5) (the span of the inner codes 1..1022).
std::vector<double> histogram(const AdcDnl& dnl, std::size_t n, std::uint64_t seed) {
    std::vector<double> counts(AdcDnl::kCodeCount, 0.0);
    Rng rng(seed, 0);
    for (std::size_t i = 0; i < n; ++i)
        counts[static_cast<std::size_t>(dnl.code_of(0.5 + 1022.0 * rng.uniform()))] += 1.0;
    return counts;
}

TEST(AdcDnl, MissingCodesNeverAppearAndOthersDo) {
    AdcDnlParams p;
    p.dnl_rms_lsb = 0.1;
    p.missing_codes = {255, 256, 700};
    AdcDnl dnl(p);
    const auto h = histogram(dnl, 2'000'000, 1);
    for (std::size_t code = 1; code <= 1022; ++code) {
        if (code == 255 || code == 256 || code == 700) {
            EXPECT_EQ(h[code], 0.0) << code;
        } else {
            EXPECT_GT(h[code], 0.0) << code;
        }
    }
}

TEST(AdcDnl, HistogramDnlHasTheConfiguredRms) {
    AdcDnlParams p;
    p.dnl_rms_lsb = 0.2;
    AdcDnl dnl(p);
    const std::size_t n = 4'000'000;
    const auto h = histogram(dnl, n, 2);
    const double mean_count = static_cast<double>(n) / 1022.0;
    double s2 = 0.0;
    for (std::size_t code = 1; code <= 1022; ++code) s2 += std::pow(h[code] / mean_count - 1.0, 2);
    s2 /= 1022.0;
    // Measured DNL^2 = true DNL^2 + multinomial noise 1/mean_count; the rms of 1022 draws scatters by
    // 1/sqrt(2 * 1022) = 2.2 % (5 sigmas = 11 %).
    const double rms = std::sqrt(s2 - 1.0 / mean_count);
    EXPECT_NEAR(rms / 0.2, 1.0, 0.11);
}

TEST(AdcDnl, SarCarryCodesAreWiderByTheCarryDnl) {
    AdcDnlParams p;
    p.carry_bits = 6;  // codes 64, 128, ...
    p.carry_dnl_lsb = 0.8;
    AdcDnl dnl(p);
    const std::size_t n = 2'000'000;
    const auto h = histogram(dnl, n, 3);
    // 15 carry codes of width 1.8 and 1007 of width 1 rescaled to keep the span: w = 1022 / (1022 + 15 * 0.8).
    const double scale = 1022.0 / (1022.0 + 15.0 * 0.8);
    const double per_lsb = static_cast<double>(n) / 1022.0;
    double carry_sum = 0.0, other_sum = 0.0;
    for (std::size_t code = 1; code <= 1022; ++code) {
        const double width = h[code] / per_lsb;
        if (code % 64 == 0) {
            carry_sum += width;
            EXPECT_GT(width, 1.5) << code;  // 1.78 expected, binomial sd 0.03
        } else {
            other_sum += width;
        }
    }
    // Means over 15 carry codes (sd 0.03 / sqrt(15)) and 1007 other codes (sd 0.0225 / sqrt(1007)); 5 sigmas.
    EXPECT_NEAR(carry_sum / 15.0, 1.8 * scale, 5.0 * 0.03 / std::sqrt(15.0));
    EXPECT_NEAR(other_sum / 1007.0, scale, 5.0 * 0.0225 / std::sqrt(1007.0));
}

TEST(AdcDnl, PatternDependsOnPatternSeedNotOnRunSeed) {
    AdcDnlParams p;
    p.dnl_rms_lsb = 0.3;
    AdcDnl a(p), b(p);
    a.reset(1);
    b.reset(999);
    p.pattern_seed = 2;
    AdcDnl c(p);
    bool differs = false;
    for (int code = 1; code < AdcDnl::kCodeCount; ++code) {
        EXPECT_EQ(a.transition_counts(code), b.transition_counts(code));
        differs = differs || a.transition_counts(code) != c.transition_counts(code);
    }
    EXPECT_TRUE(differs);
    EXPECT_DOUBLE_EQ(a.transition_counts(1), 0.5);  // ends stay ideal: DNL adds no gain error
    EXPECT_DOUBLE_EQ(a.transition_counts(1023), 1022.5);
}

// A measured table: the listed transitions are where the codes begin; the other codes keep their ideal places.
TEST(AdcDnl, ListedTransitionsReplaceTheIdealOnes) {
    AdcDnlParams p;
    p.transition_codes = {506, 507};
    p.transition_counts = {505.2, 506.9};  // code 505 0.3 LSB narrower, 506 0.2 LSB wider
    AdcDnl dnl(p);
    EXPECT_DOUBLE_EQ(dnl.transition_counts(506), 505.2);
    EXPECT_DOUBLE_EQ(dnl.transition_counts(507), 506.9);
    EXPECT_DOUBLE_EQ(dnl.transition_counts(505), 504.5);
    EXPECT_DOUBLE_EQ(dnl.transition_counts(508), 507.5);
    EXPECT_EQ(dnl.code_of(505.1), 505);
    EXPECT_EQ(dnl.code_of(505.3), 506);
    EXPECT_EQ(dnl.code_of(506.8), 506);
    EXPECT_EQ(dnl.code_of(507.0), 507);
    ChannelValues v = {505.3, 0.0, 0.0, 0.0};
    dnl.apply(v, EffectContext{});
    EXPECT_EQ(v[0], 506.0);  // a table alone makes the effect active
}

TEST(AdcDnl, OutputIsAnIntegralCodeClippedToTheRange) {
    AdcDnlParams p;
    p.dnl_rms_lsb = 0.2;
    AdcDnl dnl(p);
    ChannelValues v = {-40.0, 2000.0, 511.3, 1022.9};
    dnl.apply(v, EffectContext{});
    EXPECT_EQ(v[0], 0.0);
    EXPECT_EQ(v[1], 1023.0);
    EXPECT_EQ(v[2], std::round(v[2]));
    EXPECT_EQ(v[3], 1023.0);
}

}  // namespace
}  // namespace driftlab::sim
