// `driftlab gap`'s options and refusals: what the simulator cannot stand beside is refused naming the file or line;
// no output is written over an input or another output; the report defines its words; --max-effects and
// --fit-fraction do what they say.
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

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

}  // namespace
}  // namespace driftlab::e2e
