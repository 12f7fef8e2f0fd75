// `driftlab whiteness`, `fit` and `report` from the command line: whiteness prints every warning of the analysis as
// fit does (it had printed only the adaptation note), a table without a time column says that t is the row index,
// the timing options take allan's and gap's spelling, a log refuses a sample period its rows contradict, and fit's
// table says its units, the accelerometer scale it assumes and what it cannot determine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include <nlohmann/json.hpp>

#include "driftlab/proto/wire.hpp"
#include "e2e_support.hpp"
#include "firmware/core/version.hpp"

namespace driftlab::e2e {
namespace {

// 600 rows 1 s apart with a 30 s hole after row 300, eq. 1 plus a deterministic zig-zag.
std::string table_with_gap(const TempDir& dir) {
    const std::string path = dir.file("gap.csv");
    std::ofstream out(path);
    out << "t_s,gyro\n";
    for (int k = 0; k < 600; ++k) {
        const double t = 1.0 + k + (k >= 300 ? 30.0 : 0.0);
        out << t << ',' << 3.0 * (1.0 - std::exp(-t / 150.0)) + 505.0 + 0.2 * std::sin(2.3 * k) << '\n';
    }
    return path;
}

TEST(AnalysisCli, WhitenessPrintsTheWarningsFitPrints) {
    TempDir dir("whitewarn");
    const std::string table = table_with_gap(dir);
    const RunResult fit = run_driftlab({"fit", table}, dir.path());
    const RunResult white = run_driftlab({"whiteness", table}, dir.path());
    ASSERT_EQ(white.exit_code, 0) << white.output;
    const std::string gap_warning = "warning: 1 gaps in time (spacing > 1.5x the median 1 s; the longest 31 s)";
    EXPECT_NE(fit.output.find(gap_warning), std::string::npos) << fit.output;
    EXPECT_NE(white.output.find(gap_warning), std::string::npos) << white.output;
    const RunResult json = run_driftlab({"whiteness", table, "--json"}, dir.path());
    const auto warnings = json.output.find("\"warnings\": [");
    ASSERT_NE(warnings, std::string::npos) << json.output;
    EXPECT_LT(json.output.find("\"1 gaps in time", warnings), json.output.find("\"whiteness\"")) << json.output;
}

TEST(AnalysisCli, ATableWithoutTimeSaysTIsTheRowIndex) {
    TempDir dir("rowindex");
    const std::string path = dir.file("values.txt");
    std::ofstream(path) << "1 2 3 5 4 6 7 9 8 10 11 13 12 14 15 17 16 18 19 21 20 22 23 25 24\n";
    for (const char* command : {"fit", "whiteness"}) {
        const RunResult r = run_driftlab({command, path}, dir.path());
        EXPECT_NE(r.output.find("no time column: t is the row index x 1 s"), std::string::npos) << command << r.output;
    }
}

/// Occurrences of `what` in `text`.
std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

/// The lines of fit's table: from its header (starting "channel") to the first line that is not a series' row.
std::vector<std::string> table_rows(const std::string& output) {
    const auto lines = lines_of(output);
    auto it = std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return l.rfind("channel", 0) == 0; });
    std::vector<std::string> rows;
    for (; it != lines.end() && !it->empty() && it->find(": ") == std::string::npos; ++it) rows.push_back(*it);
    return rows;
}

