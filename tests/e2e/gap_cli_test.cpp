// `driftlab gap` as a user runs it on a log of the full host-in-the-loop chain (native firmware, frames, radio
// link): the diagnosis's in-process replicate chain leaves out frames and link, so a log the simulator made must
// come out with no gap. A plain recording (another logger's table) runs through its column mapping. And bad input
// is refused with a message naming the file.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"
#include "host/gap_eval/truth.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::e2e {
namespace {

// Copies the hil log `from` to `to` with `edit` given each data row's fields (t_s, seq, gyro, accel_x, accel_y,
// accel_z, tick, sat_flags, ...) and its index from 0; metadata and the header as they are.
void copy_log_editing_rows(const std::string& from, const std::string& to,
                           const std::function<void(std::vector<std::string>& fields, int row)>& edit) {
    std::ifstream in(from);
    std::ofstream out(to);
    int row = 0;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line[0] != '#' && line.rfind("t_s,", 0) != 0) {
            std::vector<std::string> f;
            std::stringstream fields(line);
            for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
            edit(f, row++);
            line.clear();
            for (const auto& x : f) line += (line.empty() ? "" : ",") + x;
        }
        out << line << "\n";
    }
}

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

// The loop a user closes: a unit with a thermal cycle the simulator's base lacks (on the gyro: 0.05 deg/s per K of a
// 2 K, 400 s sine), its log diagnosed with --model-out, and that file simulated by hil. The file holds the cycle
// and the calibrated base near the unit's own values, and a log simulated from it reads as the unit's did.
TEST(GapCli, TheModelFileOutSimulatesTheUnitTheLogCameFrom) {
    TempDir dir("gapmodelout");
    {
        std::ofstream(dir.file("unit.toml"))
            << "[effects.ambient_cycle]\nwaveform = \"sine\"\namplitude_k_pp = 2.0\nperiod_s = 400.0\n"
               "lag_s = 0.0\ncoupling_dps_per_k = 0.05\n";
    }
    ASSERT_EQ(run_driftlab({"hil", "--model", dir.file("unit.toml"), "--duration", "1500", "--seed", "3", "-o",
                            dir.file("unit.csv")},
                           dir.path())
                  .exit_code,
              0);
    const RunResult gap = run_driftlab({"gap", dir.file("unit.csv"), "--replicates", "16", "--model-out",
                                        dir.file("fitted.toml"), "--stability", "3", "--report", dir.file("report")},
                                       dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    EXPECT_NE(gap.output.find("verdict: ambient_cycle (on gyro it removes "), std::string::npos) << gap.output;
    // Its shrink is the gyro's own held-out score's, which the line says, beside the whole log's in the gap line.
    EXPECT_NE(gap.output.find(" % of gyro's own held-out gap excess (gyro's held-out score "), std::string::npos)
        << gap.output;
    // The candidate list starts with the effects added, in step order.
    const std::size_t candidates = gap.output.find("\ncandidates (");
    ASSERT_NE(candidates, std::string::npos) << gap.output;
    EXPECT_EQ(gap.output.find("\n  1 ambient_cycle      gyro     ADDED", candidates),
              gap.output.find('\n', candidates + 1))
        << gap.output;
    // The cycle locates more cells than the terminal lists: it shows the 15 largest and counts the rest; the report
    // lists every one.
    const std::size_t at = gap.output.find("located cells (|z| > ");
    ASSERT_NE(at, std::string::npos) << gap.output;
    const std::size_t located = std::stoul(gap.output.substr(gap.output.find("): ", at) + 3));
    ASSERT_GT(located, 15u) << gap.output;
    EXPECT_NE(gap.output.find("  ... and " + std::to_string(located - 15) + " more with smaller |z|"),
              std::string::npos)
        << gap.output;
    {
        std::ifstream report(dir.file("report/gap.md"));
        const std::string md((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
        const std::size_t table = md.find("## Where: located cells");
        ASSERT_NE(table, std::string::npos) << md.substr(0, 600);
        std::size_t rows = 0;
        for (std::size_t line = md.find("\n| ", table); line < md.find("cells located before", table);
             line = md.find("\n| ", line + 1))
            ++rows;
        EXPECT_EQ(rows, located + 1) << md.substr(table, 3000);  // and the header row
        // The report shows the stability logs' estimates under the terminal's heading, as a list.
        const std::size_t heading = md.find(
            "Estimates on those logs (middle 68 %, where each added the effect again):\n\n- ambient_cycle on gyro (3 "
            "of 3 logs)");
        EXPECT_NE(heading, std::string::npos) << md.substr(0, 1500);
    }
    // A cycle this clear is read again in every log the fitted model makes.
    EXPECT_NE(
        gap.output.find(
            "of 3 logs simulated from the estimated model and diagnosed alike, 3 (100 %) are called ambient_cycle"),
        std::string::npos)
        << gap.output;
    // Each of them estimates the cycle's period again near the model's, the unit's 400 s.
    const std::size_t spread = gap.output.find("ambient_cycle on gyro (3 of 3 logs): amplitude_dps ");
    ASSERT_NE(spread, std::string::npos) << gap.output;
    double estimate = 0.0, low = 0.0, high = 0.0, median = 0.0;
    ASSERT_EQ(std::sscanf(gap.output.c_str() + gap.output.find("period_s ", spread),
                          "period_s %lf -> %lf to %lf (median %lf)", &estimate, &low, &high, &median),
              4)
        << gap.output;
    EXPECT_NEAR(estimate, 400.0, 20.0);
    EXPECT_LE(low, median);
    EXPECT_LE(median, high);
    EXPECT_NEAR(low, 400.0, 20.0);
    EXPECT_NEAR(high, 400.0, 20.0);
    EXPECT_NE(gap.output.find("model file: " + dir.file("fitted.toml")), std::string::npos) << gap.output;
    {
        // The file says how sure its estimates are, when --stability ran.
        std::ifstream file(dir.file("fitted.toml"));
        const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        EXPECT_NE(text.find("#   ambient_cycle on gyro (3 of 3 logs): amplitude_dps "), std::string::npos)
            << text.substr(0, 1200);
    }
    const sim::SimModel fitted = sim::load_model_file(dir.file("fitted.toml"));
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

    // Given back to gap as the unit, on a log of the same unit whose cycle has another phase (another power-on), the
    // file's cycle is refitted to that log and nothing is missing.
    {
        std::ofstream(dir.file("later.toml"))
            << "[effects.ambient_cycle]\nwaveform = \"sine\"\namplitude_k_pp = 2.0\nperiod_s = 400.0\n"
               "lag_s = 0.0\nphase_rad = 2.0\ncoupling_dps_per_k = 0.05\n";
    }
    ASSERT_EQ(run_driftlab({"hil", "--model", dir.file("later.toml"), "--duration", "1500", "--seed", "5", "-o",
                            dir.file("later.csv")},
                           dir.path())
                  .exit_code,
              0);
    const RunResult as_unit = run_driftlab(
        {"gap", dir.file("later.csv"), "--replicates", "16", "--model", dir.file("fitted.toml"), "--json"}, dir.path());
    ASSERT_EQ(as_unit.exit_code, 0) << as_unit.output;
    const auto u = nlohmann::json::parse(as_unit.output);
    EXPECT_EQ(u["verdict"], "none") << u["located"].dump();
    ASSERT_EQ(u["given"]["refitted"].size(), 1u) << u["given"].dump();
    EXPECT_EQ(u["given"]["refitted"][0]["effect"], "ambient_cycle");
    EXPECT_NEAR(u["given"]["refitted"][0]["params"]["period_s"].get<double>(), 400.0, 20.0);
    EXPECT_NEAR(u["given"]["refitted"][0]["params"]["phase_rad"].get<double>(), 2.0, 0.3);

    ASSERT_EQ(run_driftlab({"hil", "--model", dir.file("fitted.toml"), "--duration", "1500", "--seed", "4", "-o",
                            dir.file("again.csv")},
                           dir.path())
                  .exit_code,
              0);
    const RunResult again = run_driftlab({"gap", dir.file("again.csv"), "--replicates", "16", "--json"}, dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    const auto j = nlohmann::json::parse(again.output);
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

// A recorded channel that never changes (a stuck or unconnected sensor) has no noise to compare: it is left out of
// the diagnosis and named, rather than silently dropped; selected alone, it is refused with its value. Rows the
// firmware flagged saturated (sat_flags) are counted for the analysed channels.
TEST(GapCli, AStuckChannelIsNamedAndSaturatedRowsAreCounted) {
    TempDir dir("gapstuck");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "400", "--seed", "4", "-o", log}, dir.path()).exit_code, 0);
    const std::string stuck = dir.file("stuck.csv");
    copy_log_editing_rows(log, stuck, [](std::vector<std::string>& f, int row) {
        f[3] = "512";
        if (row >= 99 && row < 104) f[7] = "10";  // accel_x (not analysed) and accel_z saturated
    });
    const RunResult text =
        run_driftlab({"gap", stuck, "--replicates", "10", "--locate-only", "--report", dir.file("report")}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("not analysed: accel_x at 512 counts in every row: a channel that never changes"),
              std::string::npos)
        << text.output;
    EXPECT_NE(text.output.find("saturated: accel_z in 5 rows from t = 100.1 s to 104.1 s"), std::string::npos)
        << text.output;
    std::ifstream report(dir.file("report/gap.md"));
    const std::string md((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    EXPECT_NE(md.find("Not analysed: accel_x at 512 counts in every row"), std::string::npos) << md.substr(0, 600);
    EXPECT_NE(md.find("Saturated: accel_z in 5 rows"), std::string::npos) << md.substr(0, 900);
    // The plots' scales, at the paper's 90 deg/s and 1 g over 512 counts; the constant channel has none.
    EXPECT_NE(md.find("one count is 0.176 deg/s on gyro, 1.95 mg on accel_y, 1.95 mg on accel_z."), std::string::npos);
    const RunResult json = run_driftlab({"gap", stuck, "--replicates", "10", "--locate-only", "--json"}, dir.path());
    ASSERT_EQ(json.exit_code, 0) << json.output;
    const auto j = nlohmann::json::parse(json.output);
    ASSERT_EQ(j["constant_channels"].size(), 1u) << j["constant_channels"].dump();
    EXPECT_EQ(j["constant_channels"][0]["channel"], "accel_x");
    EXPECT_DOUBLE_EQ(j["constant_channels"][0]["counts"].get<double>(), 512.0);
    EXPECT_FALSE(j["calibration"]["channels"].contains("accel_x")) << j["calibration"].dump();
    EXPECT_EQ(j["calibration"]["channels"].size(), 3u) << j["calibration"].dump();
    ASSERT_EQ(j["saturated"].size(), 1u) << j["saturated"].dump();
    EXPECT_EQ(j["saturated"][0]["channel"], "accel_z");
    EXPECT_EQ(j["saturated"][0]["rows"], 5);
    EXPECT_NEAR(j["saturated"][0]["first_t_s"].get<double>(), 100.1, 0.5);  // the 100th row, at 1 s per row
    EXPECT_NEAR(j["saturated"][0]["last_t_s"].get<double>(), 104.1, 0.5);
    // The user leaves the disturbed start out: from 110 s on nothing is flagged.
    const SplitRun later = run_driftlab_split({"gap", stuck, "--replicates", "10", "--locate-only", "--json", "--from",
                                               "110", "--model-out", dir.file("later.toml")},
                                              dir.path());
    ASSERT_EQ(later.exit_code, 0) << later.err;
    EXPECT_TRUE(nlohmann::json::parse(later.out)["saturated"].empty()) << later.out;
    // What the range kept, beside the JSON as fit and allan say it (rows 1 s apart from 1.098 s to 400.098 s).
    EXPECT_EQ(later.err, "note: --from 110 kept 291 of 400 rows, t = 110.098 s to 400.098 s\n");
    {
        std::ifstream file(dir.file("later.toml"));
        std::string first;
        std::getline(file, first);
        EXPECT_EQ(first.rfind("# driftlab gap " + stuck + " (rows from 110.098 s to 400.098 s): verdict ", 0), 0u)
            << first;  // the rows it came from
    }
    // Spelled as fit's --t-min/--t-max, the same range.
    const RunResult outside = run_driftlab({"gap", stuck, "--t-min", "500", "--t-max", "600"}, dir.path());
    EXPECT_EQ(outside.exit_code, 3) << outside.output;
    EXPECT_NE(outside.output.find("stuck.csv: no row lies between 500 s and 600 s (its rows run from "),
              std::string::npos)
        << outside.output;
    EXPECT_EQ(run_driftlab({"gap", stuck, "--from", "300", "--to", "200"}, dir.path()).exit_code, 2);
    // Channels not selected are not reported; the stuck one selected alone leaves nothing to compare.
    const RunResult gyro =
        run_driftlab({"gap", stuck, "--replicates", "10", "--locate-only", "--json", "--channel", "gyro"}, dir.path());
    ASSERT_EQ(gyro.exit_code, 0) << gyro.output;
    EXPECT_TRUE(nlohmann::json::parse(gyro.output)["constant_channels"].empty());
    const RunResult alone = run_driftlab({"gap", stuck, "--channel", "accel_x"}, dir.path());
    EXPECT_EQ(alone.exit_code, 3) << alone.output;
    EXPECT_NE(alone.output.find("stuck.csv: no selected channel varies (accel_x at 512 counts in every row)"),
              std::string::npos)
        << alone.output;
}

// A shock in the middle of a log (ten rows thrown off and flagged saturated) is a gap the simulator cannot make;
// --exclude leaves it out, the rows either side are joined, and the join is not read as lost frames.
TEST(GapCli, AShockInTheMiddleIsLeftOutWithExclude) {
    TempDir dir("gapshock");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "600", "--seed", "4", "-o", log}, dir.path()).exit_code, 0);
    const std::string shock = dir.file("shock.csv");
    double shock_from = 0.0, shock_to = 0.0;
    copy_log_editing_rows(log, shock, [&](std::vector<std::string>& f, int row) {
        if (row < 300 || row >= 310) return;
        f[2] = std::to_string(std::stod(f[2]) + 150.0);
        f[7] = "1";
        if (row == 300) shock_from = std::stod(f[0]);
        shock_to = std::stod(f[0]);
    });
    const RunResult with = run_driftlab({"gap", shock, "--replicates", "10", "--locate-only", "--json"}, dir.path());
    ASSERT_EQ(with.exit_code, 0) << with.output;
    const auto j = nlohmann::json::parse(with.output);
    EXPECT_FALSE(j["located"].empty());
    ASSERT_EQ(j["saturated"].size(), 1u) << j["saturated"].dump();
    EXPECT_EQ(j["saturated"][0]["rows"], 10);
    EXPECT_TRUE(j["left_out"].empty());
    // Left out (with a second left at the log's start): nothing located, nothing saturated, no frame lost.
    const std::string window = std::to_string(shock_from - 0.5) + ":" + std::to_string(shock_to + 0.5);
    const RunResult without = run_driftlab({"gap", shock, "--replicates", "10", "--locate-only", "--json", "--exclude",
                                            window, "--exclude", "0:1.5", "--model-out", dir.file("m.toml")},
                                           dir.path());
    ASSERT_EQ(without.exit_code, 0) << without.output;
    const auto k = nlohmann::json::parse(without.output);
    EXPECT_TRUE(k["located"].empty()) << k["located"].dump();
    EXPECT_TRUE(k["saturated"].empty());
    EXPECT_EQ(k["timing"]["sequence_jumps"], 0);
    EXPECT_LT(k["timing"]["dt_jitter_rel"].get<double>(), 0.01);  // the 10 s join is no irregular spacing
    ASSERT_EQ(k["left_out"].size(), 2u) << k["left_out"].dump();
    EXPECT_EQ(k["left_out"][0]["rows"], 1);
    EXPECT_EQ(k["left_out"][1]["rows"], 10);
    EXPECT_NEAR(k["left_out"][1]["from_s"].get<double>(), shock_from - 0.5, 1e-6);
    {
        std::ifstream file(dir.file("m.toml"));
        std::string first;
        std::getline(file, first);
        EXPECT_NE(first.find(", without 0 s to 1.5 s and "), std::string::npos) << first;
    }
    // --exclude-saturated finds the same ten rows from their sat_flags, with its margin either side.
    const RunResult flagged = run_driftlab(
        {"gap", shock, "--replicates", "10", "--locate-only", "--json", "--exclude-saturated", "0.25"}, dir.path());
    ASSERT_EQ(flagged.exit_code, 0) << flagged.output;
    const auto s = nlohmann::json::parse(flagged.output);
    EXPECT_TRUE(s["located"].empty()) << s["located"].dump();
    EXPECT_TRUE(s["saturated"].empty());
    ASSERT_EQ(s["left_out"].size(), 1u) << s["left_out"].dump();
    EXPECT_EQ(s["left_out"][0]["rows"], 10);
    EXPECT_EQ(s["left_out"][0]["by"], "--exclude-saturated");
    EXPECT_NEAR(s["left_out"][0]["from_s"].get<double>(), shock_from - 0.25, 1e-6);
    EXPECT_NEAR(s["left_out"][0]["to_s"].get<double>(), shock_to + 0.25, 1e-6);
    const RunResult text =
        run_driftlab({"gap", shock, "--replicates", "10", "--locate-only", "--exclude", window}, dir.path());
    EXPECT_NE(text.output.find("left out: 10 rows from t = "), std::string::npos) << text.output;
    // The option that left them out, not both names whichever it was.
    EXPECT_NE(text.output.find(" s (--exclude): the rows either side are joined"), std::string::npos) << text.output;
    EXPECT_EQ(text.output.find("saturated:"), std::string::npos) << text.output;
    // Mistakes are refused: a window with no row, a reversed one, text that is not FROM:TO.
    const RunResult empty = run_driftlab({"gap", shock, "--exclude", "300.2:300.3"}, dir.path());
    EXPECT_EQ(empty.exit_code, 3) << empty.output;
    EXPECT_NE(empty.output.find("shock.csv: no row lies between 300.2 s and 300.3 s"), std::string::npos)
        << empty.output;
    EXPECT_EQ(run_driftlab({"gap", shock, "--exclude", "400:300"}, dir.path()).exit_code, 2);
    const RunResult margin = run_driftlab({"gap", shock, "--exclude-saturated", "-1"}, dir.path());
    EXPECT_EQ(margin.exit_code, 2);
    EXPECT_NE(margin.output.find("--exclude-saturated: expected a number >= 0, got '-1'"), std::string::npos)
        << margin.output;
    const RunResult bad = run_driftlab({"gap", shock, "--exclude", "300-310"}, dir.path());
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("--exclude: expected FROM:TO in seconds since power-on (e.g. 600:640), got '300-310'"),
              std::string::npos)
        << bad.output;
}

