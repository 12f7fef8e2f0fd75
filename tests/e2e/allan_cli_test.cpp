// `driftlab allan` options against the file they describe: a --tau0 that is not the time column's spacing would
// pack or spread the rows on the grid (wrong taus, a real gap closed up), the time column is not a series, and a
// plain file's turn-on drift is removed only on request.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "e2e_support.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/view/allan_section.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::e2e {
namespace {

// 2000 rows 0.02 s apart of a deterministic zig-zag.
std::string table_at_50_hz(const TempDir& dir) {
    const std::string path = dir.file("t50hz.txt");
    std::ofstream out(path);
    out << "t_s gx\n";
    for (int k = 0; k < 2000; ++k) out << 0.02 * k << ' ' << std::sin(0.7 * k) + 0.1 * (k % 7) << '\n';
    return path;
}

// A table "t_s gx" of `rows` rows, `row` writing row k's two numbers.
void write_gx_table(const std::string& path, int rows, const std::function<void(std::ostream&, int)>& row) {
    std::ofstream out(path);
    out << "t_s gx\n";
    for (int k = 0; k < rows; ++k) {
        row(out, k);
        out << '\n';
    }
}

// 3000 samples 1 s apart of eq. 1 (C1 = 0.3, C2 = 0.1, T = 600 s) with white noise of 0.02.
std::vector<double> warming_rate(unsigned seed) {
    std::vector<double> v(3000);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 0.02);
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = 0.4 - 0.3 * std::exp(-static_cast<double>(k) / 600.0) + g(rng);
    return v;
}

