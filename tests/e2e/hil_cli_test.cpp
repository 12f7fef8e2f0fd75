// `driftlab hil` options as a user types them: a 100 Hz log needs fewer conversions per output than the
// paper preset's 25 (docs/firmware.md: 10 ms outputs allow at most 12), which --conversions sets, and a link
// faster than the paper's 9600-baud radio (sim/models/hundred_hz.toml).
#include <gtest/gtest.h>

#include "e2e_support.hpp"
#include "host/log/log_reader.hpp"

namespace driftlab::e2e {
namespace {

TEST(HilCli, ConversionsPerOutputMakesA100HzLogPossible) {
    TempDir dir("hil100");
    const std::string out = dir.file("h100.csv");
    const RunResult r = run_driftlab(
        {"hil", "--model", std::string(DRIFTLAB_SOURCE_DIR) + "/sim/models/hundred_hz.toml", "--duration", "2",
         "--conversions", "6", "--window", "6", "-o", out}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const host::LogData log = host::read_log(out);
    EXPECT_EQ(log.metadata.get_int("conversions_per_output"), 6);
    EXPECT_EQ(log.metadata.get_int("window"), 6);
    // 2 s of 10 ms outputs; the first poll follows the handshake, so allow one short.
    EXPECT_NEAR(static_cast<double>(log.size()), 200.0, 1.0);
    // Host receive instants: frame transmission jitters single spacings, the mean spacing is the period.
    EXPECT_NEAR((log.t_s.back() - log.t_s.front()) / static_cast<double>(log.size() - 1), 0.01, 1e-5);
}

TEST(HilCli, TooManyConversionsForThePeriodIsRefusedByField) {
    TempDir dir("hil100bad");
    const RunResult r =
        run_driftlab({"hil", "--duration", "2", "--period", "0.01", "-o", dir.file("h.csv")}, dir.path());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("conversions_per_output"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace driftlab::e2e