// One corrupt row (the gyro's top code in a row of 507) is a gap no effect closes: the diagnosis says so, and warns
// of the row with the --exclude window that leaves it out, on the terminal, in the report and in the JSON. With that
// window the log reads as the simulator's own; the clean log draws no warning.
TEST(GapCli, ACorruptRowIsWarnedWithTheWindowThatLeavesItOut) {
    TempDir dir("gaplone");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "600", "--seed", "4", "-o", log}, dir.path()).exit_code, 0);
    const std::string corrupt = dir.file("corrupt.csv");
    double row_t = 0.0;
    copy_log_editing_rows(log, corrupt, [&](std::vector<std::string>& f, int row) {
        if (row != 300) return;
        row_t = std::stod(f[0]);
        f[2] = "1023";
    });
    ASSERT_GT(row_t, 0.0);
    const std::vector<std::string> quick = {"--replicates", "10", "--locate-only", "--json"};
    const auto gap_json = [&](const std::string& file, std::vector<std::string> more) {
        std::vector<std::string> args = {"gap", file};
        args.insert(args.end(), quick.begin(), quick.end());
        args.insert(args.end(), more.begin(), more.end());
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return nlohmann::json::parse(r.output);
    };
    const auto clean = gap_json(log, {});
    EXPECT_TRUE(clean["lone_values"].empty()) << clean["lone_values"].dump();
    EXPECT_EQ(clean["verdict"], "none");

    const auto j = gap_json(corrupt, {});
    EXPECT_EQ(j["verdict"], "unexplained");
    EXPECT_FALSE(j["located"].empty());
    ASSERT_EQ(j["lone_values"].size(), 1u) << j["lone_values"].dump();
    const auto& lone = j["lone_values"][0];
    EXPECT_EQ(lone["channel"], "gyro");
    ASSERT_EQ(lone["t_s"].size(), 1u);
    EXPECT_DOUBLE_EQ(lone["t_s"][0].get<double>(), row_t);
    // The row's difference from either neighbour, about 516 counts against a noise of under one count, is nearly all of
    // the sample-to-sample variance.
    EXPECT_GT(lone["variance_share"].get<double>(), 0.99);
    const std::string warning = lone["warning"];
    EXPECT_EQ(warning.rfind("1 lone value (t = ", 0), 0u) << warning;
    EXPECT_NE(warning.find(" s: 1023) carries "), std::string::npos) << warning;
    const std::size_t at = warning.rfind("--exclude ");
    ASSERT_NE(at, std::string::npos) << warning;
    const std::string window = warning.substr(at + std::strlen("--exclude "));
    const std::size_t colon = window.find(':');
    ASSERT_NE(colon, std::string::npos) << window;
    // The window holds that row and no other (rows 1 s apart).
    EXPECT_LT(std::stod(window.substr(0, colon)), row_t);
    EXPECT_GT(std::stod(window.substr(0, colon)), row_t - 1.0);
    EXPECT_GT(std::stod(window.substr(colon + 1)), row_t);
    EXPECT_LT(std::stod(window.substr(colon + 1)), row_t + 1.0);

    const auto without = gap_json(corrupt, {"--exclude", window});
    EXPECT_TRUE(without["lone_values"].empty()) << without["lone_values"].dump();
    EXPECT_EQ(without["verdict"], "none");
    EXPECT_TRUE(without["located"].empty()) << without["located"].dump();
    ASSERT_EQ(without["left_out"].size(), 1u);
    EXPECT_EQ(without["left_out"][0]["rows"], 1);

    // After the first 100 s, which the report says it analysed (rows 1 s apart from t = 1.098 s).
    const RunResult text = run_driftlab(
        {"gap", corrupt, "--replicates", "10", "--locate-only", "--from", "100", "--report", dir.file("report")},
        dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("\nwarning: gyro: " + warning + "\n"), std::string::npos) << text.output;
    const std::string md = read_text(dir.file("report/gap.md"));
    EXPECT_NE(md.find("\nWarning: gyro: " + warning + "\n"), std::string::npos);
    EXPECT_NE(md.find("\n501 rows analysed, t = 100.098 s to 600.098 s.\n"), std::string::npos) << md.substr(0, 400);
}