// allan and gap spell the period --tau0 and the time window --from/--to: fit, whiteness and report had refused
// both ("The following arguments were not expected: 0.01 --tau0").
TEST(AnalysisCli, TauZeroFromAndToAreOtherNamesOfTheTimingOptions) {
    TempDir dir("timingnames");
    const std::string path = dir.file("rate.txt");
    {
        std::ofstream out(path);
        for (int k = 0; k < 1200; ++k)
            out << 3.0 * (1.0 - std::exp(-0.5 * k / 150.0)) + 505.0 + 0.2 * std::sin(2.3 * k) << '\n';
    }
    const SplitRun given = run_driftlab_split(
        {"fit", path, "--json", "--sample-period", "0.5", "--t-min", "20", "--t-max", "500"}, dir.path());
    const SplitRun alias =
        run_driftlab_split({"fit", path, "--json", "--tau0", "0.5", "--from", "20", "--to", "500"}, dir.path());
    ASSERT_EQ(alias.exit_code, 0) << alias.err;
    EXPECT_EQ(alias.out, given.out);
    EXPECT_EQ(nlohmann::json::parse(alias.out)["channels"]["col1"]["t_last_s"], 500.0);
    // Beside the JSON, on the error output, what the range kept (rows 0.5 s apart from t = 0: 20 s to 500 s).
    EXPECT_EQ(alias.err, "note: --from 20 --to 500 kept 961 of 1200 rows, t = 20 s to 500 s\n");
    EXPECT_EQ(given.err, alias.err);
    const RunResult whiteness = run_driftlab({"whiteness", path, "--tau0", "0.5", "--from", "20"}, dir.path());
    EXPECT_EQ(whiteness.exit_code, 0) << whiteness.output;
    EXPECT_NE(whiteness.output.find("note: --from 20 kept 1160 of 1200 rows, t = 20 s to 599.5 s\n"), std::string::npos)
        << whiteness.output;
    const RunResult report = run_driftlab(
        {"report", path, "--tau0", "0.5", "--to", "500", "-o", dir.file("r.html"), "--no-plots"}, dir.path());
    EXPECT_EQ(report.exit_code, 0) << report.output;
    EXPECT_NE(report.output.find("note: --to 500 kept 1001 of 1200 rows, t = 0 s to 500 s\n"), std::string::npos)
        << report.output;
    const RunResult help = run_driftlab({"fit", "--help"}, dir.path());
    EXPECT_NE(help.output.find("--sample-period,--tau0"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("--from,--t-min"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("--to,--t-max"), std::string::npos) << help.output;
    // A refusal names an option by all its spellings, as the notes name --sample-period/--tau0, so that the one typed
    // is there: `fit --tau0 -1` had been refused as --sample-period.
    const RunResult refused = run_driftlab({"fit", path, "--t-min", "5 "}, dir.path());
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.output.find("driftlab: error: --from/--t-min: expected a finite number, got '5 '\n"),
              std::string::npos)
        << refused.output;
    const RunResult tau0 = run_driftlab({"fit", path, "--tau0", "-1"}, dir.path());
    EXPECT_EQ(tau0.exit_code, 2) << tau0.output;
    EXPECT_NE(tau0.output.find("driftlab: error: --sample-period/--tau0: expected a number > 0, got '-1'\n"),
              std::string::npos)
        << tau0.output;
    // One spelling is named as it is: -o is --output's short name, not a second spelling of a long one.
    const RunResult output = run_driftlab({"report", path, "-o", ""}, dir.path());
    EXPECT_EQ(output.exit_code, 2) << output.output;
    EXPECT_NE(output.output.find("driftlab: error: --output: expected a path, got ''\n"), std::string::npos)
        << output.output;
}

// A canonical log carries its own time: --sample-period 7 on one had been dropped without a word. One that
// contradicts the rows is refused, one that agrees is noted as unused (beside JSON on the error output).
TEST(AnalysisCli, ASamplePeriodOnALogIsRefusedOrNoted) {
    TempDir dir("logperiod");
    const std::string log = dir.file("h.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "300", "-o", log}, dir.path()).exit_code, 0);
    const std::string html = dir.file("r.html");
    for (const auto& args : {std::vector<std::string>{"fit", log, "--sample-period", "7"},
                             {"whiteness", log, "--tau0", "7"},
                             {"report", log, "--sample-period", "7", "-o", html, "--no-plots"}}) {
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.output;
        EXPECT_NE(r.output.find("--sample-period/--tau0 7 s contradicts " + log +
                                ": it is a driftlab log, timed by "
                                "its own t_s column, whose rows are 1 s apart"),
                  std::string::npos)
            << args[0] << ": " << r.output;
    }
    const RunResult agrees = run_driftlab({"fit", log, "--tau0", "1"}, dir.path());
    EXPECT_EQ(agrees.exit_code, 0) << agrees.output;
    EXPECT_NE(agrees.output.find("note: --sample-period/--tau0 1 s is not used: " + log), std::string::npos)
        << agrees.output;
    const SplitRun json = run_driftlab_split({"fit", log, "--tau0", "1", "--json"}, dir.path());
    EXPECT_EQ(json.exit_code, 0) << json.err;
    EXPECT_NE(json.err.find("note: --sample-period/--tau0 1 s is not used"), std::string::npos) << json.err;
    EXPECT_TRUE(nlohmann::json::parse(json.out).contains("channels"));  // the note is not in it
}

// --time-column on a canonical log had been dropped without a word, as --sample-period had: a log is timed by its
// t_s alone.
TEST(AnalysisCli, ATimeColumnOnALogIsRefusedOrNoted) {
    TempDir dir("logtimecolumn");
    const std::string log = dir.file("h.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "300", "-o", log}, dir.path()).exit_code, 0);
    for (const auto& args : {std::vector<std::string>{"fit", log, "--time-column", "seq"},
                             {"report", log, "--time-column", "seq", "-o", dir.file("r.html"), "--no-plots"}}) {
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.output;
        EXPECT_NE(r.output.find("--time-column seq contradicts " + log +
                                ": it is a driftlab log, timed by its own t_s "
                                "column; leave the option out (it is for plain tables)"),
                  std::string::npos)
            << args[0] << ": " << r.output;
    }
    const RunResult own = run_driftlab({"whiteness", log, "--time-column", "t_s"}, dir.path());
    EXPECT_EQ(own.exit_code, 0) << own.output;
    EXPECT_NE(own.output.find("note: --time-column t_s is not used: " + log), std::string::npos) << own.output;
}

// A warm unit (T far beyond the record) and a singular fit had printed the fit's arbitrary values in the table
// (gyro -6.92737e+11 counts on hil --warm 3200), out of line, and "+- inf" below it.
TEST(AnalysisCli, WhatTheDataDoNotDetermineReadsNotDetermined) {
    TempDir dir("undetermined");
    const std::string warm = dir.file("warm.csv");
    const std::string unix_time = dir.file("unix.csv");
    {
        std::ofstream w(warm), u(unix_time);
        w << "t_s,gyro,settling\n";
        u << "t_s,gyro\n";
        for (int k = 1; k <= 1500; ++k) {
            const double noise = 0.2 * std::sin(2.3 * k);
            w << k << ',' << 508.0 - 1e-3 * k + noise << ',' << 3.0 * (1.0 - std::exp(-k / 150.0)) + 505.0 + noise
              << '\n';
            u << std::setprecision(12) << 1.7e9 + k << ',' << 3.0 * (1.0 - std::exp(-k / 411.0)) + 505.0 + noise
              << '\n';
        }
    }
    const RunResult w = run_driftlab({"fit", warm}, dir.path());
    ASSERT_EQ(w.exit_code, 0) << w.output;
    const auto rows = table_rows(w.output);
    ASSERT_EQ(rows.size(), 3u) << w.output;
    EXPECT_NE(rows[1].find("not determined"), std::string::npos) << w.output;
    EXPECT_EQ(rows[2].find("not determined"), std::string::npos) << w.output;
    EXPECT_EQ(count_of(rows[1], "not determined"), 2u) << w.output;  // C1 and T; C2 is the line's start
    EXPECT_NE(
        w.output.find("gyro: not determined: T is beyond the record, which determines only the initial slope C1/T"),
        std::string::npos)
        << w.output;
    EXPECT_NE(w.output.find("  C1 = not determined"), std::string::npos) << w.output;
    const auto slope = w.output.find("  C1/T = ");
    ASSERT_NE(slope, std::string::npos) << w.output;
    EXPECT_NEAR(std::stod(w.output.substr(slope + 9)), -1e-3, 1e-5) << w.output;
    // Columns line up whatever is in them.
    const auto status = rows[0].find("status");
    for (const auto& row : rows) EXPECT_TRUE(row[status - 1] == ' ' && row[status] != ' ') << w.output;

    const RunResult u = run_driftlab({"fit", unix_time}, dir.path());
    ASSERT_EQ(u.exit_code, 0) << u.output;
    EXPECT_NE(u.output.find("singular"), std::string::npos) << u.output;
    EXPECT_EQ(count_of(table_rows(u.output)[1], "not determined"), 3u) << u.output;
    EXPECT_EQ(u.output.find("+- inf"), std::string::npos) << u.output;
    EXPECT_EQ(u.output.find("-inf"), std::string::npos) << u.output;
    const nlohmann::json j = nlohmann::json::parse(run_driftlab({"fit", unix_time, "--json"}, dir.path()).output);
    EXPECT_TRUE(j["channels"]["gyro"]["C1"]["stderr"].is_null()) << j.dump();
    EXPECT_TRUE(j["channels"]["gyro"]["C1"]["value"].is_number()) << j.dump();  // JSON keeps the value
}

// The table says its units (C2 from mid-scale, rms in counts) also when the fit failed, gives p to 3 digits, the
// accelerometer's assumed scale, and each failure's reason once (they had been printed in the table and again).
TEST(AnalysisCli, TheTableSaysItsUnitsAndEachErrorOnce) {
    TempDir dir("fittable");
    const std::string log = dir.file("h.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "300", "-o", log}, dir.path()).exit_code, 0);
    const RunResult r = run_driftlab({"fit", log}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto rows = table_rows(r.output);
    ASSERT_EQ(rows.size(), 5u) << r.output;
    EXPECT_NE(rows[0].find("C2 [counts] (physical from mid-scale)"), std::string::npos) << rows[0];
    EXPECT_NE(rows[0].find("rms [counts]"), std::string::npos) << rows[0];
    for (const auto& line : lines_of(r.output)) {
        const auto p = line.find(", p = ");
        if (p == std::string::npos) continue;
        const std::string value = line.substr(p + 6, line.find(' ', p + 6) - p - 6);
        EXPECT_LE(value.size(), 7u) << line;  // 0.00332 or 0.357, not 0.00332395
    }
    const std::string accel_note = "note: accelerometer values in mm/s^2 at 19.14 mm/s^2 (1/512 g) per count";
    EXPECT_NE(r.output.find(accel_note), std::string::npos) << r.output;
    EXPECT_EQ(run_driftlab({"fit", log, "--channel", "gyro"}, dir.path()).output.find(accel_note), std::string::npos);
    const std::string html = dir.file("r.html");
    ASSERT_EQ(run_driftlab({"report", log, "-o", html, "--no-plots"}, dir.path()).exit_code, 0);
    EXPECT_NE(read_text(html).find("accelerometer values in mm/s^2 at 19.14 mm/s^2 (1/512 g) per count"),
              std::string::npos);

    const RunResult failed = run_driftlab({"fit", log, "--t-max", "10"}, dir.path());
    EXPECT_EQ(failed.exit_code, 3) << failed.output;
    EXPECT_NE(failed.output.find("C1 [counts]"), std::string::npos) << failed.output;
    EXPECT_EQ(failed.output.find("[table unit]"), std::string::npos) << failed.output;
    EXPECT_EQ(count_of(failed.output, "9 samples in the selected time range"), 4u) << failed.output;
    EXPECT_NE(failed.output.find(log + ": not analysed: gyro, accel_x, accel_y, accel_z (the reasons are above)"),
              std::string::npos)
        << failed.output;

    // Where no series can be analysed, report writes no page of empty tables, and says the shared reason once
    // with the span the range missed.
    const std::string none = dir.file("none.html");
    const RunResult empty = run_driftlab({"report", log, "--from", "400", "-o", none, "--no-plots"}, dir.path());
    EXPECT_EQ(empty.exit_code, 3) << empty.output;
    EXPECT_FALSE(std::filesystem::exists(none));
    EXPECT_EQ(count_of(empty.output, "samples in the selected time range"), 1u) << empty.output;
    EXPECT_NE(empty.output.find("series 'gyro', 'accel_x', 'accel_y', 'accel_z': 0 samples in the selected time range "
                                "(the series' rows run from "),
              std::string::npos)
        << empty.output;
}

// report on a `hil` log opens with what was recorded, from the log's header: the simulation and its seed, the
// firmware, the rate and the on-board smoothing.
TEST(AnalysisCli, ReportOpensWithTheRecordingOfAHilLog) {
    TempDir dir("reportrecording");
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "60", "--seed", "7", "-o", log}, dir.path()).exit_code, 0);
    const std::string html = dir.file("r.html");
    ASSERT_EQ(run_driftlab({"report", log, "-o", html, "--no-plots"}, dir.path()).exit_code, 0);
    const std::string page = read_text(html);
    for (const char* row : {"<tr><th>source</th><td>hil: simulated sensor, firmware in the loop</td></tr>",
                            "<tr><th>simulation</th><td>target native, model paper, model file paper (built in), "
                            "preset fig3, seed 7, effects none</td></tr>",
                            "<tr><th>samples</th><td>60</td></tr>",
                            "<tr><th>output rate</th><td>1 Hz (sample_period_s 1 s, poll mode)</td></tr>",
                            "<tr><th>smoothing</th><td>on-board least squares of order 0 (a mean) over 25 conversions, "
                            "25 conversions per output</td></tr>"})
        EXPECT_NE(page.find(row), std::string::npos) << row << "\n" << page;
    // The firmware in the loop reports its own version in VERSION, which the log keeps.
    const std::string firmware = "<tr><th>firmware</th><td>version " + std::to_string(fw::kFwMajor) + "." +
                                 std::to_string(fw::kFwMinor) + "." + std::to_string(fw::kFwPatch) + ", protocol " +
                                 std::to_string(proto::kProtocolVersion) + "</td></tr>";
    EXPECT_NE(page.find(firmware), std::string::npos) << firmware << "\n" << page;
    EXPECT_EQ(page.find("<th>start</th>"), std::string::npos);  // hil runs in virtual time: no start to show
}

// report --unit puts a plain table's columns in physical units (the noise terms in navigation units follow, and the
// JSON's unit); each bad value is refused naming itself (exit 2) before a page is written, and a log takes none.
TEST(AnalysisCli, ReportUnitsForAPlainTable) {
    TempDir dir("reportunit");
    const std::string table = table_with_gap(dir);  // its one column: gyro
    const std::string html = dir.file("r.html");
    const SplitRun ok =
        run_driftlab_split({"report", table, "--unit", "gyro:deg/s", "-o", html, "--no-plots", "--json"}, dir.path());
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_EQ(nlohmann::json::parse(ok.out)["channels"]["gyro"]["unit"], "deg/s");
    const std::string page = read_text(html);
    EXPECT_NE(page.find("<th>B [deg/s]</th>"), std::string::npos) << page;
    EXPECT_NE(page.find("Rate gyros: noise terms in navigation units"), std::string::npos) << page;

    const std::string refused = dir.file("refused.html");
    const auto error_of = [&](const std::string& input, const std::string& unit) {
        const RunResult r = run_driftlab({"report", input, "--unit", unit, "-o", refused, "--no-plots"}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << r.output;
        return r.output;
    };
    EXPECT_NE(error_of(table, "gyro:deg/sec")
                  .find("--unit 'gyro:deg/sec': unknown unit 'deg/sec'; angular rate: "
                        "deg/s, dps, mdps, deg/h, rad/s; acceleration: g, mg"),
              std::string::npos);
    EXPECT_NE(error_of(table, "gx:deg/s")
                  .find("--unit 'gx:deg/s': " + table +
                        " has no column 'gx' among those "
                        "analysed (gyro)"),
              std::string::npos);
    const std::string log = dir.file("hil.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "60", "-o", log}, dir.path()).exit_code, 0);
    EXPECT_NE(error_of(log, "mg").find("--unit: " + log + " is a driftlab log"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(refused));
}

// Every number of `a` within a relative 1e-9 of `b`'s (absolutely for those near 0), the rest equal.
void expect_close(const nlohmann::json& a, const nlohmann::json& b, const std::string& where) {
    ASSERT_EQ(a.type(), b.type()) << where;
    if (a.is_object()) {
        ASSERT_EQ(a.size(), b.size()) << where;
        for (auto it = a.begin(); it != a.end(); ++it) {
            ASSERT_TRUE(b.contains(it.key())) << where << "." << it.key();
            expect_close(it.value(), b.at(it.key()), where + "." + it.key());
        }
    } else if (a.is_array()) {
        ASSERT_EQ(a.size(), b.size()) << where;
        for (std::size_t i = 0; i < a.size(); ++i) expect_close(a[i], b[i], where + "[" + std::to_string(i) + "]");
    } else if (a.is_number_float()) {
        const double x = a.get<double>(), y = b.get<double>();
        EXPECT_LE(std::abs(x - y), 1e-9 * std::max(1.0, std::max(std::abs(x), std::abs(y)))) << where;
    } else {
        EXPECT_EQ(a, b) << where;
    }
}

// DRIFTLAB_FFT_PORTABLE=1 plans the transforms without the CPU's vector codelets: the same results but for the last
// digits (a transform rounds at 1e-16 of its largest bin either way).
TEST(AnalysisCli, PortableTransformsGiveTheSameFitToTheLastDigits) {
    TempDir dir("portable");
    const std::string table = table_with_gap(dir);
    const RunResult fast = run_driftlab({"fit", table, "--json"}, dir.path());
    ASSERT_EQ(fast.exit_code, 0) << fast.output;
    ::setenv("DRIFTLAB_FFT_PORTABLE", "1", 1);
    const RunResult portable = run_driftlab({"fit", table, "--json"}, dir.path());
    ::unsetenv("DRIFTLAB_FFT_PORTABLE");
    ASSERT_EQ(portable.exit_code, 0) << portable.output;
    const auto a = nlohmann::json::parse(fast.output), b = nlohmann::json::parse(portable.output);
    ASSERT_TRUE(a.contains("channels")) << fast.output;
    expect_close(a, b, "fit");
}

}  // namespace
}  // namespace driftlab::e2e
