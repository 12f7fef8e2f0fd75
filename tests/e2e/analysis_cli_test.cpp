// `driftlab whiteness` and `fit` on plain tables: whiteness prints every warning of the analysis as fit does (it had
// printed only the adaptation note), and a table without a time column says that t is the row index.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "e2e_support.hpp"

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

}  // namespace
}  // namespace driftlab::e2e