// A stuck accelerometer with one corrupt row, in a 1500 s hil log: calibrated to white noise far below a code
// (0.014 counts), its replicates were the same for nearly every seed, and the held-out score had read 6e7 (4e16 on a
// 4000 s log), verdict unexplained. The two simulations that find a channel without noise now look at any channel
// with less than half a code of it: the channel is left out and named, its row warned of, and the gyro and the other
// accelerometers read as the simulator's own.
TEST(GapCli, AStuckChannelWithACorruptRowOrTwoIsLeftOut) {
    TempDir dir("gapstuckrow");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "1500", "--seed", "3", "-o", log}, dir.path()).exit_code, 0);
    const std::string stuck = dir.file("stuck.csv");
    copy_log_editing_rows(log, stuck, [](std::vector<std::string>& f, int row) { f[3] = row == 749 ? "1023" : "512"; });
    const RunResult r = run_driftlab({"gap", stuck, "--replicates", "10", "--locate-only", "--json"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j["noise_free_channels"].size(), 1u) << j["noise_free_channels"].dump();
    EXPECT_EQ(j["noise_free_channels"][0]["channel"], "accel_x");
    ASSERT_EQ(j["lone_values"].size(), 1u) << j["lone_values"].dump();
    EXPECT_EQ(j["lone_values"][0]["channel"], "accel_x");
    EXPECT_EQ(j["verdict"], "none");
    EXPECT_TRUE(j["located"].empty()) << j["located"].dump();
    EXPECT_LT(j["gap_before"]["heldout"].get<double>(), 2.0);
    EXPECT_GT(j["gap_before"]["heldout"].get<double>(), 0.3);

    // Two such rows had measured each other, and neither was named: a log's counts have a code, which bounds the step.
    const std::string twice = dir.file("twice.csv");
    copy_log_editing_rows(
        log, twice, [](std::vector<std::string>& f, int row) { f[3] = row == 749 || row == 1100 ? "1023" : "512"; });
    const RunResult r2 = run_driftlab({"gap", twice, "--replicates", "10", "--locate-only", "--json"}, dir.path());
    ASSERT_EQ(r2.exit_code, 0) << r2.output;
    const auto j2 = nlohmann::json::parse(r2.output);
    ASSERT_EQ(j2["lone_values"].size(), 1u) << j2["lone_values"].dump();
    EXPECT_EQ(j2["lone_values"][0]["channel"], "accel_x");
    ASSERT_EQ(j2["lone_values"][0]["t_s"].size(), 2u) << j2["lone_values"].dump();
    EXPECT_EQ(j2["lone_values"][0]["t_s"][0], j["lone_values"][0]["t_s"][0]);
    EXPECT_EQ(j2["verdict"], "none");
    // fit and allan take the code of a log's channel alike.
    const std::string two = "2 lone values (t = 750.098 s: 1023, t = 1101.098 s: 1023)";
    const RunResult fit = run_driftlab({"fit", twice, "--channel", "accel_x"}, dir.path());
    ASSERT_EQ(fit.exit_code, 0) << fit.output;
    EXPECT_NE(fit.output.find(two), std::string::npos) << fit.output;
    const RunResult allan = run_driftlab({"allan", twice, "--channel", "accel_x", "--json"}, dir.path());
    ASSERT_EQ(allan.exit_code, 0) << allan.output;
    const auto warning = nlohmann::json::parse(allan.output)["channels"]["accel_x"]["lone_values_warning"];
    ASSERT_TRUE(warning.is_string()) << allan.output;
    EXPECT_NE(warning.get<std::string>().find(two), std::string::npos) << warning;
}

