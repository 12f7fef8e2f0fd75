// gap-eval's plots: each generator's shares against size, with exact binomial intervals, written for gnuplot.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host/util/error.hpp"
#include "host/view/gap_eval_view.hpp"
#include "host/view/gnuplot.hpp"
#include "plot_data.hpp"

namespace driftlab::host::gap {
namespace {

SizeScore size_score(const std::string& generator, double level, int logs, int detected, int top1) {
    SizeScore z;
    z.generator = generator;
    z.level = level;
    z.logs = logs;
    z.detected = detected;
    z.top1 = top1;
    return z;
}

TEST(EvalPlots, SharesAgainstSizeCarryClopperPearsonIntervals) {
    if (!view::gnuplot_available()) GTEST_SKIP() << "gnuplot not on PATH";
    EvalScores s;
    s.by_size = {size_score("none", 0.0, 40, 2, 38), size_score("thermal_rc", 1.0, 20, 10, 8),
                 size_score("thermal_rc", 2.0, 20, 20, 19), size_score("mode_hop", 1.0, 20, 9, 16),
                 size_score("mode_hop", 2.0, 20, 20, 12)};
    const auto dir = std::filesystem::temp_directory_path() / "driftlab_eval_plots_test";
    std::filesystem::remove_all(dir);
    EXPECT_EQ(view::write_eval_plots(s, dir.string()).size(), 4u);  // two plots, PNG and SVG
    const auto detected = testing::plot_block(dir / "gap_eval_detected.dat", 0);
    ASSERT_EQ(detected.size(), 2u);  // thermal_rc at sizes 1 and 2; the clean row is not a size
    // 10 of 20: the exact 95 % interval is 0.2720-0.7280 (Clopper & Pearson 1934; tabulated).
    EXPECT_DOUBLE_EQ(detected[0][1], 0.5);
    EXPECT_NEAR(detected[0][2], 0.2720, 5e-4);
    EXPECT_NEAR(detected[0][3], 0.7280, 5e-4);
    // 20 of 20: the upper end is 1, the lower (0.025)^(1/20) = 0.8316.
    EXPECT_NEAR(detected[1][2], 0.8316, 5e-4);
    EXPECT_DOUBLE_EQ(detected[1][3], 1.0);
    // The two generators sit a few per cent apart at the same size, thermal_rc left of mode_hop.
    const auto hop = testing::plot_block(dir / "gap_eval_top1.dat", 1);
    ASSERT_EQ(hop.size(), 2u);
    EXPECT_DOUBLE_EQ(hop[1][1], 12.0 / 20.0);
    EXPECT_NEAR(hop[0][0] / detected[0][0], 1.04, 1e-9);
    EXPECT_GT(hop[0][0], 0.9);
    EXPECT_LT(hop[0][0], 1.1);
    // The last block is the target line.
    const auto target = testing::plot_block(dir / "gap_eval_top1.dat", 2);
    ASSERT_EQ(target.size(), 2u);
    EXPECT_DOUBLE_EQ(target[0][1], 0.8);
}

TEST(EvalPlots, ARunThatPlantedNothingHasNoSizeToPlot) {
    EvalScores s;
    s.by_size = {size_score("none", 0.0, 40, 2, 38)};
    EXPECT_THROW(
        view::write_eval_plots(s, (std::filesystem::temp_directory_path() / "driftlab_eval_plots_none").string()),
        UsageError);
}

}  // namespace
}  // namespace driftlab::host::gap
