// The benchmark's other log forms: raw-mode logs, outputs that are codes (window 1) and logs behind a lossy link.
// Each is found and named by the diagnosis, and each comes after the smoothed logs in a run, so adding one changes no
// other log.
#include <gtest/gtest.h>

#include "eval_support.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap_eval/planted_log.hpp"

namespace driftlab::host::gap {
namespace {

// The converter truth: a SAR converter with mismatched bits, planted at 4 x a_50 (0.51 output-noise deviations of
// rms DNL over the codes the log occupies, as detection_sizes() measured it on 1500-sample logs). Its logs are
// raw-mode, so the diagnosis can fit adc_dnl to their code histogram; a log without raw codes could not (not_tried).
TEST(GapEval, AConvertersMismatchIsFoundInTheRawCodesAndAttributedToDnl) {
    EvalOptions o = quick_options();
    o.tune = false;
    o.generators = {"sar_mismatch"};
    o.samples = 1500;
    const auto [planted, right] = planted_and_right(run_cases(o, {{"sar_mismatch", 0.51, {}}}), "adc_dnl");
    EXPECT_EQ(planted, 3);
    EXPECT_GE(right, 2);
}

// The same converter behind outputs of one conversion each (window 1) and no raw column: the outputs are the codes,
// so the codes cells and adc_dnl work on them (4 x a_50, a_50 = 0.14 as detection_sizes() measured it on 1500-sample
// logs).
TEST(GapEval, AConvertersMismatchIsFoundInOutputsThatAreCodes) {
    EvalOptions o = quick_options();
    o.tune = false;
    o.generators = {"sar_codes"};
    o.samples = 1500;
    const auto [planted, right] = planted_and_right(run_cases(o, {{"sar_codes", 0.14, {}}}), "adc_dnl");
    EXPECT_EQ(planted, 3);
    EXPECT_GE(right, 2);
    const Planted p = plant("sar_codes", 0.4, 11, 800);
    EXPECT_EQ(p.log.optional_columns.count("raw_gyro"), 0u);
    EXPECT_EQ(p.log.metadata.get_int("window").value_or(0), 1);
    GapOptions go;
    go.replicates = 16;
    go.explain = false;
    const GapResult r = diagnose(p.log, sim::paper_model(), go);
    EXPECT_TRUE(r.output_codes[0]);
    EXPECT_FALSE(r.raw_codes[0]);
    EXPECT_TRUE(r.not_tried.empty());  // adc_dnl can be tried
}

// Interference that takes frames in episodes (not a Gilbert chain's geometric bursts), beside the calibrated link's
// single corrupted frames: at 4 x a_50 (a_50 = 0.97 % of frames, measured on 1500-sample logs) the diagnosis names
// the bursty loss, and its clean lossy-link logs are mostly left alone.
TEST(GapEval, InterferenceBurstsAreNamedPacketLoss) {
    EvalOptions o = quick_options();
    o.tune = false;
    o.generators = {"interference_bursts"};
    o.samples = 1500;
    o.score_last = o.score_first + 4;
    o.clean_per_seed = 1;
    o.clean_form = CleanForm::lossy_link;
    const auto cases = run_cases(o, {{"interference_bursts", 0.97, {}}});
    int planted = 0, right = 0, clean = 0, flagged = 0;
    for (const auto& c : cases) {
        if (c.generator == "none") {
            ++clean, flagged += decide(c, Thresholds{}).verdict != "none";
            continue;
        }
        ++planted;
        right += decide(c, Thresholds{}).verdict == "packet_loss";
    }
    EXPECT_EQ(planted, 5);
    EXPECT_GE(right, 4);
    EXPECT_EQ(clean, 5);
    EXPECT_LE(flagged, 1);
    EXPECT_EQ(pair_refusal("interference_bursts", "thermal_rc"),
              "interference_bursts acts on the link; pairs act at the converter input");
}

// A supply wander every channel sees is named supply_coupling by reading the four channels together (at 8 x a_50,
// a_50 = 0.26 of the gyro's output noise on 1500-sample logs: the accelerometer axes see it too), and clean
// four-channel logs are mostly left alone.
TEST(GapEval, ASupplyWanderIsReadAcrossTheChannels) {
    EvalOptions o = quick_options();
    o.tune = false;
    o.generators = {"supply_wander"};
    o.levels = {8.0};
    o.samples = 1500;
    o.score_last = o.score_first + 4;
    o.clean_per_seed = 1;
    o.clean_form = CleanForm::four_channels;
    const auto cases = run_cases(o, {{"supply_wander", 0.26, {}}});
    const auto [planted, right] = planted_and_right(cases, "supply_coupling");
    EXPECT_EQ(planted, 5);
    EXPECT_GE(right, 4);
    int clean = 0, flagged = 0;
    for (const auto& c : cases)
        if (c.generator == "none") ++clean, flagged += decide(c, Thresholds{}).verdict != "none";
    EXPECT_EQ(clean, 5);
    EXPECT_LE(flagged, 1);
    EXPECT_EQ(pair_refusal("supply_wander", "thermal_rc"),
              "supply_wander acts on every channel; pairs act on the gyro");
}

// Raw-mode generators' logs are placed after all others, so adding one to a run changes no other log.
TEST(GapEval, ARawModeGeneratorInTheRunChangesNoOtherLog) {
    EvalOptions o = quick_options();
    o.tune = false;
    o.score_last = o.score_first;
    o.samples = 800;
    o.generators = {"mode_hop"};
    const std::vector<DetectionSize> sizes{{"mode_hop", 0.4, {}}, {"sar_mismatch", 1.0, {}}};
    const auto alone = run_cases(o, sizes);
    o.generators = {"sar_mismatch", "mode_hop"};
    const auto both = run_cases(o, sizes);
    ASSERT_EQ(alone.size(), 2u);
    ASSERT_EQ(both.size(), 3u);
    for (std::size_t k = 0; k < alone.size(); ++k) {
        EXPECT_EQ(both[k].generator, alone[k].generator);
        EXPECT_EQ(both[k].seed, alone[k].seed);
        EXPECT_EQ(both[k].detected, alone[k].detected);
        ASSERT_EQ(both[k].tried.size(), alone[k].tried.size());
        for (std::size_t e = 0; e < alone[k].tried.size(); ++e)
            EXPECT_EQ(both[k].tried[e].heldout_after, alone[k].tried[e].heldout_after);
    }
    EXPECT_EQ(both.back().generator, "sar_mismatch");
}

}  // namespace
}  // namespace driftlab::host::gap