TEST(GapCli, ATooShortLogIsRefusedNamingTheFile) {
    TempDir dir("gapshort");
    const std::string log = dir.file("short.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "60", "-o", log}, dir.path()).exit_code, 0);
    const RunResult gap = run_driftlab({"gap", log}, dir.path());
    EXPECT_EQ(gap.exit_code, 3) << gap.output;
    EXPECT_NE(gap.output.find("short.csv"), std::string::npos) << gap.output;
    EXPECT_NE(gap.output.find("at least 200 samples"), std::string::npos) << gap.output;
    const RunResult holdout = run_driftlab({"gap", log, "--holdout", "random"}, dir.path());
    EXPECT_EQ(holdout.exit_code, 2) << holdout.output;
    EXPECT_NE(holdout.output.find("--holdout"), std::string::npos) << holdout.output;
    // A missing file is said to be missing, not taken for a plain table that lacks its options.
    const RunResult missing = run_driftlab({"gap", dir.file("absent.csv")}, dir.path());
    EXPECT_EQ(missing.exit_code, 3) << missing.output;
    EXPECT_NE(missing.output.find("absent.csv: cannot open"), std::string::npos) << missing.output;
    const RunResult tau0 = run_driftlab({"gap", log, "--tau0", "-1"}, dir.path());
    EXPECT_EQ(tau0.exit_code, 2) << tau0.output;
    EXPECT_NE(tau0.output.find("--tau0: expected a number > 0, got '-1'"), std::string::npos) << tau0.output;
}

// What the simulator cannot stand beside is refused with the file and line, not diagnosed: a gap found there would be
// the log's damage (a wild value), a wrong period (every lag and band misplaced), or a smoothing the replicates do not
// repeat (a window of 1 assumed had read every averaged log as broken).
TEST(GapCli, ALogTheSimulatorCannotStandBesideIsRefusedNamingTheLine) {
    TempDir dir("gapmeta");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "300", "-o", log}, dir.path()).exit_code, 0);
    std::vector<std::string> lines;
    {
        std::istringstream in(read_text(log));
        for (std::string line; std::getline(in, line);) lines.push_back(line);
    }
    const auto line_of = [&](const std::string& start) {
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (lines[i].rfind(start, 0) == 0) return i;
        ADD_FAILURE() << "no line starts with " << start;
        return std::size_t{0};
    };
    const auto variant = [&](const std::string& name, auto edit) {
        std::vector<std::string> v = lines;
        edit(v);
        std::ofstream out(dir.file(name));
        for (const auto& line : v) out << line << "\n";
        return dir.file(name);
    };
    const auto refused = [&](const std::string& file, const std::string& expected) {
        const RunResult r = run_driftlab({"gap", file, "--replicates", "10"}, dir.path());
        EXPECT_EQ(r.exit_code, 3) << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("verdict"), std::string::npos) << "refused before the diagnosis";
    };
    const std::size_t period = line_of("# sample_period_s:");
    refused(variant("period.csv", [&](auto& v) { v[period] = "# sample_period_s: 10"; }),
            "period.csv:" + std::to_string(period + 1) +
                ": metadata 'sample_period_s' is 10 s, but the rows are 1 s apart");
    const std::size_t bits = line_of("# adc_bits:");
    refused(variant("bits.csv", [&](auto& v) { v[bits] = "# adc_bits: 12"; }),
            "bits.csv:" + std::to_string(bits + 1) + ": adc_bits is 12, but the simulator's converter has 10 bits");
    refused(
        variant("window.csv", [&](auto& v) { v.erase(v.begin() + static_cast<std::ptrdiff_t>(line_of("# window:"))); }),
        "window.csv: the metadata lacks 'window'");
    // Without adc_bits a value no 10-bit converter makes had calibrated the gyro to a spread of 1e95 counts and
    // answered "none".
    const std::size_t row = line_of("t_s,") + 10;
    refused(variant("wild.csv",
                    [&](auto& v) {
                        v.erase(v.begin() + static_cast<std::ptrdiff_t>(bits));
                        std::string& r = v[row - 1];
                        const auto a = r.find(',', r.find(',') + 1);  // the gyro is the third field
                        r = r.substr(0, a + 1) + "1e100" + r.substr(r.find(',', a + 1));
                    }),
            "wild.csv:" + std::to_string(row) + ": field 3 (gyro) '1e100': beyond the 10-bit converter's reach");
}

