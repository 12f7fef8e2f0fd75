// A plain recording becomes the log the diagnosis reads: integer codes of each column's LSB, offset so the column's
// median sits at mid-scale, averaged over blocks (the order-0 smoother), timed at each block's last sample.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap/plain_recording.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "sim/model/adc.hpp"
#include "sim/model/sensor.hpp"
#include "tests/support/numeric_table.hpp"

namespace driftlab::host::gap {
namespace {

NumericTable table(std::vector<std::string> names, std::vector<std::vector<double>> columns) {
    return test_support::numeric_table("rec.txt", std::move(names), std::move(columns));
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
    const NumericTable t = table({"t_s", "gx", "az"}, {{0.0, 0.011, 0.02, 0.031}, {1, 2, 3, 4}, {8, 8, 9, 9}});
    PlainRecording how;
    how.columns = {parse_column_mapping("accel_z=az:1"), parse_column_mapping("gyro=gx:1")};
    how.sample_period_s = 0.01;
    how.block = 2;
    const LogData log = log_from_table(t, how);
    EXPECT_EQ(log.t_s, (std::vector<double>{0.011, 0.031}));
    EXPECT_EQ(log.counts[channel_index(Channel::gyro)], (std::vector<double>{510.5, 512.5}));     // median 3
    EXPECT_EQ(log.counts[channel_index(Channel::accel_z)], (std::vector<double>{511.0, 512.0}));  // median 9
}

// The simulator's own front end and converter, given the recording's unit, turn each recorded value into the code
// log_from_table() made of it: one code per LSB, the column's median code at mid-scale; other channels are the
// unit's. So a physical parameter the diagnosis reports (deg/s, g) is the recording's own.
TEST(PlainRecording, ItsUnitConvertsEachValueToTheCodeTheLogHolds) {
    // Values as a sensor gives them: whole LSBs (8.75 mdps; 1/4096 g).
    const NumericTable t = table({"gx", "az"}, {{-34 * 0.00875, 2 * 0.00875, 46 * 0.00875, 14 * 0.00875, -6 * 0.00875},
                                                {4014 / 4096.0, 4137 / 4096.0, 4055 / 4096.0, 4178 / 4096.0, 1.0}});
    PlainRecording how;
    how.columns = {parse_column_mapping("gyro=gx:0.00875"), parse_column_mapping("accel_z=az:0.000244140625")};
    how.sample_period_s = 0.01;
    const LogData log = log_from_table(t, how);
    sim::SimModel paper = sim::paper_model();
    paper.adc.bits = 12;  // the codes are 10-bit whatever the unit's converter
    const sim::SimModel unit = unit_of_recording(paper, how, log);
    EXPECT_EQ(unit.adc.bits, 10);
    const sim::Adc adc(unit.adc);
    for (const auto& [c, column] : {std::pair{Channel::gyro, 0}, std::pair{Channel::accel_z, 1}}) {
        const sim::FrontEnd fe(unit.channels[channel_index(c)].front_end, unit.adc.vref_v);
        for (std::size_t k = 0; k < log.size(); ++k)
            EXPECT_NEAR(adc.counts_from_volts(fe.amplifier_v(fe.sensor_v(t.columns[column][k]))),
                        log.counts[channel_index(c)][k], 1e-6)
                << kChannelNames[channel_index(c)] << " row " << k;
        // At rest the unit reads its input, the column's median: mid-scale.
        EXPECT_NEAR(adc.counts_from_volts(fe.amplifier_v(fe.sensor_v(unit.channels[channel_index(c)].input_unit))),
                    512.0, 1e-9);
    }
    EXPECT_EQ(unit.channels[1].front_end.span_unit, paper.channels[1].front_end.span_unit);  // accel_x: not mapped
    EXPECT_THROW(unit_of_recording(paper, how, LogData{}), std::invalid_argument);
}

// A column in rad/s (or mdps, mg, m/s2) is the same recording as in deg/s (g): the same codes, and a unit whose
// front end spans the same deg/s, so that what the diagnosis reports in deg/s is right. Without the unit the
// recording's numbers were read as deg/s, 57 times too small for rad/s.
TEST(PlainRecording, AColumnInAnotherUnitReadsAsTheSameRecordingInDegreesPerSecondOrG) {
    const double rad = 3.14159265358979323846 / 180.0;
    const std::vector<double> dps = {-0.2975, 0.0175, 0.4025, 0.1225, -0.0525};
    std::vector<double> rps;
    for (double v : dps) rps.push_back(v * rad);
    const ColumnMapping in_rad = parse_column_mapping("gyro=gx:" + format_double(0.00875 * rad) + ":rad/s");
    EXPECT_EQ(in_rad.column, "gx");
    EXPECT_EQ(in_rad.lsb, 0.00875 * rad);
    EXPECT_NEAR(in_rad.to_model_unit * rad, 1.0, 1e-15);
    EXPECT_EQ(parse_column_mapping("gyro=gx:0.00875:deg/s").to_model_unit, 1.0);
    EXPECT_EQ(parse_column_mapping("gyro=gx:8.75:mdps").to_model_unit, 1e-3);
    EXPECT_EQ(parse_column_mapping("accel_z=az:0.244:mg").to_model_unit, 1e-3);
    EXPECT_NEAR(parse_column_mapping("accel_z=az:0.0024:m/s2").to_model_unit * 9.80665, 1.0, 1e-15);
    // The spellings allan --unit takes too (one table for both).
    EXPECT_EQ(parse_column_mapping("accel_z=az:0.0024:m/s^2").to_model_unit,
              parse_column_mapping("accel_z=az:0.0024:m/s2").to_model_unit);
    EXPECT_NEAR(parse_column_mapping("accel_z=az:0.24:cm/s2").to_model_unit * 980.665, 1.0, 1e-15);
    EXPECT_EQ(parse_column_mapping("gyro=gx:0.00875:dps").to_model_unit, 1.0);
    EXPECT_NEAR(parse_column_mapping("gyro=gx:30:deg/h").to_model_unit * 3600.0, 1.0, 1e-15);
    for (const char* bad :
         {"gyro=gx:1:g", "accel_x=ax:1:rad/s", "gyro=gx:rad/s", "gyro=gx:1:furlongs", "gyro=:1:deg/s"})
        EXPECT_THROW(parse_column_mapping(bad), UsageError) << bad;

    PlainRecording deg_how, rad_how;
    deg_how.columns = {parse_column_mapping("gyro=gx:0.00875")};
    rad_how.columns = {in_rad};
    deg_how.sample_period_s = rad_how.sample_period_s = 0.01;
    const LogData deg_log = log_from_table(table({"gx"}, {dps}), deg_how);
    const LogData rad_log = log_from_table(table({"gx"}, {rps}), rad_how);
    EXPECT_EQ(rad_log.counts[0], deg_log.counts[0]);
    const sim::SimModel deg_unit = unit_of_recording(sim::paper_model(), deg_how, deg_log);
    const sim::SimModel rad_unit = unit_of_recording(sim::paper_model(), rad_how, rad_log);
    const auto& d = deg_unit.channels[0];
    const auto& r = rad_unit.channels[0];
    EXPECT_NEAR(r.front_end.span_unit / d.front_end.span_unit, 1.0, 1e-12);
    EXPECT_NEAR(r.front_end.center_unit / d.front_end.center_unit, 1.0, 1e-12);
    EXPECT_NEAR(r.input_unit / d.input_unit, 1.0, 1e-12);
}

TEST(PlainRecording, BadMappingsAndTablesAreRefusedSayingWhy) {
    EXPECT_EQ(parse_column_mapping("accel_y=a y:2e-3").column, "a y");
    for (const char* bad : {"gyro", "gyro=col1", "yaw=col1:1", "gyro=:1", "gyro=col1:0", "gyro=col1:-1", "gyro=col1:x"})
        EXPECT_THROW(parse_column_mapping(bad), UsageError) << bad;
    try {
        parse_column_mapping("Gyro=col1:1");
        ADD_FAILURE() << "a channel name in the wrong case was accepted";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "--as: unknown channel 'Gyro' (gyro, accel_x, accel_y, accel_z)");
    }
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
    // Read from a file, the row's file line is named too (after a comment and a name line, row 4 is line 6).
    NumericTable read = t;
    read.source_name = "gyro.txt";
    read.row_lines = {3, 4, 5, 6};
    try {
        log_from_table(read, how);
        ADD_FAILURE() << "a column beyond the 10-bit range was accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("gyro.txt:6: column 'col1' row 4"), std::string::npos) << e.what();
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
    how.columns = {parse_column_mapping("gyro=col1:1")};
    how.block = 65;  // more conversions per output than a log's smoothing holds: the option, not the metadata, is named
    try {
        log_from_table(t, how);
        ADD_FAILURE() << "a block of 65 was accepted";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--block: 1 to 64 samples per output"), std::string::npos) << e.what();
    }
    how.block = 1;
    // The time column times the rows; mapped as a channel it was looked up among the channels' and crashed.
    how.columns = {parse_column_mapping("gyro=t_s:0.01")};
    try {
        log_from_table(table({"t_s", "gx"}, {{0.0, 0.01, 0.02, 0.03}, {1.0, 2.0, 3.0, 4.0}}), how);
        ADD_FAILURE() << "the time column was taken as a channel";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--as: 't_s' is the time column of"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace driftlab::host::gap
