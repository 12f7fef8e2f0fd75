// The converter truth generator of gap-eval: a successive-approximation converter with mismatched bit weights and
// a noisy comparator (truth_sar_mismatch.cpp), checked against the simulator's ideal converter, a code-density
// measurement of its code widths, and the binary carry structure of a SAR's DNL.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap/gap_model.hpp"
#include "host/gap_eval/truth.hpp"
#include "sim/model/adc.hpp"
#include "sim/model/board_outputs.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {
namespace {

// Code widths by code density: a fine uniform ramp of inputs over the inner codes; each code's share of the ramp is
// its width [LSB]. The comparator's noise blurs the edges but keeps each width's mean.
std::vector<double> measured_widths(const sim::Quantiser& q, double step = 0.002) {
    std::vector<double> count(1024, 0.0);
    for (double x = 0.5 + step / 2; x < 1022.5; x += step) count[static_cast<std::size_t>(q(x))] += step;
    return count;
}

double rms_dnl(const std::vector<double>& widths, const std::vector<double>& weight) {
    double sum = 0.0, w = 0.0;
    for (std::size_t j = 1; j < 1023; ++j) {
        const double h = weight.empty() ? 1.0 : weight[j];
        sum += h * (widths[j] - 1.0) * (widths[j] - 1.0);
        w += h;
    }
    return std::sqrt(sum / w);
}

TEST(SarMismatch, WithoutMismatchItIsTheSimulatorsIdealConverter) {
    const sim::Adc adc(sim::paper_model().adc);
    const sim::Quantiser q = make_converter_truth("sar_mismatch", 0.0, {}, 5, 5);
    for (double x = -3.0; x < 1028.0; x += 0.0625) ASSERT_EQ(q(x), adc.convert_counts(x)) << "input " << x;
}

TEST(SarMismatch, ItsCodeWidthsHaveTheRequestedRmsDnl) {
    for (std::uint64_t seed : {1, 2, 3}) {
        const auto widths = measured_widths(make_converter_truth("sar_mismatch", 0.1, {}, seed, seed));
        EXPECT_NEAR(rms_dnl(widths, {}), 0.1, 0.01) << "seed " << seed;
    }
    // Sized over the codes a log occupies: there, not over the whole range.
    std::vector<double> occupancy(1024, 0.0);
    for (int j = 500; j <= 512; ++j) occupancy[static_cast<std::size_t>(j)] = 1.0 + (j % 3);
    const auto widths = measured_widths(make_converter_truth("sar_mismatch", 0.3, occupancy, 4, 4));
    EXPECT_NEAR(rms_dnl(widths, occupancy), 0.3, 0.02);
}

// In a binary-weighted DAC the step from code j to j + 1 sets the bit above j's trailing ones and clears those: its
// width depends on the number of trailing ones alone. So the converter has ten code widths, one per carry depth
// (all even codes alike, all codes ending in 01 alike, ..., code 511 alone), not an independent width per code.
// (While the DAC is monotone: with a carry's error below -1 LSB the search skips codes near it, as a real SAR does.)
TEST(SarMismatch, CodesWithTheSameCarryDepthHaveTheSameWidth) {
    for (std::uint64_t seed : {1, 2}) {
        const auto widths = measured_widths(make_converter_truth("sar_mismatch", 0.1, {}, seed, seed));
        std::vector<double> lowest(10, 1e9), highest(10, -1e9);
        for (int j = 2; j < 1022; ++j) {  // code 1 begins below the ramp
            int depth = 0;
            while (j & (1 << depth)) ++depth;
            lowest[static_cast<std::size_t>(depth)] =
                std::min(lowest[static_cast<std::size_t>(depth)], widths[static_cast<std::size_t>(j)]);
            highest[static_cast<std::size_t>(depth)] =
                std::max(highest[static_cast<std::size_t>(depth)], widths[static_cast<std::size_t>(j)]);
        }
        double min_width = 1e9, max_width = -1e9;
        for (std::size_t d = 0; d < 10; ++d) {
            // Within a depth only the comparator's noise on the edges moves a width (sd about 0.006 LSB at this
            // ramp step, so up to some 0.04 between the extremes of 256 codes).
            EXPECT_LT(highest[d] - lowest[d], 0.05) << "seed " << seed << ", carry depth " << d;
            min_width = std::min(min_width, lowest[d]);
            max_width = std::max(max_width, highest[d]);
        }
        EXPECT_GT(max_width - min_width, 0.1) << "the depths' widths differ (rms 0.1 LSB), seed " << seed;
    }
}

TEST(SarMismatch, TheComparatorMakesCodesNearATransitionRandom) {
    const sim::Quantiser q = make_converter_truth("sar_mismatch", 0.5, {}, 7, 7);
    // Find a transition, then convert an input just at it many times: both codes occur.
    double x = 500.0;
    const int below = q(x);
    while (q(x) == below && x < 520.0) x += 0.001;
    int low = 0, high = 0;
    for (int k = 0; k < 2000; ++k) (q(x) == below ? low : high) += 1;
    EXPECT_GT(low, 100);
    EXPECT_GT(high, 100);
}

TEST(SarMismatch, AnIdealQuantiserInTheChainChangesNothing) {
    GapModel m;
    m.unit = sim::paper_model();
    m.unit.effects.clear();
    m.smoothing = {1.0, 8, 8, 0};
    m.base[0] = {{3.0, 505.0, 400.0}, 1.1};
    std::vector<double> t(300);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k + 1);
    sim::OutputRequest plain;
    plain.t_s = &t;
    plain.channels = {true, false, false, false};
    sim::OutputRequest sar = plain;
    sar.quantiser[0] = make_converter_truth("sar_mismatch", 0.0, {}, 3, 3);
    EXPECT_EQ(sim::simulate_outputs(m, plain, 9)[0], sim::simulate_outputs(m, sar, 9)[0]);
    sar.quantiser[0] = make_converter_truth("sar_mismatch", 0.4, {}, 3, 3);
    EXPECT_NE(sim::simulate_outputs(m, plain, 9)[0], sim::simulate_outputs(m, sar, 9)[0]);
}

TEST(SarMismatch, ASignalGeneratorIsNotAConverterNorTheOtherWayRound) {
    EXPECT_THROW(make_converter_truth("thermal_rc", 0.1, {}, 1, 1), std::invalid_argument);
    EXPECT_THROW(make_truth("sar_mismatch", {1.0, 2.0}, 0.1, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::host::gap