// A plain recording's time column must agree with --tau0 (it had been diagnosed at the wrong period) and count from
// power-on, as eq. 1 does.
TEST(GapCli, APlainRecordingsTimeColumnMustAgreeWithTau0AndStartAtPowerOn) {
    TempDir dir("gapplaintime");
    const auto table = [&](const std::string& name, double t0) {
        std::ofstream out(dir.file(name));
        out << "t,gx\n";
        std::mt19937 rng(3);
        std::normal_distribution<double> noise(0.0, 0.05);
        for (int k = 0; k < 3000; ++k) out << t0 + k * 0.01 << "," << noise(rng) << "\n";
        return dir.file(name);
    };
    const std::string good = table("good.csv", 0.0);
    const RunResult slow =
        run_driftlab({"gap", good, "--as", "gyro=gx:0.00875", "--tau0", "0.02", "--block", "10"}, dir.path());
    EXPECT_EQ(slow.exit_code, 2) << slow.output;
    EXPECT_NE(slow.output.find("--tau0 0.02 s, but the time column's rows are 0.01 s apart"), std::string::npos)
        << slow.output;
    const RunResult early = run_driftlab(
        {"gap", table("early.csv", -100.0), "--as", "gyro=gx:0.00875", "--tau0", "0.01", "--block", "10"}, dir.path());
    EXPECT_EQ(early.exit_code, 3) << early.output;
    EXPECT_NE(early.output.find("early.csv:2: the time column starts at -100 s"), std::string::npos) << early.output;
}

// A report folder that cannot be made (a file in the way) is refused before the diagnosis, with the device error's
// exit code and the folder named; so is a log folder for hil.
TEST(GapCli, AnUnusableReportFolderIsRefusedBeforeTheDiagnosis) {
    TempDir dir("gapreportdir");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "400", "-o", log}, dir.path()).exit_code, 0);
    const RunResult gap = run_driftlab({"gap", log, "--replicates", "10", "--report", log + "/report"}, dir.path());
    EXPECT_EQ(gap.exit_code, 4) << gap.output;
    EXPECT_NE(gap.output.find("hil.csv/report: cannot create the report folder"), std::string::npos) << gap.output;
    EXPECT_EQ(gap.output.find("verdict"), std::string::npos) << "no diagnosis before the refusal";
    const RunResult model =
        run_driftlab({"gap", log, "--replicates", "10", "--model-out", dir.file("absent/m.toml")}, dir.path());
    EXPECT_EQ(model.exit_code, 4) << model.output;
    EXPECT_NE(model.output.find("absent/m.toml: cannot write the model file"), std::string::npos) << model.output;
    EXPECT_EQ(model.output.find("verdict"), std::string::npos) << "no diagnosis before the refusal";
    const RunResult hil = run_driftlab({"hil", "--duration", "10", "-o", log + "/x.csv"}, dir.path());
    EXPECT_EQ(hil.exit_code, 4) << hil.output;
    EXPECT_NE(hil.output.find("cannot create the log folder"), std::string::npos) << hil.output;
}

