// Stable JSON keys of `fit`, gnuplot rendering and the self-contained HTML report.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/stats/whiteness.hpp"
#include "host/util/error.hpp"
#include "host/view/allan_section.hpp"
#include "host/view/analysis_plots.hpp"
#include "host/view/fit_view.hpp"
#include "host/view/gnuplot.hpp"
#include "host/view/html_report.hpp"
#include "host/view/json_out.hpp"
#include "sim/model/rng.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::view {
namespace {

namespace fs = std::filesystem;
using test_support::TempDir;

/// A small canonical log in `dir` with the paper's gyro row on every channel and raw columns; with `warm_gyro` the
/// gyro is a warm unit's straight decline instead (T far beyond the record).
std::string write_log(const TempDir& dir, bool warm_gyro = false) {
    const std::string path = dir.file("log.csv");
    std::ofstream out(path);
    out << "# driftlab-log: 1\n# source: test\nt_s,seq,gyro,accel_x,accel_y,accel_z,raw_gyro,raw_accel_x,raw_accel_y,"
           "raw_accel_z\n";
    sim::Rng rng(1, 1);
    for (int k = 1; k <= 600; ++k) {
        out << k << ',' << k - 1;
        double v[4];
        for (double& x : v) x = 3.0 * (1.0 - std::exp(-k / 150.0)) + 505.0 + 0.25 * rng.normal();
        if (warm_gyro) v[0] += 3.0 - 1e-2 * k - 3.0 * (1.0 - std::exp(-k / 150.0));
        for (double x : v) out << ',' << x;
        for (double x : v) out << ',' << std::round(x);
        out << '\n';
    }
    return path;
}

TEST(Report, FitJsonHasTheStableKeys) {
    const TempDir dir("report_json");
    fit::FileAnalysisRequest request;
    request.path = write_log(dir);
    const fit::FileAnalysis file = fit::analyse_file(request);
    ASSERT_EQ(file.failures(), 0u);
    const nlohmann::json j = fit_json(*file.series[0].analysis);
    for (const char* p : {"C1", "C2", "T"}) {
        ASSERT_TRUE(j.contains(p)) << p;
        EXPECT_TRUE(j[p]["value"].is_number());
        EXPECT_TRUE(j[p]["stderr"].is_number());
        ASSERT_TRUE(j[p]["ci95"].is_array());
        EXPECT_EQ(j[p]["ci95"].size(), 2u);
        EXPECT_LT(j[p]["ci95"][0].get<double>(), j[p]["ci95"][1].get<double>());
    }
    for (const char* k : {"fraction_inside", "ljung_box_p", "white"}) EXPECT_TRUE(j["whiteness"].contains(k)) << k;
    EXPECT_EQ(j["status"], "converged");
    EXPECT_EQ(j["n"], 600);
    EXPECT_TRUE(j["rms"].is_number());
    EXPECT_EQ(j["physical"]["unit"], "deg/s");
    // C1 = 3 counts -> 3 x 90/512 deg/s.
    EXPECT_NEAR(j["physical"]["C1"].get<double>(), j["C1"]["value"].get<double>() * 90.0 / 512.0, 1e-12);
    EXPECT_TRUE(json_number(std::numeric_limits<double>::infinity()).is_null());
}

// Fig. 2: a row whose RAW frame was lost (raw code -1) breaks the raw steps; it is not drawn as a code of -1.
TEST(Report, RawPlotLeavesLostCodesOut) {
    fit::DriftAnalysis a;
    a.data.name = "gyro";
    a.data.t_s = {0.1, 0.2, 0.3, 0.4};
    a.data.values = {507.2, 507.4, 507.1, 507.3};
    a.data.raw_values = {507.0, -1.0, 508.0, 507.0};
    const auto plot = raw_vs_smoothed_plot(a);
    ASSERT_TRUE(plot.has_value());
    const PlotSeries& raw = plot->series.front();
    ASSERT_EQ(raw.y.size(), 4u);
    EXPECT_TRUE(std::isnan(raw.y[1]));
    EXPECT_EQ(raw.y[2], 508.0);
}

TEST(Report, GnuplotWritesPngAndSvg) {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot not on PATH";
    Plot p;
    p.title = "it's a test";  // quote in a title must survive
    p.x_label = "tau [s]";
    p.y_label = "dev";
    p.log_x = p.log_y = true;
    PlotSeries s;
    s.title = "line";
    s.x = {1, 10, 100};
    s.y = {1, 0.3, 0.1};
    s.y_low = {0.9, 0.25, 0.05};
    s.y_high = {1.1, 0.35, 0.15};
    s.style = SeriesStyle::error_bars;
    PlotSeries band = s;
    band.title = "band";
    band.style = SeriesStyle::band;
    p.series = {s, band};
    const TempDir temp("report_plot");
    const std::string dir = temp.path().string();
    const auto images = render_plot(p, dir, "t");
    ASSERT_EQ(images.size(), 2u);
    for (const auto& image : images) EXPECT_GT(fs::file_size(image), 500u) << image;
    EXPECT_NE(render_svg(p).find("<svg"), std::string::npos);
    // The band fills between its low and high columns (3 and 4 of its data block).
    std::ifstream script(fs::path(dir) / "t.png.gp");
    const std::string gp((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
    EXPECT_NE(gp.find("index 1 using 1:3:4 with filledcurves"), std::string::npos) << gp;
    // A series name from a column header ("gyro(deg/s)") names a file in `dir`, not a folder below it.
    const auto named = render_plot(p, dir, "allan_gyro(deg/s) <b>", {ImageFormat::svg});
    ASSERT_EQ(named.size(), 1u);
    EXPECT_EQ(fs::path(named[0]).filename().string(), "allan_gyro_deg_s___b_.svg");
    EXPECT_EQ(fs::path(named[0]).parent_path(), fs::path(dir));
    Plot empty;
    EXPECT_THROW(render_plot(empty, dir, "e"), UsageError);
    p.series[1].y_high.pop_back();
    EXPECT_THROW(render_plot(p, dir, "b"), UsageError);
}

TEST(Report, HtmlIsSelfContainedWithTablesVerdictsAllanAndFigures) {
    const TempDir dir("report_html");
    fit::FileAnalysisRequest request;
    request.path = write_log(dir);
    const fit::FileAnalysis file = fit::analyse_file(request);
    ReportOptions options;
    options.plots = gnuplot_available();
    const std::string html = render_html_report(file, options);
    EXPECT_NE(html.find("<table>"), std::string::npos);
    EXPECT_NE(html.find("Whiteness of the residual"), std::string::npos);
    EXPECT_NE(html.find("Allan analysis"), std::string::npos);
    EXPECT_EQ(html.find("Allan analysis failed"), std::string::npos);
    EXPECT_EQ(html.find("src="), std::string::npos);
    EXPECT_EQ(html.find("href=\"http"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    // A log's channels are counts, of a known quantity: both navigation tables, the gyro's and the accelerometers'.
    EXPECT_NE(html.find("<th>B [counts]</th>"), std::string::npos);
    EXPECT_NE(html.find("Rate gyros: noise terms in navigation units"), std::string::npos);
    EXPECT_NE(html.find("<th>bias instability B [mg]</th>"), std::string::npos);
    if (options.plots) {
        // Fig. 2 (raw columns present), 3 and 4 per channel plus one Allan plot per channel.
        std::size_t svgs = 0;
        for (std::size_t pos = 0; (pos = html.find("<svg", pos)) != std::string::npos; ++pos) ++svgs;
        EXPECT_EQ(svgs, 4u * 4u);
    }
}

// The intervals table writes each value to the digit its standard error justifies: the error to two significant
// digits and the value to the same last digit (C2 = 505.08 +- 0.11, not 505.083 +- 0.11 or 505 +- 0.1).
TEST(Report, ValuesAreRoundedToTheirStandardError) {
    const TempDir dir("report_rounding");
    fit::FileAnalysisRequest request;
    request.path = write_log(dir);
    request.names = {"gyro"};
    const fit::FileAnalysis file = fit::analyse_file(request);
    ASSERT_EQ(file.failures(), 0u);
    ReportOptions options;
    options.plots = false;
    const std::string html = render_html_report(file, options);
    const std::string row = "<tr><td>gyro</td><td>C2</td><td>";
    const auto at = html.find(row);
    ASSERT_NE(at, std::string::npos) << html;
    const std::string cell = html.substr(at + row.size(), html.find("</td>", at + row.size()) - at - row.size());
    const auto pm = cell.find(" &plusmn; ");
    ASSERT_NE(pm, std::string::npos) << cell;
    const std::string value = cell.substr(0, pm), error = cell.substr(pm + 10);
    const double se = file.series[0].analysis->plain.c2.stderr_;
    ASSERT_LT(se, 1.0);  // the digits after the point are the ones to count
    const auto decimals = [](const std::string& text) { return text.size() - text.find('.') - 1; };
    const auto wanted = static_cast<std::size_t>(1 - std::floor(std::log10(se)));
    EXPECT_EQ(decimals(value), wanted) << cell;
    EXPECT_EQ(decimals(error), wanted) << cell;
    EXPECT_NEAR(std::stod(error), se, 0.051 * se) << cell;  // two significant digits: within half a unit of the second
    EXPECT_NEAR(std::stod(value), file.series[0].analysis->plain.c2.value, 0.051 * se) << cell;
}

/// A plain table `name` in `dir` of white noise at the times `t_s`.
std::string write_table(const TempDir& dir, const std::string& name, const std::vector<double>& t_s) {
    const std::string path = dir.file(name);
    std::ofstream out(path);
    out << "t_s gx\n";
    sim::Rng rng(3, 1);
    for (double t : t_s) out << t << ' ' << 4.5 + 0.1 * rng.normal() << '\n';
    return path;
}

// The report's Allan grid: rows in bursts (5 rows 2 ms apart every 50 ms, 100 a second, as the MPU6050 recording)
// get tau0 = their mean spacing, 10 ms (59.958 s / 5999), and a curve out to seconds; at the median, 2 ms, 80 % of the
// grid had been gaps and the curve had ended at 16 ms. A 1 s record with a reconnect that lost 30 % keeps tau0 = 1 s
// and warns. The fit's values of what the data do not determine are arbitrary (C1 = -6.9e11 counts on a warm log): the
// page says "not determined", why, and gives the initial slope C1/T the record does determine. A fit whose evaluation
// budget ran out reads so in the fit table, not as the JSON's name iteration_limit.
TEST(Report, AFitThatStoppedShortSaysSoInWords) {
    const TempDir dir("report_stopped_short");  // a name without the words looked for
    fit::FileAnalysisRequest request;
    request.path = write_log(dir);
    request.names = {"gyro"};
    request.options.fit.max_function_evaluations = 2;
    const fit::FileAnalysis file = fit::analyse_file(request);
    ReportOptions options;
    options.plots = false;
    const std::string html = render_html_report(file, options);
    EXPECT_NE(html.find("<td>not converged (iteration limit)</td>"), std::string::npos) << html;
    EXPECT_EQ(html.find("iteration_limit"), std::string::npos) << html;
}

TEST(Report, WhatTheDataDoNotDetermineReadsNotDetermined) {
    const TempDir dir("report_undetermined");
    fit::FileAnalysisRequest request;
    request.path = write_log(dir, true);
    request.names = {"gyro", "accel_x"};
    const fit::FileAnalysis file = fit::analyse_file(request);
    ASSERT_EQ(file.failures(), 0u);
    ASSERT_FALSE(file.series[0].analysis->c1_and_t_determined());
    ReportOptions options;
    options.plots = false;
    const std::string html = render_html_report(file, options);
    EXPECT_NE(html.find("<tr><td>gyro</td><td>not determined</td><td>508"), std::string::npos) << html;
    EXPECT_NE(html.find("<b>gyro:</b> not determined: T is beyond the record"), std::string::npos) << html;
    EXPECT_NE(html.find("<tr><td>gyro</td><td>C1</td><td colspan=\"3\">not determined</td></tr>"), std::string::npos)
        << html;
    EXPECT_NE(html.find("<tr><td>gyro</td><td>C1/T [per s]</td><td>-0.0"), std::string::npos) << html;
    EXPECT_EQ(html.find("<b>accel_x:</b> not determined"), std::string::npos) << html;
}

TEST(Report, AllanGridOfBurstyRowsIsTheirMeanSpacingAndGapsAreWarned) {
    const TempDir dir("report_allan_grid");
    std::vector<double> bursts;
    for (int k = 0; k < 6000; ++k) bursts.push_back(0.05 * (k / 5) + 0.002 * (k % 5));
    std::vector<double> reconnect;
    for (int k = 0; k < 700; ++k) reconnect.push_back(k < 350 ? k : k + 300.0);
    for (const auto& [name, times] : {std::pair{"bursts.txt", bursts}, std::pair{"reconnect.txt", reconnect}}) {
        fit::FileAnalysisRequest request;
        request.path = write_table(dir, name, times);
        const fit::FileAnalysis file = fit::analyse_file(request);
        ASSERT_EQ(file.failures(), 0u) << name;
        const AllanSection section = allan_section({&*file.series[0].analysis});
        ASSERT_EQ(section.plots.size(), 1u) << name;
        const std::vector<double>& tau = section.plots[0].series[0].x;
        ASSERT_FALSE(tau.empty()) << name;
        if (times == bursts) {
            EXPECT_NE(section.html.find("<td>gx</td><td>0.009995</td>"), std::string::npos) << section.html;
            EXPECT_GT(tau.back(), 5.0);
            EXPECT_EQ(section.html.find("class=\"warn\""), std::string::npos) << section.html;
        } else {
            EXPECT_NE(section.html.find("<td>gx</td><td>1</td>"), std::string::npos) << section.html;
            EXPECT_NE(
                section.html.find("30 % of the 1000 grid slots at tau0 = 1 s are gaps (rows 1 s apart (median; mean "
                                  "1.42918 s))"),
                std::string::npos)
                << section.html;
        }
    }
}

// The report's Allan section gives allan's packing caveat where it applies: a record whose rows come twice as fast
// for its first 1000 s, on the 1 s grid of the rest, has its later rows 1000 slots late; the steady bursts above get
// none.
TEST(Report, AllanPackingThatCanBiasTheCurveIsWarned) {
    const TempDir dir("report_allan_packing");
    std::vector<double> times;
    for (int k = 0; k < 2000; ++k) times.push_back(0.5 * k);
    for (int k = 0; k < 4000; ++k) times.push_back(1000.0 + k);
    fit::FileAnalysisRequest request;
    request.path = write_table(dir, "changed.txt", times);
    const fit::FileAnalysis file = fit::analyse_file(request);
    ASSERT_EQ(file.failures(), 0u);
    const AllanSection section = allan_section({&*file.series[0].analysis});
    EXPECT_NE(section.html.find("<b>gx:</b> 5996 samples came faster than tau0 (bursts, or a record that changes its "
                                "rate) and were placed up to 1000 slots (1000 s) after their time"),
              std::string::npos)
        << section.html;
}

/// The number in the first cell after `<tr><td>name</td>` that follows `heading` in `html`; NaN when absent.
double cell_after(const std::string& html, const std::string& heading, const std::string& name) {
    const auto table = html.find(heading);
    if (table == std::string::npos) return std::nan("");
    const std::string row = "<tr><td>" + name + "</td><td>";
    const auto cell = html.find(row, table);
    return cell == std::string::npos ? std::nan("") : std::stod(html.substr(cell + row.size()));
}

// The Allan tables carry units: a plain table's columns given deg/s and mg (report --unit) differ, so the headers
// say U and a column gives each row's; the noise terms come again in navigation units, against the white noise's
// own: sigma per sample at tau0 is N / sqrt(tau0), so 0.1 deg/s at 100 Hz is N = 0.01 deg/s/sqrt(Hz) = 0.6 deg/sqrt(h)
// (ARW), and 1 mg is N = 0.1 mg/sqrt(Hz) = 0.1 x 9.80665e-3 x 60 = 0.0588 m/s/sqrt(h) (VRW).
TEST(Report, AllanTermsInNavigationUnitsWhereTheQuantityIsKnown) {
    const TempDir dir("report_allan_units");
    const std::string path = dir.file("imu.csv");
    std::ofstream out(path);
    out << "t_s,gx,ax\n";
    sim::Rng rng(21, 1);
    for (int k = 0; k < 40000; ++k) out << 0.01 * k << ',' << 0.1 * rng.normal() << ',' << rng.normal() << '\n';
    out.close();
    fit::FileAnalysisRequest request;
    request.path = path;
    fit::FileAnalysis file = fit::analyse_file(request);
    ASSERT_EQ(file.failures(), 0u);
    file.series[0].analysis->data.unit = "deg/s";
    file.series[1].analysis->data.unit = "mg";
    const std::string html = allan_section({&*file.series[0].analysis, &*file.series[1].analysis}).html;
    EXPECT_NE(html.find("<th>U</th><th>&tau;0 [s]</th><th>OADEV &sigma;(&tau;0) raw [U]</th>"), std::string::npos)
        << html;
    EXPECT_NE(html.find("<th>N [U/&radic;Hz]</th>"), std::string::npos) << html;
    EXPECT_NE(html.find("<tr><td>gx</td><td>deg/s</td>"), std::string::npos) << html;
    EXPECT_NEAR(cell_after(html, "<th>angle random walk N [&deg;/&radic;h]</th>", "gx"), 0.6, 0.03) << html;
    EXPECT_NEAR(cell_after(html, "<th>velocity random walk N [m/s/&radic;h]</th>", "ax"), 0.0588, 0.003) << html;
    // One unit: named in the headers, no unit column. A unit the table does not know gives no navigation table.
    const std::string gx_only = allan_section({&*file.series[0].analysis}).html;
    EXPECT_NE(gx_only.find("<th>channel</th><th>&tau;0 [s]</th><th>OADEV &sigma;(&tau;0) raw [deg/s]</th>"),
              std::string::npos)
        << gx_only;
    EXPECT_EQ(gx_only.find("Accelerometers"), std::string::npos) << gx_only;
    file.series[0].analysis->data.unit = "";
    const std::string plain = allan_section({&*file.series[0].analysis}).html;
    EXPECT_NE(plain.find("<th>B [data unit]</th>"), std::string::npos) << plain;
    EXPECT_EQ(plain.find("navigation units"), std::string::npos) << plain;
}

// The report's expected share of lags inside +-2 sigma for a white residual is what this estimator gives: the
// biased R(d) has variance (L-d)/L^2 of the bound's 1/L, so P(|Z| < 2 sqrt(L/(L-d))) averaged over d = 1..L-1,
// 98.87 % for L = 50 (not the 95.45 % of a normal variable at 2 sigma).
TEST(Report, WhitenessSentenceStatesWhatWhiteNoiseGives) {
    sim::Rng rng(11, 3);
    double sum = 0.0;
    const int runs = 200;
    for (int r = 0; r < runs; ++r) {
        std::vector<double> w(4000);
        for (double& v : w) v = rng.normal();
        sum += stats::test_whiteness(w, 1.0).fraction_inside;
    }
    EXPECT_NEAR(sum / runs, 0.9887, 0.003);
    const TempDir dir("report_white");
    fit::FileAnalysisRequest request;
    request.path = write_log(dir);
    ReportOptions options;
    options.plots = false;
    const std::string html = render_html_report(fit::analyse_file(request), options);
    EXPECT_NE(html.find("about 98.9 % of the lags"), std::string::npos);
    EXPECT_EQ(html.find("95.5 %"), std::string::npos);
}

// Fig. 4's lag axis is in the spacing the sequences count: rows in bursts (5 rows 2 ms apart, 20 bursts a second)
// count at their mean 10 ms, so a 5 s sequence ends near lag 5 s, not 25 s.
TEST(Report, Fig4LagAxisFollowsTheWhitenessSpacing) {
    fit::Series s;
    s.name = "gx";
    s.source = "bursts.csv";
    sim::Rng rng(5, 1);
    for (int burst = 0; burst < 1200; ++burst)
        for (int i = 0; i < 5; ++i) {
            s.t_s.push_back(1.0 + 0.05 * burst + 0.002 * i);
            s.values.push_back(3.0 * (1.0 - std::exp(-s.t_s.back() / 20.0)) + 0.25 * rng.normal());
        }
    fit::AnalysisOptions o;
    o.whiteness.sequence_length_s = 5.0;
    const Plot p = autocorrelation_plot(fit::analyse_drift(s, o));
    EXPECT_NEAR(p.series.front().x.back(), 5.0, 0.05);
}

}  // namespace
}  // namespace driftlab::host::view
