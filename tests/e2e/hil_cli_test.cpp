// `driftlab hil` options as a user types them: a 100 Hz log needs fewer conversions per output than the
// paper preset's 25 (docs/firmware.md: 10 ms outputs allow at most 12), which --conversions sets, and a link
// faster than the paper's 9600-baud radio (sim/models/hundred_hz.toml).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "e2e_support.hpp"
#include "host/log/log_reader.hpp"

namespace driftlab::e2e {
namespace {

TEST(HilCli, ConversionsPerOutputMakesA100HzLogPossible) {
    TempDir dir("hil100");
    const std::string out = dir.file("h100.csv");
    const RunResult r =
        run_driftlab({"hil", "--model", std::string(DRIFTLAB_SOURCE_DIR) + "/sim/models/hundred_hz.toml", "--duration",
                      "2", "--conversions", "6", "--window", "6", "-o", out},
                     dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const host::LogData log = host::read_log(out);
    EXPECT_EQ(log.metadata.get_int("conversions_per_output"), 6);
    EXPECT_EQ(log.metadata.get_int("window"), 6);
    // 2 s of 10 ms outputs; the first poll follows the handshake, so allow one short.
    EXPECT_NEAR(static_cast<double>(log.size()), 200.0, 1.0);
    // Host receive instants: frame transmission jitters single spacings, the mean spacing is the period.
    EXPECT_NEAR((log.t_s.back() - log.t_s.front()) / static_cast<double>(log.size() - 1), 0.01, 1e-5);
}

// The board's die temperature in every row: 25 °C at power-on warming towards 28 °C (tau 300 s, sim/hil/
// die_temperature.hpp) through the sensor's typical transfer, to 0.1 °C; a schedule too fast for a reading has -300.
TEST(HilCli, EveryRowCarriesTheBoardsDieTemperature) {
    TempDir dir("hiltemp");
    const std::string out = dir.file("t.csv");
    const RunResult r = run_driftlab({"hil", "--preset", "fig3", "--duration", "900", "-o", out}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const host::LogData log = host::read_log(out);
    ASSERT_TRUE(log.has_column("temp_c"));
    const std::vector<double>& temp = log.optional_columns.at("temp_c");
    // Code 292 (314.0 mV) at 25 °C: the middle of its step, 25.2 °C.
    EXPECT_NEAR(temp.front(), 25.0, 0.6);
    EXPECT_NEAR(temp.back(), 28.0 - 3.0 * std::exp(-900.0 / 300.0), 0.6);
    EXPECT_TRUE(std::is_sorted(temp.begin(), temp.end())) << "the die only warms";
    const RunResult fast =
        run_driftlab({"hil", "--model", std::string(DRIFTLAB_SOURCE_DIR) + "/sim/models/hundred_hz.toml", "--duration",
                      "1", "--conversions", "12", "--window", "12", "-o", dir.file("fast.csv")},
                     dir.path());
    ASSERT_EQ(fast.exit_code, 0) << fast.output;
    const host::LogData fast_log = host::read_log(dir.file("fast.csv"));
    for (double t : fast_log.optional_columns.at("temp_c")) EXPECT_EQ(t, -300.0);
}

// The run's settings are written as the shortest text that reads back to the same number: a
// warm-up of 1234.5 s is "1234.5", the paper's 9600-baud radio "9600" (not "9600.000000").
TEST(HilCli, TheLogsSettingsAreWrittenAsTheNumbersTheyAre) {
    TempDir dir("hilmeta");
    const std::string out = dir.file("h.csv");
    const RunResult r = run_driftlab({"hil", "--duration", "3", "--warm", "1234.5", "-o", out}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const host::LogData log = host::read_log(out);
    EXPECT_EQ(log.metadata.get("warm_up_s"), "1234.5");
    EXPECT_EQ(log.metadata.get("link_baud"), "9600");
    EXPECT_EQ(log.metadata.get("effects"), "none");

    // A model file's effects are named in the log and in the summary.
    const std::string model = dir.file("m.toml");
    std::ofstream(model) << "[effects.gauss_markov]\nsigma_dps = 0.05\ntau_s = 30\n\n[effects.spikes]\nrate_hz = 0.01\n"
                            "scale_counts = 5\n";
    const RunResult with = run_driftlab({"hil", "--model", model, "--duration", "3", "-o", out}, dir.path());
    ASSERT_EQ(with.exit_code, 0) << with.output;
    EXPECT_EQ(host::read_log(out).metadata.get("effects"), "gauss_markov,spikes");
    EXPECT_NE(with.output.find("effects simulated: gauss_markov,spikes"), std::string::npos) << with.output;
}

// Ctrl-C ends a run between events: every row made so far is in the log, whole (the default SIGINT action had cut
// the last one mid-write, so that fit and gap refused the file), and the exit code says the run did not finish.
TEST(HilCli, CtrlCKeepsEveryRowMadeSoFarWholeAndSaysSo) {
    TempDir dir("hilint");
    const std::string out = dir.file("h.csv");
    const pid_t pid = spawn_driftlab({"hil", "--duration", "1e9", "-o", out}, dir.file("hil.out"));
    // Until a few thousand rows are on disk however loaded the machine (at most a minute).
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::error_code ec;
    while ((!std::filesystem::exists(out, ec) || std::filesystem::file_size(out, ec) < 200000) &&
           std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ::kill(pid, SIGINT);
    const RunResult r = wait_child(pid, dir.file("hil.out"));
    EXPECT_EQ(r.exit_code, 130) << r.output;
    EXPECT_NE(r.output.find("interrupted after"), std::string::npos) << r.output;
    const host::LogData log = host::read_log(out);  // strict: a cut last line is an error
    EXPECT_GT(log.size(), 2000u);
    EXPECT_EQ(log.seq.back() - log.seq.front() + 1, log.size());  // no row lost on the way out
    EXPECT_NE(r.output.find("holds the " + std::to_string(log.size()) + " rows"), std::string::npos) << r.output;
}

TEST(HilCli, TooManyConversionsForThePeriodIsRefusedByField) {
    TempDir dir("hil100bad");
    const RunResult r =
        run_driftlab({"hil", "--duration", "2", "--period", "0.01", "-o", dir.file("h.csv")}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("conversions_per_output"), std::string::npos) << r.output;
}

// 10 ms outputs with the paper's 25 conversions per output, on a link fast enough for them: the firmware refuses
// this [firmware] (at most 12 conversions fit in 10 ms).
constexpr const char* kTenMsOutputsModel = "[firmware]\noutput_period_ms = 10\n\n[link]\nbaud = 115200.0\n";

// A model file's firmware CONFIG is checked with the command line's options over it: 10 ms outputs with the paper's
// 25 conversions are refused by the firmware, with --conversions 12 they run; --conversions 30 is refused again, and
// the message says the options took part.
TEST(HilCli, AModelFilesFirmwareIsCheckedWithTheOptionsOverIt) {
    TempDir dir("hilmodelopts");
    const auto [model, alone] = plain_hil_with_model(dir, "ten_ms.toml", kTenMsOutputsModel);
    EXPECT_EQ(alone.exit_code, 5) << alone.output;
    EXPECT_NE(alone.output.find("ten_ms.toml"), std::string::npos) << alone.output;
    const std::string out = dir.file("h.csv");
    const RunResult fits =
        run_driftlab({"hil", "--model", model, "--conversions", "12", "--duration", "1", "-o", out}, dir.path());
    EXPECT_EQ(fits.exit_code, 0) << fits.output;
    const RunResult too_many =
        run_driftlab({"hil", "--model", model, "--conversions", "30", "--duration", "1", "-o", out}, dir.path());
    EXPECT_EQ(too_many.exit_code, 5) << too_many.output;
    EXPECT_NE(too_many.output.find("conversions_per_output 30) gives a conversion period of 21 ticks"),
              std::string::npos)
        << too_many.output;
    EXPECT_NE(
        too_many.output.find("on the configuration that would run: the file's firmware fields with any the preset or "
                             "the command line sets over them"),
        std::string::npos)
        << too_many.output;
}

// With --pty the recorder configures the board, which boots with the firmware's defaults: a model file's [firmware]
// never reaches it, so one the firmware would refuse (10 ms outputs with the paper's 25 conversions) is served,
// with a note, and --duration bounds the serving, whatever the model's output period (the paper's 1 s).
TEST(HilCli, PtyServesWhateverTheModelsFirmwareSectionAndOutputPeriodSay) {
    TempDir dir("hilptyfw");
    const auto [model, simulated] = plain_hil_with_model(dir, "ten_ms.toml", kTenMsOutputsModel);
    ASSERT_EQ(simulated.exit_code, 5) << simulated.output;  // the check still holds where the file configures the board
    const RunResult served =
        run_driftlab({"hil", "--pty", "--model", model, "--speed", "10", "--duration", "1"}, dir.path());
    EXPECT_EQ(served.exit_code, 0) << served.output;
    EXPECT_NE(served.output.find("note: " + model + ": [firmware] is not applied with --pty"), std::string::npos)
        << served.output;
    EXPECT_NE(served.output.find("would refuse it: conversions_per_output:"), std::string::npos) << served.output;
    EXPECT_NE(served.output.find("served 1.0 s of board time"), std::string::npos) << served.output;

    // Half a second is shorter than the paper's 1 s output period: refused for a run, served with --pty.
    const RunResult short_run = run_driftlab({"hil", "--duration", "0.5", "-o", dir.file("h.csv")}, dir.path());
    ASSERT_EQ(short_run.exit_code, 2) << short_run.output;
    const RunResult short_serve = run_driftlab({"hil", "--pty", "--speed", "10", "--duration", "0.5"}, dir.path());
    EXPECT_EQ(short_serve.exit_code, 0) << short_serve.output;
    EXPECT_NE(short_serve.output.find("served 0.5 s of board time"), std::string::npos) << short_serve.output;
    EXPECT_EQ(short_serve.output.find("note:"), std::string::npos) << short_serve.output;  // the paper's model is fine
}

// 10 ms of jitter on 40 ms per channel reordered conversions: the gyro read code 0 on every row and hil exited 0.
TEST(HilCli, JitterThatWouldReorderConversionsIsAConfigurationErrorNamingTheFile) {
    TempDir dir("hiljitter");
    const std::string model = dir.file("j.toml");
    std::ofstream(model) << "[effects.gauss_markov]\nsigma_dps = 0.2\n\n[effects.clock_jitter]\njitter_s = 0.01\n";
    const RunResult r =
        run_driftlab({"hil", "--model", model, "--duration", "60", "-o", dir.file("h.csv")}, dir.path());
    EXPECT_EQ(r.exit_code, 5) << r.output;
    EXPECT_NE(r.output.find("j.toml:5: effects.clock_jitter.jitter_s"), std::string::npos) << r.output;
}

// 20 ms outputs need 1650 bytes/s, more than the paper's 9600 baud carry: from the model file it is the file's
// configuration (exit 5, naming it; it had been a usage error naming nothing), from --period the command line's.
TEST(HilCli, AnOutputRateTheLinkCannotCarryIsBlamedOnWhereThePeriodCameFrom) {
    TempDir dir("hillink");
    const RunResult file =
        plain_hil_with_model(dir, "fast.toml", "[firmware]\noutput_period_ms = 20\nconversions_per_output = 5\n").hil;
    EXPECT_EQ(file.exit_code, 5) << file.output;
    EXPECT_NE(file.output.find("fast.toml: link.baud: the link (link.baud 9600"), std::string::npos) << file.output;
    const std::string slow = dir.file("slow.toml");
    std::ofstream(slow) << "[firmware]\nconversions_per_output = 5\n";
    const RunResult option = run_driftlab(
        {"hil", "--model", slow, "--period", "0.02", "--duration", "1", "-o", dir.file("h.csv")}, dir.path());
    EXPECT_EQ(option.exit_code, 2) << option.output;
    const RunResult no_file = run_driftlab(
        {"hil", "--period", "0.02", "--conversions", "5", "--duration", "1", "-o", dir.file("h.csv")}, dir.path());
    EXPECT_EQ(no_file.exit_code, 2) << no_file.output;
}

// `-o -`: the log alone on standard output, so that it reads back; the summary goes to standard error, and --json
// (a second document on the same stream) is refused.
TEST(HilCli, ALogOnStandardOutputReadsBack) {
    TempDir dir("hilstdout");
    const std::string log = dir.file("piped.csv");
    const std::string command =
        std::string("'") + DRIFTLAB_BIN + "' hil --duration 30 -o - > '" + log + "' 2> '" + dir.file("err.txt") + "'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const host::LogData read = host::read_log(log);
    EXPECT_EQ(read.size(), 30u);
    const RunResult j = run_driftlab({"hil", "--duration", "3", "-o", "-", "--json"}, dir.path());
    EXPECT_EQ(j.exit_code, 2) << j.output;
}

// The summary accounts for every output the log lacks: frames lost whole on the link and samples dropped because
// their RAW frame was lost (only the JSON had them, so 600 outputs -> 569 rows did not add up from the text).
TEST(HilCli, TheSummarySaysWhereTheMissingRowsWent) {
    TempDir dir("hilsummary");
    const std::vector<std::string> run = {
        "hil",   "--model",        std::string(DRIFTLAB_SOURCE_DIR) + "/sim/models/lossy_radio.toml",
        "--raw", "--stream",       "--duration",
        "600",   "--seed",         "3",
        "-o",    dir.file("l.csv")};
    std::vector<std::string> with_json = run;
    with_json.push_back("--json");
    const RunResult js = run_driftlab(with_json, dir.path());
    ASSERT_EQ(js.exit_code, 0) << js.output;
    const auto j = nlohmann::json::parse(js.output);
    const auto missing_raw = j["rows_missing_raw"].get<std::uint64_t>();
    ASSERT_GT(missing_raw, 0u);  // the run exercises both counts
    ASSERT_GT(j["link"]["to_host"]["packets_lost"].get<std::uint64_t>(), 0u);
    const RunResult r = run_driftlab(run, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(
        r.output.find("wrote " + std::to_string(j["rows"].get<std::uint64_t>()) + " rows to " + dir.file("l.csv") +
                      " (" + std::to_string(missing_raw) + " samples not logged: their RAW frame was lost)"),
        std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(std::to_string(j["link"]["to_host"]["packets_damaged"].get<std::uint64_t>()) +
                            " frames damaged (" +
                            std::to_string(j["link"]["to_host"]["packets_lost"].get<std::uint64_t>()) + " lost whole)"),
              std::string::npos)
        << r.output;
}

// --cycles profiles a separate short streaming run, not the run the log came from (a polled fig2 run showed its
// receive interrupt at 0 calls, though every POLL goes through it): the output says so.
TEST(HilCli, TheCycleBudgetSaysItIsASeparateStreamingRun) {
#ifdef DRIFTLAB_AVR_ELF
    const std::string elf = DRIFTLAB_AVR_ELF;  // what `hil --target avr` runs by default
#else
    const std::string elf;
#endif
    if (elf.empty() || !std::filesystem::exists(elf)) GTEST_SKIP() << "AVR firmware ELF not built: '" << elf << "'";
    TempDir dir("hilcycles");
    const RunResult r = run_driftlab(
        {"hil", "--target", "avr", "--preset", "fig2", "--duration", "2", "--cycles", "-o", dir.file("c.csv")},
        dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("measured in a separate run of this configuration: 5 s of streaming after 0.5 s"),
              std::string::npos)
        << r.output;
    // 1000 conversions a second for 5 s, and a die temperature a second, converted twice (the first thrown away).
    EXPECT_NE(r.output.find("adc_isr               5010 calls"), std::string::npos) << r.output;
}

// Options of another way of running, or values the unsigned parse would wrap, are refused, not ignored.
TEST(HilCli, OptionsThatWouldBeIgnoredOrWrappedAreRefused) {
    TempDir dir("hilopts");
    const std::string out = dir.file("h.csv");
    for (const std::vector<std::string>& extra :
         std::vector<std::vector<std::string>>{{"--speed", "4"},
                                               {"--pty-link", dir.file("board")},
                                               {"--cycles"},
                                               {"--gdb", "1234"},
                                               {"--elf", out},
                                               {"--seed", "-5"},
                                               {"--seed", "18446744073709551616"},
                                               {"--duration", "1e30"},
                                               {"--pty", "--json"},
                                               {"--pty", "--speed", "inf"}}) {
        std::vector<std::string> args = {"hil", "-o", out};
        args.insert(args.end(), extra.begin(), extra.end());
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << extra.front() << ": " << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
    // On a pseudo-terminal the recorder configures the board: the firmware options had been ignored there.
    for (const std::vector<std::string>& extra : std::vector<std::vector<std::string>>{{"--period", "0.5"},
                                                                                       {"--window", "3"},
                                                                                       {"--conversions", "5"},
                                                                                       {"--order", "1"},
                                                                                       {"--raw"},
                                                                                       {"--stream"}}) {
        std::vector<std::string> args = {"hil", "--pty", "--duration", "1"};
        args.insert(args.end(), extra.begin(), extra.end());
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << extra.front() << ": " << r.output;
        EXPECT_NE(r.output.find(extra.front() + ": with --pty the recorder configures the board"), std::string::npos)
            << r.output;
    }
    // A folder given as the model had run the paper's model under the folder's name, exit 0.
    const RunResult folder =
        run_driftlab({"hil", "--model", dir.path().string(), "--duration", "2", "-o", out}, dir.path());
    EXPECT_EQ(folder.exit_code, 5) << folder.output;
    EXPECT_NE(folder.output.find("is a folder, not a model file"), std::string::npos) << folder.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    const RunResult largest =
        run_driftlab({"hil", "--duration", "2", "--seed", "18446744073709551615", "-o", out}, dir.path());
    EXPECT_EQ(largest.exit_code, 0) << largest.output;
}

}  // namespace
}  // namespace driftlab::e2e