// `gap LOG --model M --model-out M` had written the estimate over the model it started from (exit 0); the report's
// own files are outputs too. Each is refused before anything is written, whatever spelling names the file. A log
// elsewhere in the report folder is no conflict.
TEST(GapCli, NeitherTheModelFileNorTheLogIsWrittenOver) {
    TempDir dir("gapoverwrite");
    const std::string model_text = "name = \"unit\"\n";
    std::ofstream(dir.file("m.toml")) << model_text;
    const RunResult model = run_driftlab({"gap", dir.file("x.csv"), "--model", dir.file("m.toml"), "--model-out",
                                          (dir.path() / "." / "m.toml").string()},
                                         dir.path());
    EXPECT_EQ(model.exit_code, 2) << model.output;
    EXPECT_NE(model.output.find("--model-out: '" + (dir.path() / "." / "m.toml").string() +
                                "' is the model file this command reads"),
              std::string::npos)
        << model.output;
    EXPECT_EQ(read_text(dir.file("m.toml")), model_text);

    std::filesystem::create_directory(dir.file("rep"));
    const std::string table = "t_s y\n0 1\n1 2\n";
    for (const std::string name : {"gap.md", "gap_mean_gyro.dat"}) {
        std::ofstream(dir.file("rep/" + name)) << table;
        const RunResult log =
            run_driftlab({"gap", dir.file("rep/" + name), "--tau0", "1", "--report", dir.file("rep")}, dir.path());
        EXPECT_EQ(log.exit_code, 2) << name << ": " << log.output;
        EXPECT_NE(log.output.find("--report: '" + dir.file("rep/" + name) + "' is the log this command reads"),
                  std::string::npos)
            << log.output;
        EXPECT_EQ(read_text(dir.file("rep/" + name)), table) << name;
    }
    std::ofstream(dir.file("rep/gap_adev_gyro.png")) << model_text;
    const RunResult plot = run_driftlab(
        {"gap", dir.file("x.csv"), "--model", dir.file("rep/gap_adev_gyro.png"), "--report", dir.file("rep")},
        dir.path());
    EXPECT_EQ(plot.exit_code, 2) << plot.output;
    EXPECT_NE(plot.output.find("is the model file this command reads"), std::string::npos) << plot.output;
}

// `--report rep --model-out rep/gap.md` had written the model file over the report it had just written (exit 0).
// One output aimed at another's file is refused before the diagnosis, whether the file exists yet or not and
// whatever spelling or folder link names it; a model file elsewhere in the report's folder is no conflict.
TEST(GapCli, TheModelFileOutIsNoneOfTheReportsFiles) {
    TempDir dir("gapmodelreport");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "400", "-o", log}, dir.path()).exit_code, 0);
    const std::string not_yet = (dir.path() / "rep" / "." / "gap.md").string();
    const RunResult fresh = run_driftlab(
        {"gap", log, "--replicates", "10", "--report", dir.file("rep"), "--model-out", not_yet}, dir.path());
    EXPECT_EQ(fresh.exit_code, 2) << fresh.output;
    EXPECT_NE(fresh.output.find("--model-out: '" + not_yet + "' is a file --report writes ('" + dir.file("rep") +
                                "/gap.md')"),
              std::string::npos)
        << fresh.output;
    EXPECT_EQ(fresh.output.find("verdict"), std::string::npos) << "no diagnosis before the refusal";
    EXPECT_FALSE(std::filesystem::exists(dir.file("rep"))) << "nothing written";
    // The report's folder itself, spelt another way: a usage error (2), not an unwritable file (4) found later.
    const RunResult folder = run_driftlab(
        {"gap", log, "--replicates", "10", "--report", dir.file("rep"), "--model-out", dir.file("rep") + "/"},
        dir.path());
    EXPECT_EQ(folder.exit_code, 2) << folder.output;
    EXPECT_NE(folder.output.find("is the folder --report writes into; name a file, such as '" + dir.file("rep") +
                                 "/model.toml'"),
              std::string::npos)
        << folder.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("rep"))) << "nothing written";

    std::filesystem::create_directory(dir.file("rep"));
    std::filesystem::create_directory_symlink(dir.file("rep"), dir.file("alias"));
    const std::string plot = "an earlier plot\n";
    std::ofstream(dir.file("rep/gap_mean_accel_z.png")) << plot;
    const RunResult linked = run_driftlab({"gap", log, "--replicates", "10", "--report", dir.file("rep"), "--model-out",
                                           dir.file("alias/gap_mean_accel_z.png")},
                                          dir.path());
    EXPECT_EQ(linked.exit_code, 2) << linked.output;
    EXPECT_NE(linked.output.find("is a file --report writes"), std::string::npos) << linked.output;
    EXPECT_EQ(read_text(dir.file("rep/gap_mean_accel_z.png")), plot);

    const RunResult beside = run_driftlab({"gap", log, "--replicates", "10", "--locate-only", "--report",
                                           dir.file("rep"), "--model-out", dir.file("alias/m.toml")},
                                          dir.path());
    ASSERT_EQ(beside.exit_code, 0) << beside.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("rep/gap.md")));
    EXPECT_NE(read_text(dir.file("rep/m.toml")).find("# driftlab gap "), std::string::npos);
}

