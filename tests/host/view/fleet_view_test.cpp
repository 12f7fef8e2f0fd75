// A fleet's text and its markdown report show a board's rows alike: a channel whose analysis failed part way (its
// noise terms after its drift) shows what it determined, as the batch counts it; a board whose diagnosis failed
// shows "failed", one not diagnosed the unknown mark.
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host/view/fleet_view.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::view {
namespace {

fleet::ChannelResult channel(const std::string& name, const std::string& error) {
    fleet::ChannelResult c;
    c.channel = name;
    c.error = error;
    c.parameters[0] = {12.5, 0.5, true};  // C1, determined before any failure
    return c;
}

std::vector<fleet::BoardEntry> boards() {
    fleet::BoardResult failed;
    failed.channels = {channel("gyro", ""), channel("accel_x", "the fit did not converge")};
    failed.gap_run = true;
    failed.gap_error = "too few rows";
    fleet::BoardResult plain;
    plain.channels = {channel("gyro", "")};
    return {{"b1.csv", failed, ""}, {"b2.csv", plain, ""}};
}

std::vector<std::string> lines_with(const std::string& text, const std::string& part) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.find(part) != std::string::npos) out.push_back(line);
    return out;
}

TEST(FleetView, TextAndReportShowAFailedChannelAndAFailedDiagnosisAlike) {
    const std::vector<fleet::BoardEntry> b = boards();
    const FleetView v{&b, fleet::summarise(b)};
    const std::string c1_text = estimate_cell({12.5, 0.5, true}, "+-", "-");
    const std::string c1_report = estimate_cell({12.5, 0.5, true}, "±", "–");

    std::ostringstream text;
    print_fleet_text(text, v);
    const std::string rows = text.str().substr(0, text.str().find("batch ("));
    const std::vector<std::string> gyro = lines_with(rows, " gyro ");
    ASSERT_EQ(gyro.size(), 2U) << rows;
    EXPECT_NE(gyro[0].find(c1_text), std::string::npos) << gyro[0];
    EXPECT_EQ(gyro[0].substr(gyro[0].find_last_not_of(' ') - 5), "failed") << gyro[0];
    EXPECT_EQ(gyro[1].back(), '-') << gyro[1];
    const std::vector<std::string> accel = lines_with(rows, " accel_x ");
    ASSERT_EQ(accel.size(), 1U) << rows;
    EXPECT_NE(accel[0].find(c1_text), std::string::npos) << accel[0];

    test_support::TempDir dir("fleet_view");
    write_fleet_report(v, dir.path().string());
    std::ifstream in(dir.file("fleet.md"));
    const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(lines_with(md, "| b1.csv | gyro |"),
              std::vector<std::string>{"| b1.csv | gyro | " + c1_report + " | – | – | – | – | – | failed |"});
    EXPECT_EQ(lines_with(md, "| b1.csv | accel_x |"),
              std::vector<std::string>{"| b1.csv | accel_x | " + c1_report + " | – | – | – | – | – | failed |"});
    EXPECT_EQ(lines_with(md, "| b2.csv | gyro |"),
              std::vector<std::string>{"| b2.csv | gyro | " + c1_report + " | – | – | – | – | – | – |"});
}

}  // namespace
}  // namespace driftlab::host::view
