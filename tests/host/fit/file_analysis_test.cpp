// analyse_file: a sample period or time column given for a file that carries its own time, and what the analysis says
// it determines.
#include "host/fit/file_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "host/util/error.hpp"
#include "sim/model/rng.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::fit {
namespace {

using test_support::TempDir;

/// A canonical log of 600 rows 1 s apart: gyro = `gyro(t)`, the accelerometer axes the paper's gyro row.
template <class Gyro>
std::string write_log(const TempDir& dir, Gyro gyro) {
    const std::string path = dir.file("log.csv");
    std::ofstream out(path);
    out << "# driftlab-log: 1\n# source: test\nt_s,seq,gyro,accel_x,accel_y,accel_z\n";
    sim::Rng rng(1, 1);
    for (int k = 1; k <= 600; ++k) {
        out << k << ',' << k - 1 << ',' << gyro(k) + 0.25 * rng.normal();
        for (int c = 0; c < 3; ++c) out << ',' << 3.0 * (1.0 - std::exp(-k / 150.0)) + 505.0 + 0.25 * rng.normal();
        out << '\n';
    }
    return path;
}

double paper_gyro(double t) { return 3.0 * (1.0 - std::exp(-t / 150.0)) + 505.0; }

// fit LOG --sample-period 7 had fitted the log's 1 s rows without a word: the option is for tables without time.
TEST(FileAnalysis, ASamplePeriodTheRowsContradictIsRefused) {
    const TempDir dir("fa_period");
    FileAnalysisRequest request;
    request.path = write_log(dir, paper_gyro);
    request.sample_period_s = 7.0;
    try {
        analyse_file(request);
        ADD_FAILURE() << "--sample-period 7 on a log of 1 s rows was accepted";
    } catch (const UsageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("--sample-period/--tau0 7 s contradicts " + request.path), std::string::npos) << what;
        EXPECT_NE(what.find("timed by its own t_s column, whose rows are 1 s apart"), std::string::npos) << what;
    }
    // A table with a time column is timed by it just the same.
    const std::string table = dir.file("table.csv");
    {
        std::ofstream out(table);
        out << "t_ms,gyro\n";
        for (int k = 1; k <= 100; ++k) out << 100 * k << ',' << paper_gyro(0.1 * k) << '\n';
    }
    request.path = table;
    request.sample_period_s = 1.0;
    EXPECT_THROW(analyse_file(request), UsageError);
    request.sample_period_s = 0.1;  // the rows' 100 ms: agrees
    const FileAnalysis agreed = analyse_file(request);
    ASSERT_EQ(agreed.notes.size(), 1u);
    EXPECT_NE(agreed.notes[0].find("is not used: " + table + " is a table timed by its own time column"),
              std::string::npos)
        << agreed.notes[0];
}

TEST(FileAnalysis, ASamplePeriodTheRowsAgreeWithIsNotedAsUnused) {
    const TempDir dir("fa_period_ok");
    FileAnalysisRequest request;
    request.path = write_log(dir, paper_gyro);
    EXPECT_TRUE(analyse_file(request).notes.empty());
    request.sample_period_s = 1.0;
    const FileAnalysis file = analyse_file(request);
    EXPECT_EQ(file.failures(), 0u);
    ASSERT_EQ(file.notes.size(), 1u);
    EXPECT_EQ(file.notes[0], "--sample-period/--tau0 1 s is not used: " + request.path +
                                 " is a driftlab log, timed by its own t_s column, whose rows are 1 s apart (median; "
                                 "mean 1 s)");
}

// fit LOG --time-column seq had fitted on t_s without a word: a log is timed by its t_s alone, so another column is
// refused and t_s itself noted as unused.
TEST(FileAnalysis, ATimeColumnOtherThanALogsTsIsRefusedAndItsTsNoted) {
    const TempDir dir("fa_time_column");
    FileAnalysisRequest request;
    request.path = write_log(dir, paper_gyro);
    request.time_column = "seq";
    try {
        analyse_file(request);
        ADD_FAILURE() << "--time-column seq on a log was accepted";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--time-column seq contradicts " + request.path +
                      ": it is a driftlab log, timed by its own t_s column; leave the option out "
                      "(it is for plain tables)");
    }
    request.time_column = "t_s";
    const FileAnalysis file = analyse_file(request);
    EXPECT_EQ(file.failures(), 0u);
    ASSERT_EQ(file.notes.size(), 1u);
    EXPECT_EQ(file.notes[0],
              "--time-column t_s is not used: " + request.path + " is a driftlab log, timed by its own t_s column");
    // A table is timed by the column named, without a note.
    const std::string table = dir.file("table.csv");
    {
        std::ofstream out(table);
        out << "t_s,seq,gyro\n";
        for (int k = 1; k <= 300; ++k) out << k << ',' << 2 * k << ',' << paper_gyro(k) << '\n';
    }
    request.path = table;
    request.names = {"gyro"};
    request.time_column = "seq";
    const FileAnalysis by_seq = analyse_file(request);
    EXPECT_TRUE(by_seq.notes.empty());
    ASSERT_EQ(by_seq.failures(), 0u) << by_seq.failure_summary();
    EXPECT_DOUBLE_EQ(by_seq.series[0].analysis->sample_period_s, 2.0);
}

// A warm unit's straight record leaves C1 and T undetermined (only C1/T is); a singular fit leaves C2 so too
// unless T is beyond the record. fit and report print "not determined" where these say so.
TEST(FileAnalysis, WhatTheDataDetermineIsSaid) {
    const TempDir dir("fa_determined");
    FileAnalysisRequest request;
    request.path = write_log(dir, [](double t) { return 508.0 - 1e-2 * t; });
    request.names = {"gyro", "accel_x"};
    const FileAnalysis file = analyse_file(request);
    ASSERT_EQ(file.failures(), 0u);
    const DriftAnalysis& warm = *file.series[0].analysis;
    EXPECT_TRUE(warm.t_beyond_record);
    EXPECT_FALSE(warm.c1_and_t_determined());
    EXPECT_TRUE(warm.c2_determined());
    EXPECT_NE(warm.undetermined_reason().find("T is beyond the record, which determines only the initial slope C1/T"),
              std::string::npos)
        << warm.undetermined_reason();
    EXPECT_NEAR(warm.plain.initial_slope.value, -1e-2, 1e-3);
    const DriftAnalysis& settling = *file.series[1].analysis;
    EXPECT_TRUE(settling.c1_and_t_determined() && settling.c2_determined());
    EXPECT_EQ(settling.undetermined_reason(), "");

    DriftAnalysis singular = settling;
    singular.fit.status = FitStatus::singular;
    EXPECT_FALSE(singular.c1_and_t_determined());
    EXPECT_FALSE(singular.c2_determined());
    EXPECT_EQ(singular.undetermined_reason(), "the fit is singular (C1, C2 and T are not separately determined)");
    singular.t_beyond_record = true;
    EXPECT_TRUE(singular.c2_determined());  // a straight line over the record: its start is C2
}

}  // namespace
}  // namespace driftlab::host::fit