// The report's words (battery, cell, replicate, practical margin, shrink...) are said before its tables, and a table
// without rows is "None" and why, not a header alone. The log may sit in the report's folder.
TEST(GapCli, TheReportSaysNoneForAnEmptyTableAndDefinesItsWords) {
    TempDir dir("gapreportnone");
    std::filesystem::create_directory(dir.file("rep"));
    const std::string log = dir.file("rep/hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "1500", "--seed", "3", "-o", log}, dir.path()).exit_code, 0);
    const RunResult gap =
        run_driftlab({"gap", log, "--replicates", "16", "--locate-only", "--report", dir.file("rep")}, dir.path());
    ASSERT_EQ(gap.exit_code, 0) << gap.output;
    ASSERT_NE(gap.output.find("located cells (|z| > "), std::string::npos) << gap.output;
    ASSERT_NE(gap.output.find("and beyond the margin): 0\n"), std::string::npos) << gap.output;
    // A hil log's times are evenly spaced but for their rounding (1.5e-13 %), which had been printed as a spread.
    EXPECT_NE(gap.output.find("; row spacing constant (its sd below 1e-6 % of the rows' period)\n"), std::string::npos)
        << gap.output;
    // 1500 s is under twice the paper's accelerometer T (about 950 s), not the gyro's (411 s): a `none` that says a
    // slow effect there would be in eq. 1's fit, for the accelerometers alone.
    const std::size_t slow =
        gap.output.find("\nslow drift: the paper's drift model, eq. 1: C1(1 - e^(-t/T)) + C2, is fitted with T = ");
    ASSERT_NE(slow, std::string::npos) << gap.output;
    const std::string slow_line = gap.output.substr(slow + 1, gap.output.find('\n', slow + 1) - slow - 1);
    EXPECT_NE(slow_line.find(" s on accel_"), std::string::npos) << slow_line;
    EXPECT_EQ(slow_line.find(" s on gyro"), std::string::npos) << slow_line;
    const std::string md = read_text(dir.file("rep/gap.md"));
    EXPECT_NE(md.find("\n\nSlow drift: the paper's drift model, eq. 1"), std::string::npos) << md.substr(0, 800);
    const std::size_t guide = md.find("## How to read this report\n\n");
    ASSERT_NE(guide, std::string::npos) << md.substr(0, 800);
    for (const char* word : {"*replicates*", "*battery*", "*cell*", "*located*", "*practical margin*", "*gap score*",
                             "*held-out part*", "*Shrink*", "*Gain / penalty*", "*ΔIC*", "*level step*", "docs/gap.md"})
        EXPECT_NE(md.find(word, guide), std::string::npos) << word;
    EXPECT_NE(md.find("## Where: located cells (|z| > "), std::string::npos);
    EXPECT_NE(md.find("None: no cell lies beyond both.\n"), std::string::npos) << md;
    EXPECT_EQ(md.find("| statistic | channel | cell |"), std::string::npos) << "no table of headers alone";
    EXPECT_NE(md.find("## Which: candidate effects\n\nNone tried (--locate-only).\n"), std::string::npos) << md;
    EXPECT_EQ(md.find("| step | effect |"), std::string::npos) << "no table of headers alone";
    EXPECT_EQ(read_text(log).rfind("# driftlab-log", 0), 0u) << "the log in the report's folder is left as it was";
}

// --max-effects 1 on the real gyro, whose default search adds a second effect after the first: the limited run
// stops after the first step, and that step is the default run's first: the same effect, judged the same (a step's
// decision does not depend on later ones; its parameters do, as later steps refit it beside what they add).
TEST(GapCli, MaxEffectsStopsTheStepwiseSearchAfterThatManyEffects) {
    const std::string real = std::string(DRIFTLAB_SHARED_DIR) + "/data/real/gyro2_x.txt";
    if (!std::filesystem::exists(real)) GTEST_SKIP() << real << " not found (../shared is absent)";
    TempDir dir("gapmaxeffects");
    const std::vector<std::string> args{"gap",     real, "--tau0",       "0.01", "--as",  "gyro=col1:0.00875",
                                        "--block", "40", "--replicates", "16",   "--json"};
    const auto added = [](const nlohmann::json& j) {
        std::vector<nlohmann::json> out;
        for (const auto& e : j["explanations"])
            if (e["added"].get<bool>()) out.push_back(e);
        return out;
    };
    const RunResult whole = run_driftlab(args, dir.path());
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    const auto jw = nlohmann::json::parse(whole.output);
    EXPECT_EQ(jw["max_effects"], 3);
    const auto by_default = added(jw);
    ASSERT_GE(by_default.size(), 2u) << "the default adds a second effect on this log, so the limit has one to stop";
    std::vector<std::string> limited_args = args;
    limited_args.insert(limited_args.end(), {"--max-effects", "1"});
    const RunResult limited = run_driftlab(limited_args, dir.path());
    ASSERT_EQ(limited.exit_code, 0) << limited.output;
    const auto jl = nlohmann::json::parse(limited.output);
    EXPECT_EQ(jl["max_effects"], 1);
    const auto first = added(jl);
    ASSERT_EQ(first.size(), 1u) << jl["explanations"].dump();
    EXPECT_EQ(jl["verdict"], jw["verdict"]);
    for (const char* key : {"effect", "channel", "heldout_before", "heldout_after", "step"})
        EXPECT_EQ(first.front()[key], by_default.front()[key]) << key;
    // The first step is taken on a held-out score beyond its bound, the second on one already within it.
    EXPECT_FALSE(by_default[0]["within_bound_before"].get<bool>());
    EXPECT_GT(by_default[0]["heldout_before"].get<double>(), by_default[0]["heldout_bound"].get<double>());
    EXPECT_TRUE(by_default[1]["within_bound_before"].get<bool>());
    EXPECT_LE(by_default[1]["heldout_before"].get<double>(), by_default[1]["heldout_bound"].get<double>());
    EXPECT_GT(by_default[1]["heldout_bound"].get<double>(), 1.0) << "a bound on a score whose null mean is 1";
    for (const char* bad : {"0", "4"}) {
        const RunResult refused = run_driftlab({"gap", real, "--max-effects", bad}, dir.path());
        EXPECT_EQ(refused.exit_code, 2) << refused.output;
        EXPECT_NE(refused.output.find("--max-effects"), std::string::npos) << refused.output;
    }
}

// On the real gyro the default's second step is taken with the held-out score already within its bound: the terminal
// and the report say so beside that step, and the verdict beside its name.
TEST(GapCli, AStepTakenWithinTheBoundIsSaidSoOnTheTerminalAndInTheReport) {
    const std::string real = std::string(DRIFTLAB_SHARED_DIR) + "/data/real/gyro2_x.txt";
    if (!std::filesystem::exists(real)) GTEST_SKIP() << real << " not found (../shared is absent)";
    TempDir dir("gapwithinbound");
    const RunResult r = run_driftlab({"gap", real, "--tau0", "0.01", "--as", "gyro=col1:0.00875", "--block", "40",
                                      "--replicates", "16", "--report", dir.file("rep")},
                                     dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string note = "added with the held-out score already within its bound";
    const std::size_t verdict_end = r.output.find('\n');
    EXPECT_NE(r.output.substr(0, verdict_end).find(" on gyro (" + note + ")"), std::string::npos)
        << r.output.substr(0, verdict_end);
    const std::size_t table = r.output.find("explanation (effects added in order");
    ASSERT_NE(table, std::string::npos) << r.output;
    const std::size_t step1 = r.output.find("\n  1 ", table), step2 = r.output.find("\n  2 ", table);
    ASSERT_NE(step2, std::string::npos) << r.output;
    EXPECT_EQ(r.output.substr(step1, step2 - step1).find(note), std::string::npos)
        << "the first step is taken beyond the bound";
    EXPECT_NE(r.output.substr(step2, r.output.find('\n', step2 + 1) - step2).find(note), std::string::npos) << r.output;
    const std::string md = read_text(dir.file("rep/gap.md"));
    EXPECT_NE(md.find(" (within its bound "), std::string::npos) << md;
}

// --fit-fraction sets the forecast design's split; under the default interleaved design it had been ignored without
// a word, the report and the JSON still saying 0.6.
TEST(GapCli, FitFractionIsRefusedWithoutTheForecastDesign) {
    TempDir dir("gapfitfraction");
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"gap", "x.csv", "--fit-fraction", "0.7"},
          {"gap", "x.csv", "--fit-fraction", "0.7", "--holdout", "interleaved"}}) {
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find("--fit-fraction sets where --holdout forecast splits the log"), std::string::npos)
            << r.output;
    }
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "400", "-o", log}, dir.path()).exit_code, 0);
    const RunResult forecast = run_driftlab(
        {"gap", log, "--holdout", "forecast", "--fit-fraction", "0.7", "--replicates", "10", "--locate-only", "--json"},
        dir.path());
    ASSERT_EQ(forecast.exit_code, 0) << forecast.output;
    const auto j = nlohmann::json::parse(forecast.output);
    EXPECT_EQ(j["holdout"], "forecast");
    EXPECT_DOUBLE_EQ(j["fit_fraction"].get<double>(), 0.7);
}

