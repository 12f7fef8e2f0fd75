// The diagnosis's words and report (host/view/gap_view.hpp, gap_phrases.hpp) on logs with planted effects: the report
// explains what was planted and its plots show the gap closing; level steps, sentences and raw codes read right.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../gap/gap_fixtures.hpp"
#include "host/fit/drift_analysis.hpp"
#include "host/gap/calibrate.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap_eval/truth.hpp"
#include "host/stats/spectral.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "host/util/units.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"
#include "host/view/gnuplot.hpp"
#include "plot_data.hpp"
#include "sim/effects/adc_dnl.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {
namespace {

using testing::small_options;

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The report names the verdict and why, lists the added effect with its parameters, marks it among the candidates,
// and plots the residual's mean over time: the planted overshoot lies outside the base simulator's band and inside
// the band with the added effect in most time bins.
TEST(GapReport, TheReportExplainsThePlantedEffectAndItsPlotsShowTheGapClosing) {
    const testing::Planted& p = testing::planted_second_time_constant();
    ASSERT_EQ(p.result.verdict, "thermal_second_tc");
    const auto dir = std::filesystem::temp_directory_path() / "driftlab_gap_report_test";
    std::filesystem::remove_all(dir);
    view::write_gap_report(p.result, p.log, dir.string(), small_options());
    const std::string md = read_text(dir / "gap.md");
    EXPECT_NE(md.find("**Verdict: thermal_second_tc**: on gyro it removes"), std::string::npos) << md.substr(0, 300);
    // The words the tables use are said before them.
    const auto guide = md.find("## How to read this report");
    ASSERT_NE(guide, std::string::npos) << md.substr(0, 600);
    EXPECT_LT(guide, md.find("| | fitting part |"));
    // The settings a reader needs to repeat it, the step limit among them (small_options(): one effect).
    EXPECT_NE(md.find("judged on tenths 1, 2, 3, 6, 8; at most 1 effect added stepwise. "), std::string::npos)
        << md.substr(0, 1500);
    const auto explanation = md.find("## Explanation");
    ASSERT_NE(explanation, std::string::npos);
    EXPECT_NE(md.find("| 1 | thermal_second_tc | gyro | c3_dps=", explanation), std::string::npos);
    std::size_t added = 0;
    for (auto at = md.find("**added**"); at != std::string::npos; at = md.find("**added**", at + 1)) ++added;
    EXPECT_EQ(added, p.result.accepted.size());
    if (!view::gnuplot_available()) GTEST_SKIP() << "gnuplot not on PATH: the plots are not drawn";
    EXPECT_TRUE(std::filesystem::exists(dir / "gap_adev_gyro.png"));
    ASSERT_TRUE(std::filesystem::exists(dir / "gap_mean_gyro.png"));
    std::vector<std::vector<std::vector<double>>> blocks;  // base band, band with the effect, real
    for (int i = 0; i < 3; ++i) blocks.push_back(testing::plot_block(dir / "gap_mean_gyro.dat", i));
    EXPECT_TRUE(testing::plot_block(dir / "gap_mean_gyro.dat", 3).empty());
    const auto& real = blocks[2];
    ASSERT_EQ(real.size(), blocks[0].size());
    int in_base = 0, in_after = 0;
    for (std::size_t b = 0; b < real.size(); ++b) {
        in_base += real[b][1] >= blocks[0][b][2] && real[b][1] <= blocks[0][b][3];
        in_after += real[b][1] >= blocks[1][b][2] && real[b][1] <= blocks[1][b][3];
    }
    const int bins = static_cast<int>(real.size());
    EXPECT_EQ(bins, 50);  // 1500 outputs, about 30 per bin
    EXPECT_LT(in_base, bins / 2) << in_base << " of " << bins;
    EXPECT_GT(in_after, bins * 3 / 4) << in_after << " of " << bins;
    // The plots are in deg/s, at the paper's 90 deg/s over 512 counts: the real residual's ADEV at the first tau is
    // its ADEV in counts times that scale, and the report says the scale.
    const auto adev_real = testing::plot_block(dir / "gap_adev_gyro.dat", 2);
    ASSERT_FALSE(adev_real.empty());
    const auto residual = fit::fit_drift(p.log.t_s, p.log.counts[channel_index(Channel::gyro)]).residual;
    const double adev_counts = stats::octave_oadev(residual, p.log.size() / 8).front();
    EXPECT_NEAR(adev_real[0][1], adev_counts * kGyroDpsPerCount, 1e-4 * adev_counts * kGyroDpsPerCount);
    EXPECT_NE(md.find("one count is 0.176 deg/s on gyro."), std::string::npos);
}

// A mode hop (0.35 counts up at 700 s, 60 % of it back at 1200 s) that a sine closes the battery's gap around: two
// level steps describe the log better than the sine by more than their price, so the verdict is unexplained (a
// level step no library effect makes), the sine staying as a partial explanation, and the steps are reported.
// Only the mean shapes are candidates: with the processes too, a random walk ties with the sine on this log (their
// evidence within 1.2) and, being a process, goes to the level-step test instead (the LevelStep tests).
TEST(GapReport, AHopDrawnAsAShapeIsALevelStepNoLibraryEffectMakes) {
    const GapModel m = testing::paper_gyro_model(8);
    std::vector<double> added(1500, 0.0);
    for (std::size_t k = 0; k < added.size(); ++k) added[k] = (k >= 700 ? 0.35 : 0.0) - (k >= 1200 ? 0.21 : 0.0);
    const LogData log = testing::gyro_log(m, 1500, added, 3);
    GapOptions o = small_options();
    o.explain_options.candidates = {"ambient_cycle", "thermal_second_tc"};
    const GapResult r = diagnose(log, sim::paper_model(), o);
    ASSERT_EQ(r.accepted.size(), 1u);
    EXPECT_EQ(r.accepted[0].effect, "ambient_cycle");
    EXPECT_EQ(r.verdict, "unexplained");
    const StepsOverShape& s = r.accepted[0].shape_steps;
    ASSERT_TRUE(s.steps_win);
    EXPECT_GT(s.statistic, s.margin);
    EXPECT_NEAR(s.steps[0].t_s, 701.0, 40.0);
    EXPECT_NEAR(s.steps[1].t_s, 1201.0, 40.0);
    // Sized jointly with eq. 1's tangent (eq. 1 refitted beside them, linearised): near what was planted, where on
    // the bent residual alone they had come out smaller.
    EXPECT_NEAR(s.steps[0].size_counts, 0.35, 0.08);
    EXPECT_NEAR(s.steps[1].size_counts, -0.21, 0.06);
    const auto j = view::gap_to_json(r, o);
    EXPECT_TRUE(j["explanations"][0]["steps_over_shape"]["steps_win"].get<bool>());
    EXPECT_EQ(view::verdict_reason(r, o).rfind("a hop and a return on gyro", 0), 0u) << view::verdict_reason(r, o);
}

// A raw-mode log's raw codes get the code-histogram cells. A converter whose code widths differ by 0.3 LSB rms
// (the library's adc_dnl, absent from the diagnosis's base) is located there, and explained by the adc_dnl
// candidate's transition table; the ideal converter is not located.
// The verdict's reason follows the level-step test's reading: a step beside a process that remains without it is
// named as that process's outsized increments after the explanation; a step the process only stands in for makes the
// log unexplained and comes first.
TEST(GapReport, TheVerdictReasonReadsALevelStepAsOutsizedIncrementsOrAsNoLibraryEffect) {
    GapResult r;
    r.base.unit = sim::paper_model();  // 90 deg/s over 512 counts: a 1.5-count step is 0.264 deg/s
    Explanation walk;
    walk.effect = "rate_random_walk";
    walk.channel = "gyro";
    walk.heldout_before = 4.0, walk.heldout_after = 1.0, walk.heldout_shrink = 1.0;
    r.accepted.push_back(walk);
    r.gap_after_heldout = 1.0, r.gap_bound_after = 2.0;
    LevelStep s;
    s.tested = true;
    s.steps = {StepEstimate{700.5, 1.5}, StepEstimate{1400.5, -1.5}};
    s.p_value = 0.012;
    s.outsized = true;
    r.level_steps.push_back(s);
    const std::string outsized = view::verdict_reason(r, small_options());
    EXPECT_EQ(outsized.rfind("on gyro it removes 100 %", 0), 0u) << outsized;
    EXPECT_NE(outsized.find("level steps on gyro (1.50 counts (0.264 deg/s) at t = 700.5 s, -1.50 counts (-0.264 "
                            "deg/s) at 1400.5 s; p = 0.012) "
                            "are read as the "
                            "processes' outsized increments"),
              std::string::npos)
        << outsized;
    r.level_steps[0].outsized = false;
    r.level_steps[0].significant = true;
    const std::string unexplained = view::verdict_reason(r, small_options());
    EXPECT_EQ(
        unexplained.rfind(
            "a level step on gyro (1.50 counts (0.264 deg/s) at t = 700.5 s; p = 0.012) that no library effect makes",
            0),
        0u)
        << unexplained;
    EXPECT_EQ(unexplained.find("outsized"), std::string::npos) << unexplained;
}

// Counts in sentences take their noun's number: one cell, one row; two rows.
TEST(GapReport, SentencesSayOneCellAndTwoRows) {
    EXPECT_EQ(counted(1, "cell"), "1 cell");
    EXPECT_EQ(counted(0, "cell"), "0 cells");
    EXPECT_EQ(counted(2, "gap event"), "2 gap events");
    GapResult r;
    r.located.resize(1);
    GapOptions o = small_options();
    o.explain = false;
    EXPECT_EQ(view::verdict_reason(r, o).rfind("1 cell located", 0), 0u) << view::verdict_reason(r, o);
    r.saturated = {{Channel::gyro, 1, 100.0, 100.0}, {Channel::accel_z, 2, 3.0, 4.0}};
    EXPECT_EQ(view::saturated_channels_sentence(r).rfind(
                  "gyro in 1 row at t = 100.0 s, accel_z in 2 rows from t = 3.0 s to 4.0 s:", 0),
              0u)
        << view::saturated_channels_sentence(r);
    r.left_out = {{5, 10.0, 10.5, 1, "--exclude"}, {9, 20.0, 22.0, 2, "--exclude-saturated"}};
    EXPECT_EQ(
        view::left_out_sentence(r).rfind("1 row from t = 10 s to 10.5 s (--exclude), 2 rows from t = 20 s to 22 s "
                                         "(--exclude-saturated): ",
                                         0),
        0u)
        << view::left_out_sentence(r);
}

// A raw-mode gyro log of `m`: the smoothed counts and the raw converter codes of the same samples.
LogData raw_mode_log(const GapModel& m, std::uint64_t seed) {
    LogData log = testing::gyro_log(m, 1500, {}, seed);
    sim::Outputs raw;
    sim::OutputRequest req;
    req.t_s = &log.t_s;
    req.channels = {true, false, false, false};
    req.raw_codes = &raw;
    log.counts[0] = sim::simulate_outputs(m, req, seed)[0];
    log.optional_columns["raw_gyro"] = raw[0];
    return log;
}

// The code-histogram cells of the battery, or only those located.
int codes_cells(const GapResult& r, bool located_only) {
    int n = 0;
    if (located_only) {
        for (const auto& l : r.located) n += r.layout[l.index].statistic == "codes";
    } else {
        for (const auto& c : r.layout) n += c.statistic == "codes";
    }
    return n;
}

// Correlation of the fitted code widths (adjacent transitions "t507_counts", "t508_counts", ...) with the true
// converter's; at least three widths are needed.
double code_width_correlation(const std::vector<std::pair<std::string, double>>& p, const sim::AdcDnl& converter) {
    std::vector<double> fitted_width, true_width;
    for (std::size_t k = 1; k < p.size(); ++k) {
        const int lower = std::stoi(p[k - 1].first.substr(1)), upper = std::stoi(p[k].first.substr(1));
        if (upper != lower + 1) continue;
        fitted_width.push_back(p[k].second - p[k - 1].second);
        true_width.push_back(converter.transition_counts(upper) - converter.transition_counts(lower));
    }
    if (fitted_width.size() < 3) return std::nan("");
    double mf = 0, mt = 0, sft = 0, sff = 0, stt = 0;
    for (std::size_t k = 0; k < fitted_width.size(); ++k) mf += fitted_width[k], mt += true_width[k];
    mf /= static_cast<double>(fitted_width.size());
    mt /= static_cast<double>(true_width.size());
    for (std::size_t k = 0; k < fitted_width.size(); ++k) {
        sft += (fitted_width[k] - mf) * (true_width[k] - mt);
        sff += (fitted_width[k] - mf) * (fitted_width[k] - mf);
        stt += (true_width[k] - mt) * (true_width[k] - mt);
    }
    return sft / std::sqrt(sff * stt);
}

// The report draws the raw codes' shares against the replicate bands: the base's ideal converter misses codes the
// table gets right (the plot is drawn where gnuplot is, which the setup script installs).
void check_codes_plot(const GapResult& r, const LogData& log, const GapOptions& o) {
    if (!view::gnuplot_available()) return;
    const auto dir = std::filesystem::temp_directory_path() / "driftlab_gap_report_dnl_test";
    std::filesystem::remove_all(dir);
    view::write_gap_report(r, log, dir.string(), o);
    ASSERT_TRUE(std::filesystem::exists(dir / "gap_codes_gyro.png"));
    const auto base = testing::plot_block(dir / "gap_codes_gyro.dat", 0),
               after = testing::plot_block(dir / "gap_codes_gyro.dat", 1),
               real = testing::plot_block(dir / "gap_codes_gyro.dat", 2);
    ASSERT_EQ(real.size(), base.size());
    ASSERT_EQ(real.size(), after.size());
    int in_base = 0, in_after = 0;
    for (std::size_t k = 0; k < real.size(); ++k) {
        in_base += real[k][1] >= base[k][2] && real[k][1] <= base[k][3];
        in_after += real[k][1] >= after[k][2] && real[k][1] <= after[k][3];
    }
    // On this log: 3 of the 10 codes within the base's band, 9 within the table's.
    EXPECT_LE(in_base * 2, static_cast<int>(real.size()));
    EXPECT_GE(in_after * 10, static_cast<int>(real.size()) * 8);
}

TEST(GapReport, ARawModeLogsCodeHistogramLocatesAndExplainsDifferentialNonLinearity) {
    GapOptions o = small_options();
    o.explain = false;
    const GapModel ideal = testing::paper_gyro_model(8);
    GapModel dnl = ideal;
    dnl.effects.push_back({"adc_dnl", toml::parse("dnl_rms_lsb = 0.3\npattern_seed = 3")});
    int found = 0;
    for (std::uint64_t seed : {21, 22, 23}) {
        const GapResult clean = diagnose(raw_mode_log(ideal, seed), sim::paper_model(), o);
        EXPECT_EQ(codes_cells(clean, false), 2) << "one per part, gyro only";
        EXPECT_EQ(codes_cells(clean, true), 0) << "seed " << seed;
        found += codes_cells(diagnose(raw_mode_log(dnl, seed), sim::paper_model(), o), true) > 0;
    }
    EXPECT_GE(found, 2);
    // Explained: adc_dnl, its table near the converter's own transitions, and the held-out gap shrinks.
    GapOptions full = small_options();
    const GapResult r = diagnose(raw_mode_log(dnl, 22), sim::paper_model(), full);
    EXPECT_EQ(r.verdict, "adc_dnl");
    ASSERT_FALSE(r.accepted.empty());
    EXPECT_GT(r.accepted[0].heldout_shrink, 0.4);
    sim::AdcDnlParams truth;
    truth.dnl_rms_lsb = 0.3;
    truth.pattern_seed = 3;
    // The table is placed on the smoothed output's scale, which the DNL itself bends (and eq. 1's offset absorbs
    // any common shift), so the code widths are what it must get right: their pattern follows the converter's
    // (correlation over the codes crossed; on this log 0.69/0.80/1.51/0.74/1.26/0.63 against
    // 0.69/0.66/1.38/0.62/0.98/0.56 LSB).
    ASSERT_GE(r.accepted[0].params.size(), 4u);
    EXPECT_GT(code_width_correlation(r.accepted[0].params, sim::AdcDnl(truth)), 0.8);
    EXPECT_TRUE(view::gap_to_json(r, full)["not_tried"].empty()) << "adc_dnl was tried on this raw-mode log";
    check_codes_plot(r, raw_mode_log(dnl, 22), full);
    // Values that are not integral codes are not a raw column: no code cells.
    LogData smoothed = raw_mode_log(ideal, 21);
    smoothed.optional_columns["raw_gyro"] = smoothed.counts[0];
    const GapResult plain = diagnose(smoothed, sim::paper_model(), o);
    EXPECT_EQ(codes_cells(plain, false), 0);
    const auto not_tried = view::gap_to_json(plain, o)["not_tried"];
    ASSERT_EQ(not_tried.size(), 1u);
    EXPECT_EQ(not_tried[0]["effect"], "adc_dnl");
}

}  // namespace
}  // namespace driftlab::host::gap
