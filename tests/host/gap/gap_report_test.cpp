// The files a report may write: an input among them is refused (gap --report).
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap/gap_report.hpp"

namespace driftlab::host::gap {
namespace {

// A log or model file named as one of the report's files would be written over: report_files() lists them all.
TEST(GapReport, TheReportsFilesAreListedWhicheverChannelsItPlots) {
    const std::vector<std::string> files = report_files("rep");
    for (const std::string expected : {"rep/gap.md", "rep/gap_mean_gyro.png", "rep/gap_mean_gyro.dat", "rep/gap_adev_accel_z.png.gp",
                                       "rep/gap_codes_accel_x.png"})
        EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected;
    EXPECT_EQ(std::find(files.begin(), files.end(), "rep/h.csv"), files.end());
}

}  // namespace
}  // namespace driftlab::host::gap