// A plot folder that cannot be made is refused before minutes of benchmark, not after them.
TEST(GapEvalCli, AnUnusablePlotFolderIsRefusedBeforeTheRun) {
    TempDir dir("gapevalplot");
    const std::string blocker = dir.file("file");
    std::ofstream(blocker) << "not a folder\n";
    const RunResult r =
        run_driftlab({"gap-eval", "--quick", "--effects", "thermal_rc", "--plot", blocker + "/plots"}, dir.path());
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_NE(r.output.find("cannot create the plot folder"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("| generator"), std::string::npos) << "no benchmark output before the refusal";
}

// --raw-clean makes the clean logs raw-mode: the scores say so, and the false-positive line names them.
TEST(GapEvalCli, RawCleanLogsAreReportedAsRawMode) {
    TempDir dir("gapevalraw");
    const std::vector<std::string> base{"gap-eval", "--clean-only",     "--quick", "--seeds-score",
                                        "11..12",   "--clean-per-seed", "2"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = base;
        args.insert(args.end(), extra.begin(), extra.end());
        return run_driftlab(args, dir.path());
    };
    const RunResult raw = with({"--raw-clean", "--json"});
    ASSERT_EQ(raw.exit_code, 0) << raw.output;
    const auto j = nlohmann::json::parse(raw.output.substr(raw.output.find('{')));
    EXPECT_EQ(j["false_positive"]["clean"], 4);
    EXPECT_TRUE(j["false_positive"]["raw_mode"].get<bool>());
    const RunResult plain = with({"--json"});
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    EXPECT_FALSE(
        nlohmann::json::parse(plain.output.substr(plain.output.find('{')))["false_positive"]["raw_mode"].get<bool>());
    const RunResult md = with({"--raw-clean"});
    EXPECT_NE(md.output.find("False-positive rate on clean raw-mode logs: "), std::string::npos) << md.output;
}

// --clean-only without --clean-per-seed takes as many clean logs per seed as the run has sizes (--quick: one), not
// none.
TEST(GapEvalCli, CleanOnlyWithoutACountStillDiagnosesCleanLogs) {
    TempDir dir("gapevalclean");
    const RunResult r =
        run_driftlab({"gap-eval", "--clean-only", "--quick", "--seeds-score", "11..13", "--json"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // 3 seeds x 1 size
    EXPECT_EQ(nlohmann::json::parse(r.output.substr(r.output.find('{')))["false_positive"]["clean"], 3);
    // It tunes nothing, so scoring seeds among the default tuning ones (1..4) are no overlap.
    const RunResult low =
        run_driftlab({"gap-eval", "--clean-only", "--quick", "--seeds-score", "1..2", "--json"}, dir.path());
    ASSERT_EQ(low.exit_code, 0) << low.output;
    EXPECT_EQ(nlohmann::json::parse(low.output.substr(low.output.find('{')))["false_positive"]["clean"], 2);
}

// A seed range is two whole numbers in order, at most kMaxEvalSeed: "-1" is no number (not 2^64 - 1, which ran
// forever).
TEST(GapEvalCli, ASeedRangeOfNegativeOrHugeNumbersIsRefused) {
    TempDir dir("gapevalrange");
    for (const std::string range : {"101..-1", "-3..4", "1..2000000", "5..4", "1..2x", "..4"}) {
        const RunResult r = run_driftlab({"gap-eval", "--quick", "--seeds-score", range}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << range << ": " << r.output;
        EXPECT_NE(r.output.find("--seeds-score: expected A..B with whole numbers 0 <= A <= B <= 1000000, got '" +
                                range + "'"),
                  std::string::npos)
            << r.output;
    }
}

// --pairs names two generators of library effects that act at the converter input; anything else is a usage error
// naming the pair, before any log is made.
TEST(GapEvalCli, ABadPairIsRefusedNamingIt) {
    TempDir dir("gapevalpairs");
    auto refused = [&](const std::string& pair, const std::string& message) {
        const RunResult r =
            run_driftlab({"gap-eval", "--quick", "--effects", "thermostat", "--pairs", pair}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << pair << ": " << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("| generator"), std::string::npos) << "no benchmark output before the refusal";
    };
    refused("thermostat", "--pairs: expected A+B, got 'thermostat'");
    refused("thermostat+ambient_cycle", "names one generator twice");
    refused("thermostat+mode_hop", "--pairs: mode_hop stands for no library effect");
    refused("sar_mismatch+flicker", "--pairs: sar_mismatch replaces the converter");
    refused("thermostat+wobble", "--pairs: unknown generator or effect 'wobble'");
    refused("none+thermostat", "--pairs: unknown generator or effect 'none'");
    // A misspelt name is answered with the names there are.
    const RunResult misspelt = run_driftlab({"gap-eval", "--quick", "--effects", "thermostatt"}, dir.path());
    EXPECT_EQ(misspelt.exit_code, 2) << misspelt.output;
    for (const auto& t : host::gap::truth_list())
        EXPECT_NE(misspelt.output.find(t.generator), std::string::npos) << t.generator;
}

}  // namespace
}  // namespace driftlab::e2e