// A log's accelerometer noise density in SI is the simulator's noise: each 1 s output is the mean of 25 conversions
// (the paper's preset, order 0), so N = sigma_conversion / sqrt(25) x sqrt(1 s), in m/s^2/sqrt(Hz). The host had read
// a count as 19.14 cm/s^2 and given ten times that (docs/analysis.md §2).
TEST(AllanCli, AnAccelerometersNoiseDensityIsTheSimulatorsNoiseInSI) {
    TempDir dir("allanaccel");
    const std::string log = dir.file("h.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "2000", "-o", log}, dir.path()).exit_code, 0);
    const RunResult r = run_driftlab({"allan", log, "--channel", "accel_x", "--json"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    const double n = j["channels"]["accel_x"]["terms"]["physical"]["N_m_per_s2_per_sqrt_hz"].get<double>();
    const double sigma_g = sim::paper_model().channels[1].raw_noise_std_unit;
    const double expected = sigma_g * 9.80665 / std::sqrt(25.0);
    EXPECT_NEAR(n / expected, 1.0, 0.15) << n << " vs " << expected;
    EXPECT_EQ(j["channels"]["accel_x"]["kalibr"]["accelerometer_noise_density"].get<double>(), n);
}

TEST(AllanCli, ATau0OtherThanTheRowsSpacingIsRefused) {
    TempDir dir("allantau0");
    const std::string table = table_at_50_hz(dir);
    for (const char* tau0 : {"0.01", "0.04"}) {
        const RunResult r = run_driftlab({"allan", table, "--kind", "rate", "--tau0", tau0}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << tau0 << ": " << r.output;
        EXPECT_NE(r.output.find("rows are 0.02 s apart (median; mean 0.02 s)"), std::string::npos) << r.output;
    }
    const RunResult ok = run_driftlab({"allan", table, "--kind", "rate", "--tau0", "0.02"}, dir.path());
    EXPECT_EQ(ok.exit_code, 0) << ok.output;
    EXPECT_NE(ok.output.find("0 gap samples"), std::string::npos) << ok.output;
}

// The table's n column hides what gaps cost: runs of 100 rows 0.02 s apart with 5 rows lost between them. Long
// taus lose most terms (a term spans 2 tau, a run 2 s), which the text says with the longest gap-free stretch.
TEST(AllanCli, TheTextSaysWhenGapsSkipMostTerms) {
    TempDir dir("allangaps");
    const std::string path = dir.file("gappy.txt");
    {
        std::ofstream out(path);
        out << "t_s gx\n";
        for (int k = 0; k < 4200; ++k)
            if (k % 105 < 100) out << 0.02 * k << ' ' << std::sin(0.7 * k) + 0.1 * (k % 7) << '\n';
    }
    const RunResult r = run_driftlab({"allan", path, "--kind", "rate", "--tau0", "0.02"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("note: gaps skip more than 20 % of the terms from tau = "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("the longest gap-free stretch is 2 s"), std::string::npos) << r.output;
    const RunResult whole =
        run_driftlab({"allan", table_at_50_hz(dir), "--kind", "rate", "--tau0", "0.02"}, dir.path());
    EXPECT_EQ(whole.output.find("note: gaps"), std::string::npos) << whole.output;
}

// The zig-zag has no flat floor and no long-term wander: the fit pins B, K and R at 0. Every output says so; none
// writes a number a Kalibr or VINS configuration would take for a measured zero: JSON null where the text says
// "not resolved (<= bound)", the Kalibr random walk (K) included. The keys stay.
TEST(AllanCli, UnresolvedTermsAreNullInJsonAndMarkedInTextInEveryUnit) {
    TempDir dir("allanunresolved");
    const std::string table = table_at_50_hz(dir);
    const std::vector<std::string> base = {"allan", table, "--kind", "rate", "--tau0", "0.02", "--unit", "deg/s"};
    std::vector<std::string> with_json = base;
    with_json.push_back("--json");
    const RunResult j_run = run_driftlab(with_json, dir.path());
    ASSERT_EQ(j_run.exit_code, 0) << j_run.output;
    const RunResult text = run_driftlab(base, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    const auto terms = nlohmann::json::parse(j_run.output)["channels"]["gx"]["terms"];
    const auto kalibr = nlohmann::json::parse(j_run.output)["channels"]["gx"]["kalibr"];
    // The text line of `key`, e.g. "      K_deg_per_s_per_sqrt_s     not resolved (<= 0.0088222)".
    const auto text_line = [&](const std::string& key) {
        const std::size_t at = text.output.find(" " + key + " ");
        return at == std::string::npos ? std::string() : text.output.substr(at, text.output.find('\n', at) - at);
    };
    const std::map<std::string, std::string> kalibr_key = {{"N", "gyroscope_noise_density"},
                                                           {"K", "gyroscope_random_walk"}};
    for (const char* sym : {"B", "K", "R"}) ASSERT_TRUE(terms[sym]["std_error"].is_null()) << sym << ": " << terms[sym];
    ASSERT_FALSE(terms["N"]["std_error"].is_null());
    for (const auto& [key, value] : terms["physical"].items()) {
        const bool unresolved = terms[key.substr(0, 1)]["std_error"].is_null();
        EXPECT_EQ(value.is_null(), unresolved) << key << " = " << value;
        EXPECT_EQ(text_line(key).find("not resolved (<= ") != std::string::npos, unresolved) << text_line(key);
    }
    for (const auto& [sym, key] : kalibr_key) {
        ASSERT_TRUE(kalibr.contains(key)) << kalibr;
        const bool unresolved = terms[sym]["std_error"].is_null();
        EXPECT_EQ(kalibr[key].is_null(), unresolved) << key << " = " << kalibr[key];
        EXPECT_EQ(text_line(key).find("not resolved (<= ") != std::string::npos, unresolved) << text_line(key);
    }
}

// allan --unit takes report's [COLUMN:]UNIT from the one unit table: a column's own unit, the others the one for
// every column, and the Kalibr densities follow each in SI. ax is gx doubled (exact: a power of two), so its density
// in mg is 2 x 9.80665e-3 m/s^2 per deg/s's pi/180 rad/s times gx's. A misspelt unit had been taken for a label that
// silently dropped the physical terms: it is refused (exit 2) naming itself and the known units, as is a column the
// file does not have.
TEST(AllanCli, UnitsAreReportsColumnUnitsAndAMisspeltOneIsRefused) {
    TempDir dir("allanunit");
    const std::string table = dir.file("two.txt");
    {
        std::ofstream out(table);
        out.precision(17);  // ax exactly twice gx as read back, not each rounded to 6 digits on its own
        out << "t_s gx ax\n";
        for (int k = 0; k < 2000; ++k) {
            const double z = std::sin(0.7 * k) + 0.1 * (k % 7);
            out << 0.02 * k << ' ' << z << ' ' << 2.0 * z << '\n';
        }
    }
    const std::vector<std::string> base = {"allan", table, "--kind", "rate", "--tau0", "0.02"};
    const auto run_with = [&](const std::vector<std::string>& extra) {
        std::vector<std::string> args = base;
        args.insert(args.end(), extra.begin(), extra.end());
        return run_driftlab(args, dir.path());
    };
    const RunResult r = run_with({"--unit", "gx:dps", "--unit", "mg", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto channels = nlohmann::json::parse(r.output)["channels"];
    EXPECT_EQ(channels["gx"]["terms"]["unit"], "deg/s");
    EXPECT_EQ(channels["ax"]["terms"]["unit"], "mg");
    const double gyro = channels["gx"]["kalibr"]["gyroscope_noise_density"].get<double>();
    const double accel = channels["ax"]["kalibr"]["accelerometer_noise_density"].get<double>();
    EXPECT_NEAR(accel / gyro, 2.0 * 9.80665e-3 / (std::numbers::pi / 180.0), 1e-9);

    const auto error_of = [&](const std::string& unit) {
        const RunResult refused = run_with({"--unit", unit});
        EXPECT_EQ(refused.exit_code, 2) << refused.output;
        return refused.output;
    };
    EXPECT_NE(error_of("deg/sec").find("--unit 'deg/sec': unknown unit 'deg/sec'; angular rate: deg/s, dps, mdps, "
                                       "deg/h, rad/s; acceleration: g, mg"),
              std::string::npos);
    EXPECT_NE(error_of("gz:deg/s")
                  .find("--unit 'gz:deg/s': " + table +
                        " has no column 'gz' among those analysed "
                        "(gx, ax)"),
              std::string::npos);
}

// Phase samples name their integral's unit: an angle in deg is the integral of a rate in deg/s, so the same noise
// given as its rate (deg/s) and as that rate summed times tau0 (deg) has the same deviations, terms and Kalibr
// densities. A time (ns) gives a clock's fractional frequency, in ns/s, with no navigation terms. A rate's unit for
// phase samples had been the only kind accepted, and `--unit deg` or `--unit ns` refused; now a rate's unit there is
// refused, naming the integral's.
TEST(AllanCli, PhaseSamplesNameTheirIntegralsUnit) {
    TempDir dir("allanphase");
    const std::string rate = dir.file("rate.txt"), phase = dir.file("phase.txt");
    {
        std::ofstream r(rate), p(phase);
        r.precision(17), p.precision(17);
        std::mt19937_64 rng(11);
        std::normal_distribution<double> g(0.0, 0.05);
        std::vector<double> y(4000);
        double mean = 0.0;
        for (double& v : y) mean += (v = 0.3 + g(rng)) / static_cast<double>(y.size());
        // The pipeline's own phase of a rate: x_0 = 0, x_{k+1} = x_k + (y_k - mean) tau0 (docs/allan.md §2).
        double x = 0.0;
        p << x << '\n';
        for (double v : y) {
            r << v << '\n';
            p << (x += (v - mean) * 0.01) << '\n';
        }
    }
    const auto json_of = [&](const std::vector<std::string>& args) {
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return nlohmann::json::parse(r.output)["channels"]["col1"];
    };
    const auto from_rate = json_of({"allan", rate, "--kind", "rate", "--tau0", "0.01", "--unit", "deg/s", "--json"});
    const auto from_phase = json_of({"allan", phase, "--kind", "phase", "--tau0", "0.01", "--unit", "deg", "--json"});
    EXPECT_EQ(from_phase["terms"]["unit"], "deg/s");
    ASSERT_EQ(from_phase["adev"].size(), from_rate["adev"].size());
    for (std::size_t i = 0; i < from_rate["adev"].size(); ++i)
        EXPECT_NEAR(from_phase["adev"][i].get<double>() / from_rate["adev"][i].get<double>(), 1.0, 1e-9) << i;
    const double n_rate = from_rate["kalibr"]["gyroscope_noise_density"].get<double>();
    EXPECT_NEAR(from_phase["kalibr"]["gyroscope_noise_density"].get<double>() / n_rate, 1.0, 1e-9);
    // White rate noise of 0.05 deg/s at 100 Hz: N = 0.05 x sqrt(0.01 s) deg/s/sqrt(Hz), in rad/s/sqrt(Hz).
    EXPECT_NEAR(n_rate / (0.05 * 0.1 * std::numbers::pi / 180.0), 1.0, 0.1);

    const auto clock = json_of({"allan", phase, "--kind", "phase", "--tau0", "0.01", "--unit", "ns", "--json"});
    EXPECT_EQ(clock["terms"]["unit"], "ns/s");
    EXPECT_TRUE(clock["kalibr"].is_null()) << clock["kalibr"];
    EXPECT_TRUE(clock["terms"]["physical"].empty()) << clock["terms"]["physical"];
    EXPECT_FALSE(from_phase["terms"]["physical"].empty());

    const RunResult refused =
        run_driftlab({"allan", phase, "--kind", "phase", "--tau0", "0.01", "--unit", "deg/s"}, dir.path());
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(
        refused.output.find("--unit 'deg/s': unknown unit 'deg/s' for phase samples ('deg/s' is a rate's: give its "
                            "integral's, e.g. deg for deg/s); angle: deg, mdeg, rad; velocity: m/s, cm/s, mm/s; "
                            "time: s, ms, us, ns, ps"),
        std::string::npos)
        << refused.output;
}

// A log whose rows come in bursts (5 rows 2 ms apart every 50 ms, 100 a second, as the MPU6050 recording) gets the
// report's tau0 from `allan` too: the mean spacing, (1199 x 0.05 + 0.008) s / 5999 = 9.995 ms, and as the report's
// Allan section computes it. At the median, 2 ms, `allan` had made a grid 80 % gaps with a curve ending at 16 ms.
TEST(AllanCli, ALogInBurstsGetsTheReportsTau0) {
    TempDir dir("allanbursts");
    const std::string log = dir.file("bursts.csv");
    {
        std::ofstream out(log);
        out << "# driftlab-log: 1\n# source: test\nt_s,seq,gyro,accel_x,accel_y,accel_z\n";
        std::mt19937_64 rng(5);
        std::normal_distribution<double> g(0.0, 0.1);
        for (int k = 0; k < 6000; ++k) {
            out << 0.05 * (k / 5) + 0.002 * (k % 5) << ',' << k << ',' << 505.0 + g(rng);
            for (int c = 0; c < 3; ++c) out << ',' << 470.0 + g(rng);
            out << '\n';
        }
    }
    const RunResult r = run_driftlab({"allan", log, "--channel", "gyro", "--keep-drift", "--json"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto gyro = nlohmann::json::parse(r.output)["channels"]["gyro"];
    const double tau0 = gyro["tau0_s"].get<double>();
    EXPECT_NEAR(tau0, (1199 * 0.05 + 0.008) / 5999, 1e-12);
    EXPECT_LT(gyro["gap_samples"].get<double>(), 0.01 * gyro["samples"].get<double>());
    EXPECT_GT(gyro["tau"].back().get<double>(), 5.0);

    host::fit::FileAnalysisRequest request;
    request.path = log;
    request.names = {"gyro"};
    const host::fit::FileAnalysis file = host::fit::analyse_file(request);
    ASSERT_EQ(file.failures(), 0u) << file.failure_summary();
    const host::view::AllanSection section = host::view::allan_section({&*file.series[0].analysis});
    ASSERT_EQ(section.plots.size(), 1u);
    EXPECT_NEAR(section.plots[0].series[0].x.front() / tau0, 1.0, 1e-12);  // the octave grid's first tau is tau0
}

// Rows packed onto the grid are warned of per channel where they can bias its curve (allan.md §7): a record at
// 2 rows a second for 1000 s, then 1 a second, on a grid of 1 s; steady bursts of white noise are not warned.
TEST(AllanCli, PackingIsWarnedWhereItCanBiasTheCurve) {
    TempDir dir("allanpacking");
    const std::string changed = dir.file("changed.txt");
    const std::string bursts = dir.file("bursts.txt");
    std::mt19937_64 rng(9);
    std::normal_distribution<double> g(0.0, 1.0);
    write_gx_table(changed, 6000,
                   [&](std::ostream& row, int k) { row << (k < 2000 ? 0.5 * k : k - 1000.0) << ' ' << g(rng); });
    write_gx_table(bursts, 6000,
                   [&](std::ostream& row, int k) { row << 0.05 * (k / 5) + 0.002 * (k % 5) << ' ' << g(rng); });
    const RunResult text = run_driftlab({"allan", changed, "--kind", "rate", "--tau0", "1"}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("  warning: 5996 samples came faster than tau0"), std::string::npos) << text.output;
    const RunResult json = run_driftlab({"allan", changed, "--kind", "rate", "--tau0", "1", "--json"}, dir.path());
    ASSERT_EQ(json.exit_code, 0) << json.output;
    EXPECT_TRUE(nlohmann::json::parse(json.output)["channels"]["gx"]["packing_warning"].is_string()) << json.output;

    const RunResult steady = run_driftlab({"allan", bursts, "--kind", "rate", "--tau0", "0.01", "--json"}, dir.path());
    ASSERT_EQ(steady.exit_code, 0) << steady.output;
    const auto gx = nlohmann::json::parse(steady.output)["channels"]["gx"];
    EXPECT_GT(gx["packed_samples"].get<int>(), 0);
    EXPECT_TRUE(gx["packing_warning"].is_null()) << steady.output;
}

// One corrupt row (a bus error's 0x7FFF) in a plain table had given a "converged" fit and an Allan deviation of its
// size at every tau, unremarked: allan, fit and report name it, by time and value, and the --exclude that leaves it
// out; the clean table gets no warning.
TEST(AllanCli, ALoneCorruptRowIsWarnedByAllanFitAndReportAndLeftOutByTheWindowGiven) {
    TempDir dir("allanlone");
    const std::string clean = dir.file("clean.txt");
    const std::string corrupt = dir.file("corrupt.txt");
    const std::vector<double> v = warming_rate(11);
    write_gx_table(clean, 3000, [&](std::ostream& row, int k) { row << k << ' ' << v[k]; });
    write_gx_table(corrupt, 3000, [&](std::ostream& row, int k) { row << k << ' ' << (k == 1234 ? 32767.0 : v[k]); });
    const std::string named = "1 lone value (t = 1234 s: 32767) carries 100 % of the sample-to-sample variance";
    const RunResult text = run_driftlab({"allan", corrupt, "--kind", "rate", "--tau0", "1"}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("  warning: " + named), std::string::npos) << text.output;
    for (const std::string& file : {clean, corrupt}) {
        const RunResult allan = run_driftlab({"allan", file, "--kind", "rate", "--tau0", "1", "--json"}, dir.path());
        ASSERT_EQ(allan.exit_code, 0) << allan.output;
        const auto warning = nlohmann::json::parse(allan.output)["channels"]["gx"]["lone_values_warning"];
        EXPECT_EQ(warning.is_string(), file == corrupt) << allan.output;
        const RunResult fit = run_driftlab({"fit", file, "--json"}, dir.path());
        ASSERT_EQ(fit.exit_code, 0) << fit.output;
        EXPECT_EQ(fit.output.find(named) != std::string::npos, file == corrupt) << fit.output;
    }
    const RunResult report = run_driftlab({"report", corrupt, "--no-plots", "-o", dir.file("r.html")}, dir.path());
    ASSERT_EQ(report.exit_code, 0) << report.output;
    std::ifstream html(dir.file("r.html"));
    const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
    EXPECT_NE(page.find(named), std::string::npos);

    // The window the warning gives leaves the row out: no warning, and what the clean table gives. The fit of 2999
    // of its 3000 rows moves C2 by far less than its standard error; the Allan deviation at tau0 has one gap slot
    // and one term fewer (of 2999), within 1 %.
    EXPECT_NE(text.output.find("leave it out with --exclude 1233.5:1234.5"), std::string::npos) << text.output;
    const RunResult fit_clean = run_driftlab({"fit", clean, "--json"}, dir.path());
    // The note of the rows left out goes to the error output beside --json, from fit and allan alike.
    const SplitRun fit_left = run_driftlab_split({"fit", corrupt, "--exclude", "1233.5:1234.5", "--json"}, dir.path());
    ASSERT_EQ(fit_left.exit_code, 0) << fit_left.err;
    EXPECT_EQ(fit_left.err, "note: --exclude 1233.5:1234.5 left out 1 row\n");
    EXPECT_EQ(fit_left.out.find("lone value"), std::string::npos) << fit_left.out;
    const auto c2_clean = nlohmann::json::parse(fit_clean.output)["channels"]["gx"]["C2"];
    const auto c2_left = nlohmann::json::parse(fit_left.out)["channels"]["gx"]["C2"];
    EXPECT_NEAR(c2_left["value"].get<double>(), c2_clean["value"].get<double>(),
                0.1 * c2_clean["stderr"].get<double>());
    const RunResult allan_clean = run_driftlab({"allan", clean, "--kind", "rate", "--tau0", "1", "--json"}, dir.path());
    const SplitRun allan_left = run_driftlab_split(
        {"allan", corrupt, "--kind", "rate", "--tau0", "1", "--exclude", "1233.5:1234.5", "--json"}, dir.path());
    ASSERT_EQ(allan_left.exit_code, 0) << allan_left.err;
    EXPECT_EQ(allan_left.err, fit_left.err);
    const auto gx_clean = nlohmann::json::parse(allan_clean.output)["channels"]["gx"];
    const auto gx_left = nlohmann::json::parse(allan_left.out)["channels"]["gx"];
    EXPECT_TRUE(gx_left["lone_values_warning"].is_null()) << allan_left.out;
    EXPECT_EQ(gx_left["gap_samples"].get<int>(), 1);
    EXPECT_NEAR(gx_left["adev"][0].get<double>(), gx_clean["adev"][0].get<double>(),
                0.01 * gx_clean["adev"][0].get<double>());

    // A window that holds no row is a mistaken time (exit 3, naming it); one that is not FROM:TO, a usage error.
    const RunResult missed = run_driftlab({"fit", corrupt, "--exclude", "5000:6000"}, dir.path());
    EXPECT_EQ(missed.exit_code, 3);
    EXPECT_NE(missed.output.find("--exclude 5000:6000 holds no row (the series' rows run from 0 s to 2999 s)"),
              std::string::npos)
        << missed.output;
    const RunResult malformed =
        run_driftlab({"allan", corrupt, "--kind", "rate", "--tau0", "1", "--exclude", "5"}, dir.path());
    EXPECT_EQ(malformed.exit_code, 2);
    EXPECT_NE(malformed.output.find("--exclude: expected FROM:TO in seconds since power-on"), std::string::npos)
        << malformed.output;
}

// --from/--to, as fit and gap take them: the curve of a table from t = 1000 s on is the curve of the table cut there,
// to the last bit, drift removed at its times since power-on; a range without two rows names where the rows are.
TEST(AllanCli, FromAndToAnalyseTheRowsOfATableCutThere) {
    TempDir dir("allanfrom");
    const std::string whole = dir.file("whole.txt");
    const std::string cut = dir.file("cut.txt");
    const std::vector<double> v = warming_rate(13);
    write_gx_table(whole, 3000, [&](std::ostream& row, int k) { row << k << ' ' << v[k]; });
    write_gx_table(cut, 1501, [&](std::ostream& row, int k) { row << k + 1000 << ' ' << v[k + 1000]; });
    const std::vector<std::string> allan = {"allan", "--kind", "rate", "--tau0", "1", "--remove-drift", "--json"};
    auto with = [&](std::vector<std::string> args, std::vector<std::string> more) {
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    const SplitRun ranged = run_driftlab_split(with(allan, {whole, "--from", "1000", "--to", "2500"}), dir.path());
    const RunResult alone = run_driftlab(with(allan, {cut}), dir.path());
    ASSERT_EQ(ranged.exit_code, 0) << ranged.err;
    ASSERT_EQ(alone.exit_code, 0) << alone.output;
    // What the range kept is said beside the JSON, and the JSON holds its ends as fit's does.
    EXPECT_EQ(ranged.err, "note: --from 1000 --to 2500 kept 1501 of 3000 rows, t = 1000 s to 2500 s\n");
    auto ranged_gx = nlohmann::json::parse(ranged.out)["channels"]["gx"];
    auto alone_gx = nlohmann::json::parse(alone.output)["channels"]["gx"];
    EXPECT_EQ(ranged_gx["samples"].get<int>(), 1501);
    EXPECT_EQ(ranged_gx["t_first_s"], 1000.0);
    EXPECT_EQ(ranged_gx["t_last_s"], 2500.0);
    EXPECT_EQ(ranged_gx["t_first_s"], alone_gx["t_first_s"]);
    EXPECT_EQ(ranged_gx["adev"], alone_gx["adev"]);
    EXPECT_EQ(ranged_gx["drift"], alone_gx["drift"]);

    const RunResult beyond = run_driftlab(with(allan, {whole, "--from", "5000"}), dir.path());
    EXPECT_EQ(beyond.exit_code, 3);
    // Worded as fit words it, after the note of what the range kept (none here, so no note).
    EXPECT_NE(beyond.output.find("series 'gx': 0 samples in the selected time range (the series' rows run from 0 s to "
                                 "2999 s); the Allan deviation needs at least 2"),
              std::string::npos)
        << beyond.output;
    const RunResult reversed = run_driftlab(with(allan, {whole, "--from", "50", "--to", "40"}), dir.path());
    EXPECT_EQ(reversed.exit_code, 2);
    EXPECT_NE(reversed.output.find("--from must be before --to"), std::string::npos) << reversed.output;
}

// --per-decade counts taus in a decade: a whole number. 2.5 had failed in the parser's words ("Could not convert");
// 3 gives m = round(10^(k/3)) up to the largest overlapping factor floor(2000 / 4) = 500 of 2000 rate samples.
TEST(AllanCli, PerDecadeIsAWholeNumberOfTausNamedWithItsRange) {
    TempDir dir("allandecade");
    const std::string table = table_at_50_hz(dir);
    for (const char* bad : {"2.5", "0", "1001"}) {
        const RunResult r = run_driftlab(
            {"allan", table, "--kind", "rate", "--tau0", "0.02", "--grid", "log", "--per-decade", bad}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find(std::string("--per-decade: expected a whole number in [1, 1000], got '") + bad + "'"),
                  std::string::npos)
            << r.output;
    }
    const RunResult r = run_driftlab({"allan", table, "--kind", "rate", "--tau0", "0.02", "--grid", "log",
                                      "--per-decade", "3", "--deviation", "oadev", "--json"},
                                     dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<double> tau = nlohmann::json::parse(r.output)["channels"]["gx"]["tau"].get<std::vector<double>>();
    const std::vector<int> m = {1, 2, 5, 10, 22, 46, 100, 215, 464};
    ASSERT_EQ(tau.size(), m.size()) << r.output;
    for (std::size_t i = 0; i < m.size(); ++i) EXPECT_NEAR(tau[i], 0.02 * m[i], 1e-9) << i;
}

TEST(AllanCli, TheTimeColumnIsNotASeries) {
    TempDir dir("allantime");
    const RunResult r = run_driftlab(
        {"allan", table_at_50_hz(dir), "--kind", "rate", "--tau0", "0.02", "--channel", "t_s"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("'t_s' is the time column"), std::string::npos) << r.output;
}

// A plain rate table (no time column, tau0 0.1 s) of white noise sigma = 0.5 over an eq. 1 warm-up of 40 units with
// T = 300 s. Independent expectation: white rate noise has ADEV sigma / sqrt(tau / tau0) at every tau.
TEST(AllanCli, RemoveDriftFitsEqOneOnAPlainRateFileOnlyWhenAsked) {
    TempDir dir("allandrift");
    const std::string table = dir.file("warmup.txt");
    constexpr double kTau0 = 0.1, kSigma = 0.5;
    {
        std::ofstream out(table);
        std::mt19937_64 rng(31);
        std::normal_distribution<double> g(0.0, kSigma);
        for (int k = 0; k < 40000; ++k) out << 500.0 + 40.0 * (1.0 - std::exp(-k * kTau0 / 300.0)) + g(rng) << '\n';
    }
    const auto white = [&](double tau) { return kSigma / std::sqrt(tau / kTau0); };
    const std::vector<std::string> base = {"allan", table, "--kind", "rate", "--tau0", "0.1", "--json"};

    const RunResult given = run_driftlab(base, dir.path());
    ASSERT_EQ(given.exit_code, 0) << given.output;
    const auto g_json = nlohmann::json::parse(given.output)["channels"]["col1"];
    EXPECT_FALSE(g_json["drift_removed"].get<bool>());
    EXPECT_EQ(g_json["drift_status"],
              "not removed: a plain file is analysed as given; --remove-drift fits eq. 1 first");
    const double long_tau = g_json["tau"].back().get<double>();
    EXPECT_GT(g_json["adev"].back().get<double>(), 3.0 * white(long_tau));  // the transient inflates the long taus

    std::vector<std::string> removing = base;
    removing.push_back("--remove-drift");
    const RunResult removed = run_driftlab(removing, dir.path());
    ASSERT_EQ(removed.exit_code, 0) << removed.output;
    const auto r_json = nlohmann::json::parse(removed.output)["channels"]["col1"];
    ASSERT_TRUE(r_json["drift_removed"].get<bool>()) << r_json["drift_status"];
    EXPECT_NEAR(r_json["drift"]["T_s"].get<double>() / 300.0, 1.0, 0.05);
    // Every tau within its 68 % interval would fail one in three; the longest (EDF about 3) within a factor 1.5.
    EXPECT_NEAR(r_json["adev"].back().get<double>() / white(r_json["tau"].back().get<double>()), 1.0, 0.5);
    EXPECT_NEAR(r_json["adev"][0].get<double>() / white(kTau0), 1.0, 0.02);
    // No rate random walk or ramp is left: R pinned at 0, or too small to reach the white curve at the longest tau.
    const double r_term = r_json["terms"]["R"]["value"].get<double>();
    EXPECT_LT(r_term * long_tau / std::sqrt(2.0), 0.5 * white(long_tau));
    EXPECT_GT(r_json["raw"]["adev"].back().get<double>(), 3.0 * r_json["adev"].back().get<double>());

    std::vector<std::string> phase = {"allan", table, "--kind", "phase", "--tau0", "0.1", "--remove-drift"};
    const RunResult refused_phase = run_driftlab(phase, dir.path());
    EXPECT_EQ(refused_phase.exit_code, 2) << refused_phase.output;
    EXPECT_NE(refused_phase.output.find("phase input has no drift to remove"), std::string::npos)
        << refused_phase.output;
    removing.push_back("--keep-drift");
    const RunResult refused_both = run_driftlab(removing, dir.path());
    EXPECT_EQ(refused_both.exit_code, 2) << refused_both.output;
    EXPECT_NE(refused_both.output.find("excludes"), std::string::npos) << refused_both.output;
}

}  // namespace
}  // namespace driftlab::e2e
