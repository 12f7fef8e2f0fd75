// A plain recording becomes the log the diagnosis reads: integer codes of each column's LSB, offset so the column's
// median sits at mid-scale, averaged over blocks (the order-0 smoother), timed at each block's last sample.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "host/gap/plain_recording.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::gap {
namespace {

NumericTable table(std::vector<std::string> names, std::vector<std::vector<double>> columns) {
    NumericTable t;
    t.source_name = "rec.txt";
    t.names = std::move(names);
    t.columns = std::move(columns);
    return t;
}

TEST(PlainRecording, BlocksOfCodesAroundMidScaleTimedAtTheirLastSample) {
    // Codes 100, 102, 104, 106, 101, 99 of an LSB of 0.5: median code 102 (the upper middle one) -> offset 410.
    const double lsb = 0.5;
    const NumericTable t = table({"col1"}, {{50.0, 51.0, 52.0, 53.0, 50.5, 49.5}});
    PlainRecording how;
    how.columns = {parse_column_mapping("gyro=col1:0.5")};
    how.sample_period_s = 0.01;
    how.block = 2;
    const LogData log = log_from_table(t, how);
    ASSERT_EQ(log.size(), 3u);
    const double offset = 512.0 - 102.0;
    EXPECT_DOUBLE_EQ(log.counts[0][0], offset + (50.0 + 51.0) / lsb / 2.0);
    EXPECT_DOUBLE_EQ(log.counts[0][1], offset + 105.0);
    EXPECT_DOUBLE_EQ(log.counts[0][2], offset + 100.0);
    for (std::size_t c = 1; c < kChannelCount; ++c) EXPECT_EQ(log.counts[c], std::vector<double>(3, 512.0));
    // Sample k at k x tau0; an output at its block's last sample.
    EXPECT_NEAR(log.t_s[0], 0.01, 1e-12);
    EXPECT_NEAR(log.t_s[2], 0.05, 1e-12);
    EXPECT_EQ(log.seq, (std::vector<std::uint64_t>{0, 1, 2}));
    EXPECT_DOUBLE_EQ(log.metadata.get_double("sample_period_s").value_or(0.0), 0.02);
    EXPECT_EQ(log.metadata.get_int("window").value_or(0), 2);
    EXPECT_EQ(log.metadata.get_int("conversions_per_output").value_or(0), 2);
    EXPECT_EQ(log.metadata.get_int("fit_order").value_or(-1), 0);
}

TEST(PlainRecording, ATimeColumnGivesTheInstantsAndColumnsMapToTheirChannels) {
    const NumericTable t = table({"t_s", "gx", "az"}, {{0.0, 0.013, 0.02, 0.041}, {1, 2, 3, 4}, {8, 8, 9, 9}});
    PlainRecording how;
    how.columns = {parse_column_mapping("accel_z=az:1"), parse_column_mapping("gyro=gx:1")};
    how.sample_period_s = 0.01;
    how.block = 2;
    const LogData log = log_from_table(t, how);
    EXPECT_EQ(log.t_s, (std::vector<double>{0.013, 0.041}));
    EXPECT_EQ(log.counts[channel_index(Channel::gyro)], (std::vector<double>{510.5, 512.5}));  // median 3
    EXPECT_EQ(log.counts[channel_index(Channel::accel_z)], (std::vector<double>{511.0, 512.0}));  // median 9
}

TEST(PlainRecording, BadMappingsAndTablesAreRefusedSayingWhy) {
    EXPECT_EQ(parse_column_mapping("accel_y=a y:2e-3").column, "a y");
    for (const char* bad : {"gyro", "gyro=col1", "yaw=col1:1", "gyro=:1", "gyro=col1:0", "gyro=col1:-1", "gyro=col1:x"})
        EXPECT_THROW(parse_column_mapping(bad), UsageError) << bad;
    const NumericTable t = table({"col1"}, {{0.0, 1.0, 2.0, 2000.0}});
    PlainRecording how;
    how.columns = {parse_column_mapping("gyro=col1:1")};
    how.sample_period_s = 1.0;
    try {
        log_from_table(t, how);
        ADD_FAILURE() << "a column beyond the 10-bit range was accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("col1' row 4"), std::string::npos) << e.what();
    }
    // One wild value among ordinary ones is named at its own row: the median it cannot move sets the scale.
    try {
        log_from_table(table({"col1"}, {{0.0, 1.0, 2.0, 1e308, 3.0, 4.0, 5.0}}), how);
        ADD_FAILURE() << "a value of 1e308 codes was accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("col1' row 4 (1e+308)"), std::string::npos) << e.what();
    }
    how.block = 3;  // 4 rows: one block
    EXPECT_THROW(log_from_table(t, how), DataError);
    how.block = 1;
    how.columns.push_back(parse_column_mapping("gyro=col1:2"));
    EXPECT_THROW(log_from_table(t, how), UsageError);  // column mapped twice
    how.columns = {parse_column_mapping("gyro=col2:1")};
    EXPECT_THROW(log_from_table(t, how), UsageError);  // no such column
}

}  // namespace
}  // namespace driftlab::host::gap
