// `driftlab allan` options against the file they describe: a --tau0 that is not the time column's spacing would
// pack or spread the rows on the grid (wrong taus, a real gap closed up), and the time column is not a series.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "e2e_support.hpp"

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

TEST(AllanCli, TheTimeColumnIsNotASeries) {
    TempDir dir("allantime");
    const RunResult r =
        run_driftlab({"allan", table_at_50_hz(dir), "--kind", "rate", "--tau0", "0.02", "--channel", "t_s"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("'t_s' is the time column"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace driftlab::e2e
