// `driftlab gap` on a damaged log: a stuck channel, a shock, a corrupt row. Each is named, counted or left out
// with the --exclude window that removes it, and the rest of the log still reads as the simulator's own.
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

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
    // What the range kept, beside the JSON as fit and allan say it (rows 1 s apart from 1.119 s to 400.119 s).
    EXPECT_EQ(later.err, "note: --from 110 kept 291 of 400 rows, t = 110.119 s to 400.119 s\n");
    {
        std::ifstream file(dir.file("later.toml"));
        std::string first;
        std::getline(file, first);
        EXPECT_EQ(first.rfind("# driftlab gap " + stuck + " (rows from 110.119 s to 400.119 s): verdict ", 0), 0u)
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

    // After the first 100 s, which the report says it analysed (rows 1 s apart from t = 1.119 s).
    const RunResult text = run_driftlab(
        {"gap", corrupt, "--replicates", "10", "--locate-only", "--from", "100", "--report", dir.file("report")},
        dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("\nwarning: gyro: " + warning + "\n"), std::string::npos) << text.output;
    const std::string md = read_text(dir.file("report/gap.md"));
    EXPECT_NE(md.find("\nWarning: gyro: " + warning + "\n"), std::string::npos);
    EXPECT_NE(md.find("\n501 rows analysed, t = 100.119 s to 600.119 s.\n"), std::string::npos) << md.substr(0, 400);
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
    const std::string two = "2 lone values (t = 750.119 s: 1023, t = 1101.119 s: 1023)";
    const RunResult fit = run_driftlab({"fit", twice, "--channel", "accel_x"}, dir.path());
    ASSERT_EQ(fit.exit_code, 0) << fit.output;
    EXPECT_NE(fit.output.find(two), std::string::npos) << fit.output;
    const RunResult allan = run_driftlab({"allan", twice, "--channel", "accel_x", "--json"}, dir.path());
    ASSERT_EQ(allan.exit_code, 0) << allan.output;
    const auto warning = nlohmann::json::parse(allan.output)["channels"]["accel_x"]["lone_values_warning"];
    ASSERT_TRUE(warning.is_string()) << allan.output;
    EXPECT_NE(warning.get<std::string>().find(two), std::string::npos) << warning;
}

}  // namespace
}  // namespace driftlab::e2e
