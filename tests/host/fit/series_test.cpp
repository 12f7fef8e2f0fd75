// Series from a plain table: the time column times the rows and is not itself a series.
#include "host/fit/series.hpp"

#include <gtest/gtest.h>

#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::fit {
namespace {

TEST(Series, NamingTheTimeColumnIsRefused) {
    NumericTable table;
    table.source_name = "table.txt";
    table.names = {"t_s", "gyro"};
    table.columns = {{0.0, 1.0, 2.0}, {1.0, 2.0, 3.0}};
    EXPECT_EQ(series_from_table(table, {"gyro"}, "", 1.0).size(), 1u);
    try {
        series_from_table(table, {"t_s"}, "", 1.0);
        ADD_FAILURE() << "the time column was taken as a series";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("'t_s' is the time column of table.txt"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace driftlab::host::fit
