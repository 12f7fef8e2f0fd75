// `driftlab gap` as a user runs it on a log of the full host-in-the-loop chain (native firmware, frames, radio
// link): the diagnosis's in-process replicate chain leaves out frames and link, so a log the simulator made must
// come out with no gap. A plain recording (another logger's table) runs through its column mapping. And bad input
// is refused with a message naming the file.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::e2e {
namespace {

TEST(GapCli, TheSimulatorsOwnHilLogHasNoGap) {
    TempDir dir("gaphil");
    const std::string log = dir.file("hil.csv");
    const RunResult hil = run_driftlab({"hil", "--duration", "1500", "--seed", "3", "-o", log}, dir.path());
    ASSERT_EQ(hil.exit_code, 0) << hil.output;
    const RunResult gap = run_driftlab({"gap", log, "--replicates", "16", "--stability", "6", "--json"}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output);
    EXPECT_EQ(j["verdict"], "none");
    // Logs of the calibrated base itself are flagged at about the family-wise 5 %: most of six are called none.
    EXPECT_EQ(j["stability"]["logs"], 6);
    EXPECT_GE(j["stability"]["verdicts"].value("none", 0), 5) << j["stability"].dump();
    EXPECT_TRUE(j["located"].empty());
    EXPECT_EQ(j["holdout"], "interleaved");
    // All four channels vary (drift and noise) and are analysed; the score is near 1 when nothing is missing.
    EXPECT_LT(j["gap_before"]["fit"].get<double>(), 2.0);
    EXPECT_LT(j["gap_before"]["heldout"].get<double>(), 2.0);
    EXPECT_FALSE(j["diffuse_gap"].get<bool>()) << j["gap_before"].dump();
    // The terminal output says why: nothing located, nothing to explain.
    const RunResult text = run_driftlab({"gap", log, "--replicates", "16"}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("verdict: none (no cell located and the held-out score within its bound"),
              std::string::npos)
        << text.output;
}

// A unit behind a lossy radio (bursts of frames lost towards the board's host, corrupted bytes both ways, so polls
// go unanswered too), diagnosed against the paper's lossless link: its channels agree, its link does not, and the
// verdict names the bursty loss with the chain's parameters. Written out and given back, the link agrees.
TEST(GapCli, ABurstyLinkIsNamedAndItsFittedLinkWrittenBack) {
    TempDir dir("gaplink");
    const std::string log = dir.file("radio.csv");
    const RunResult hil =
        run_driftlab({"hil", "--model", std::string(DRIFTLAB_SOURCE_DIR) + "/sim/models/lossy_radio.toml", "--duration",
                      "1500", "--seed", "3", "-o", log},
                     dir.path());
    ASSERT_EQ(hil.exit_code, 0) << hil.output;
    const RunResult gap =
        run_driftlab({"gap", log, "--replicates", "16", "--model-out", dir.file("fitted.toml"), "--json"}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output.substr(gap.output.find('{')));
    EXPECT_EQ(j["verdict"], "packet_loss") << j["link"].dump();
    EXPECT_TRUE(j["located"].empty());
    const auto& link = j["link"];
    EXPECT_GT(link["lost"].get<int>(), 20);
    EXPECT_FALSE(link["located"].empty());
    bool added = false;
    for (const auto& c : link["candidates"]) {
        if (!c["added"].get<bool>()) continue;
        added = true;
        EXPECT_EQ(c["effect"], "packet_loss");
        // The unit loses 2 % in bursts of 4 (p 0.0051, r 0.25) and about 1 % more to corrupted bytes: the chain
        // fitted to both reads a loss near 3-4 % in shorter bursts.
        const double p = c["params_whole_log"]["p_good_to_bad"], r = c["params_whole_log"]["p_bad_to_good"];
        EXPECT_NEAR(p / (p + r), 0.035, 0.015);
        EXPECT_GT(r, 0.2);
        EXPECT_GT(c["params_whole_log"]["polls_unanswered"].get<double>(), 0.0);  // polled: requests lost too
    }
    EXPECT_TRUE(added) << link.dump();
    const RunResult again =
        run_driftlab({"gap", log, "--replicates", "16", "--model", dir.file("fitted.toml"), "--json"}, dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    const auto k = nlohmann::json::parse(again.output.substr(again.output.find('{')));
    EXPECT_TRUE(k["link"]["located"].empty()) << k["link"].dump();
    EXPECT_EQ(k["verdict"], "none");
}

// A log of `model_toml` (a model file's text) simulated by hil for 1500 s with `seed`, at `dir`/`name`.csv.
std::string simulate_unit(const TempDir& dir, const std::string& name, const std::string& model_toml, int seed) {
    std::ofstream(dir.file(name + ".toml")) << model_toml;
    const std::string log = dir.file(name + ".csv");
    const RunResult hil = run_driftlab(
        {"hil", "--model", dir.file(name + ".toml"), "--duration", "1500", "--seed", std::to_string(seed), "-o", log},
        dir.path());
    EXPECT_EQ(hil.exit_code, 0) << hil.output;
    return log;
}

// A unit whose supply wanders (Gauss-Markov, 150 s) into every channel by about 0.2 % of its DC level: read
// channel by channel it looks like a process on each; read together, one supply wander with loadings that follow the
// DC levels. Written out and given back, nothing is located.
TEST(GapCli, ASupplyWanderInEveryChannelIsNamedOnceAndItsWanderWrittenBack) {
    TempDir dir("gapsupply");
    const std::string log = simulate_unit(dir, "wander",
                                          "[effects.supply_coupling]\n"
                                          "pickup_v_per_v = [0.0986, 0.0918, 0.0926, 0.1215]\n"
                                          "wander_v = 0.05\nwander_tau_s = 150.0\n",
                                          3);
    const RunResult gap =
        run_driftlab({"gap", log, "--replicates", "16", "--model-out", dir.file("fitted.toml"), "--json"}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output.substr(gap.output.find('{')));
    EXPECT_EQ(j["verdict"], "supply_coupling") << j["common"].dump();
    const auto& common = j["common"];
    EXPECT_EQ(common["chosen"], "supply_coupling");
    EXPECT_FALSE(common["shared_cells"].empty());
    for (const auto& r : common["readings"]) {
        if (r["reading"] != "supply_coupling") continue;
        // 0.05 V x about 0.1 V/V over a channel DC level near 2.5 V: about 0.2 %, read from one 1500 s path of a
        // 150 s process.
        EXPECT_GT(r["relative_sd"].get<double>(), 0.0005);
        EXPECT_LT(r["relative_sd"].get<double>(), 0.004);
        EXPECT_GT(r["tau_s"].get<double>(), 50.0);
        EXPECT_LT(r["tau_s"].get<double>(), 450.0);
    }
    const RunResult again =
        run_driftlab({"gap", log, "--replicates", "16", "--model", dir.file("fitted.toml"), "--json"}, dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    const auto k = nlohmann::json::parse(again.output.substr(again.output.find('{')));
    EXPECT_EQ(k["verdict"], "none") << k["located"].dump();
}

// The terminal of a gap run that found the cycle: the verdict and its shrink, the candidates in step order, the 15
// largest located cells and a count of the rest (returned); the stability logs each read the cycle again.
std::size_t check_cycle_terminal(const std::string& out) {
    EXPECT_NE(out.find("verdict: ambient_cycle (on gyro it removes "), std::string::npos) << out;
    // Its shrink is the gyro's own held-out score's, which the line says, beside the whole log's in the gap line.
    EXPECT_NE(out.find(" % of gyro's own held-out gap excess (gyro's held-out score "), std::string::npos) << out;
    const std::size_t candidates = out.find("\ncandidates (");
    EXPECT_NE(candidates, std::string::npos) << out;
    EXPECT_EQ(out.find("\n  1 ambient_cycle      gyro     ADDED", candidates), out.find('\n', candidates + 1)) << out;
    const std::size_t at = out.find("located cells (|z| > ");
    if (at == std::string::npos) {
        ADD_FAILURE() << out;
        return 0;
    }
    const std::size_t located = std::stoul(out.substr(out.find("): ", at) + 3));
    EXPECT_GT(located, 15u) << out;
    EXPECT_NE(out.find("  ... and " + std::to_string(located - 15) + " more with smaller |z|"), std::string::npos)
        << out;
    // A cycle this clear is read again in every log the fitted model makes, each near the unit's 400 s period.
    EXPECT_NE(
        out.find(
            "of 3 logs simulated from the estimated model and diagnosed alike, 3 (100 %) are called ambient_cycle"),
        std::string::npos)
        << out;
    const std::size_t spread = out.find("ambient_cycle on gyro (3 of 3 logs): amplitude_dps ");
    double estimate = 0.0, low = 0.0, high = 0.0, median = 0.0;
    EXPECT_EQ(spread == std::string::npos
                  ? 0
                  : std::sscanf(out.c_str() + out.find("period_s ", spread), "period_s %lf -> %lf to %lf (median %lf)",
                                &estimate, &low, &high, &median),
              4)
        << out;
    EXPECT_NEAR(estimate, 400.0, 20.0);
    EXPECT_LE(low, median);
    EXPECT_LE(median, high);
    EXPECT_NEAR(low, 400.0, 20.0);
    EXPECT_NEAR(high, 400.0, 20.0);
    return located;
}

// The report lists every located cell (the terminal only the largest) and the stability logs' estimates.
void check_cycle_report(const std::string& md_path, std::size_t located) {
    std::ifstream report(md_path);
    const std::string md((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    const std::size_t table = md.find("## Where: located cells");
    ASSERT_NE(table, std::string::npos) << md.substr(0, 600);
    std::size_t rows = 0;
    for (std::size_t line = md.find("\n| ", table); line < md.find("cells located before", table);
         line = md.find("\n| ", line + 1))
        ++rows;
    EXPECT_EQ(rows, located + 1) << md.substr(table, 3000);  // and the header row
    EXPECT_NE(md.find("Estimates on those logs (middle 68 %, where each added the effect again):\n\n- ambient_cycle on "
                      "gyro (3 of 3 logs)"),
              std::string::npos)
        << md.substr(0, 1500);
}

// The model file holds the cycle, says how sure its estimates are, and keeps the calibrated base near the unit's.
void check_fitted_model(const std::string& path) {
    std::ifstream file(path);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("#   ambient_cycle on gyro (3 of 3 logs): amplitude_dps "), std::string::npos)
        << text.substr(0, 1200);
    const sim::SimModel fitted = sim::load_model_file(path);
    const sim::SimModel paper = sim::paper_model();
    ASSERT_FALSE(fitted.effects.empty());
    EXPECT_EQ(fitted.effects[0].name, "ambient_cycle");
    EXPECT_NEAR(fitted.effects[0].table["period_s"].value_or(0.0), 400.0, 20.0);
    // Amplitude in deg/s: coupling times half the peak-to-peak swing, 0.05 for the unit.
    EXPECT_NEAR(fitted.effects[0].table["coupling_dps_per_k"].value_or(0.0) *
                    fitted.effects[0].table["amplitude_k_pp"].value_or(0.0) / 2.0,
                0.05, 0.005);
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        EXPECT_NEAR(fitted.channels[i].drift.c2_counts, paper.channels[i].drift.c2_counts, 1.0) << kChannelNames[i];
        EXPECT_NEAR(fitted.channels[i].raw_noise_std_unit / paper.channels[i].raw_noise_std_unit, 1.0, 0.1)
            << kChannelNames[i];
    }
    EXPECT_EQ(std::memcmp(&fitted.firmware, &paper.firmware, sizeof paper.firmware), 0) << "the log's own smoothing";
}

// The loop a user closes: a unit with a thermal cycle the simulator's base lacks (on the gyro: 0.05 deg/s per K of a
// 2 K, 400 s sine), its log diagnosed with --model-out, and that file simulated by hil. The file holds the cycle
// and the calibrated base near the unit's own values, and a log simulated from it reads as the unit's did.
TEST(GapCli, TheModelFileOutSimulatesTheUnitTheLogCameFrom) {
    TempDir dir("gapmodelout");
    const std::string cycle =
        "[effects.ambient_cycle]\nwaveform = \"sine\"\namplitude_k_pp = 2.0\nperiod_s = 400.0\nlag_s = 0.0\n";
    const std::string unit = simulate_unit(dir, "unit", cycle + "coupling_dps_per_k = 0.05\n", 3);
    const RunResult gap = run_driftlab({"gap", unit, "--replicates", "16", "--model-out", dir.file("fitted.toml"),
                                        "--stability", "3", "--report", dir.file("report")},
                                       dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const std::size_t located = check_cycle_terminal(gap.output);
    check_cycle_report(dir.file("report/gap.md"), located);
    EXPECT_NE(gap.output.find("model file: " + dir.file("fitted.toml")), std::string::npos) << gap.output;
    check_fitted_model(dir.file("fitted.toml"));

    // Given back to gap as the unit, on a log of the same unit whose cycle has another phase (another power-on), the
    // file's cycle is refitted to that log and nothing is missing.
    const std::string later = simulate_unit(dir, "later", cycle + "phase_rad = 2.0\ncoupling_dps_per_k = 0.05\n", 5);
    const RunResult as_unit =
        run_driftlab({"gap", later, "--replicates", "16", "--model", dir.file("fitted.toml"), "--json"}, dir.path());
    ASSERT_EQ(as_unit.exit_code, 0) << as_unit.output;
    const auto u = nlohmann::json::parse(as_unit.output);
    EXPECT_EQ(u["verdict"], "none") << u["located"].dump();
    ASSERT_EQ(u["given"]["refitted"].size(), 1u) << u["given"].dump();
    EXPECT_EQ(u["given"]["refitted"][0]["effect"], "ambient_cycle");
    EXPECT_NEAR(u["given"]["refitted"][0]["params"]["period_s"].get<double>(), 400.0, 20.0);
    EXPECT_NEAR(u["given"]["refitted"][0]["params"]["phase_rad"].get<double>(), 2.0, 0.3);

    const std::string again = dir.file("again.csv");
    ASSERT_EQ(
        run_driftlab({"hil", "--model", dir.file("fitted.toml"), "--duration", "1500", "--seed", "4", "-o", again},
                     dir.path())
            .exit_code,
        0);
    const RunResult diagnosed = run_driftlab({"gap", again, "--replicates", "16", "--json"}, dir.path());
    ASSERT_EQ(diagnosed.exit_code, 0) << diagnosed.output;
    const auto j = nlohmann::json::parse(diagnosed.output);
    EXPECT_EQ(j["verdict"], "ambient_cycle");
    EXPECT_NEAR(j["explanations"][0]["params"]["period_s"].get<double>(), 400.0, 20.0) << j["explanations"].dump();
}

// Fig. 2's log: raw mode (a RAW frame per SAMPLE), 100 s of an already warm unit. Its raw codes give the code
// histogram cells and let adc_dnl be tried; a flat log's eq. 1 fit runs off to a huge T, which the calibration
// bounds without turning the base into a ramp (it once did, and the frac cells were located).
TEST(GapCli, TheSimulatorsOwnRawModeLogOfAWarmUnitHasNoGap) {
    TempDir dir("gapfig2");
    const std::string log = dir.file("fig2.csv");
    const RunResult hil = run_driftlab({"hil", "--preset", "fig2", "-o", log}, dir.path());
    ASSERT_EQ(hil.exit_code, 0) << hil.output;
    const RunResult gap = run_driftlab({"gap", log, "--replicates", "20", "--stability", "3", "--json"}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output);
    EXPECT_EQ(j["verdict"], "none") << j["located"].dump();
    // The simulated logs carry raw codes too (their code histograms are compared): the base's own read as none.
    EXPECT_GE(j["stability"]["verdicts"].value("none", 0), 2) << j["stability"].dump();
    EXPECT_TRUE(j["not_tried"].empty()) << "the raw codes were read: adc_dnl is a candidate here";
}

// A third-party recording: one column of rate values at 8.75 mdps resolution, 100 Hz, a warm-up and white noise.
TEST(GapCli, APlainRecordingRunsThroughItsColumnMapping) {
    TempDir dir("gapplain");
    const std::string table = dir.file("rate.txt");
    {
        std::ofstream out(table);
        std::mt19937 rng(5);
        std::normal_distribution<double> noise(0.0, 0.2);
        for (int k = 0; k < 24000; ++k)
            out << 0.00875 * std::round((0.5 * (1.0 - std::exp(-k * 0.01 / 60.0)) + noise(rng)) / 0.00875) << "\n";
    }
    const RunResult gap = run_driftlab({"gap", table, "--tau0", "0.01", "--as", "gyro=col1:0.00875", "--block", "40",
                                        "--replicates", "12", "--locate-only", "--json"},
                                       dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    const auto j = nlohmann::json::parse(gap.output);
    EXPECT_EQ(j["verdict"], "none");                           // --locate-only: nothing is explained
    EXPECT_TRUE(j["located"].empty()) << j["located"].dump();  // white noise on eq. 1's own shape: no gap
    // Only the mapped channel varies and is analysed; the blocks are the smoother. The others are not in the
    // recording, so they are not reported as stuck.
    EXPECT_EQ(j["calibration"]["channels"].size(), 1u) << j["calibration"].dump();
    EXPECT_TRUE(j["constant_channels"].empty()) << j["constant_channels"].dump();
    EXPECT_EQ(j["calibration"]["window"], 40);
    EXPECT_DOUBLE_EQ(j["calibration"]["sample_period_s"].get<double>(), 0.4);

    // A model file of this unit needs a firmware that smooths as the log did: 12.5 ms is no whole millisecond.
    const RunResult odd = run_driftlab(
        {"gap", table, "--tau0", "0.0125", "--as", "gyro=col1:0.00875", "--model-out", dir.file("m.toml")}, dir.path());
    EXPECT_EQ(odd.exit_code, 3) << odd.output;
    EXPECT_NE(odd.output.find("rate.txt: --model-out: the log's smoothing (output period 12.5 ms"), std::string::npos)
        << odd.output;
    EXPECT_EQ(odd.output.find("verdict"), std::string::npos) << "refused before the diagnosis";

    const RunResult unrecorded =
        run_driftlab({"gap", table, "--tau0", "0.01", "--as", "gyro=col1:0.00875", "--channel", "accel_x"}, dir.path());
    EXPECT_EQ(unrecorded.exit_code, 2) << unrecorded.output;
    EXPECT_NE(unrecorded.output.find("--channel accel_x: " + table + " does not record it"), std::string::npos)
        << unrecorded.output;
    const RunResult unknown =
        run_driftlab({"gap", table, "--tau0", "0.01", "--as", "gyro=col1:0.00875", "--channel", "accel"}, dir.path());
    EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("--channel: unknown channel 'accel' (gyro, accel_x, accel_y, accel_z)"),
              std::string::npos)
        << unknown.output;

    const RunResult unmapped = run_driftlab({"gap", table}, dir.path());
    EXPECT_EQ(unmapped.exit_code, 2);
    EXPECT_NE(unmapped.output.find("--as CHANNEL=COLUMN:LSB"), std::string::npos) << unmapped.output;
    const RunResult wrong = run_driftlab({"gap", table, "--tau0", "0.01", "--as", "gyro=gx:0.00875"}, dir.path());
    EXPECT_EQ(wrong.exit_code, 2);
    EXPECT_NE(wrong.output.find("col1"), std::string::npos) << wrong.output;  // names the columns there are
}

}  // namespace
}  // namespace driftlab::e2e
