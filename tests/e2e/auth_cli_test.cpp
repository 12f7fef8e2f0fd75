// Authenticated commands through `driftlab` (docs/security.md, invariant 19): a board on a pseudo-terminal with a key
// in its EEPROM, as `flash --key` leaves it; `record` without the key, with another key and with its own; `rekey`
// to a new key, after which the old one is refused.
#include <gtest/gtest.h>

#include <string>

#include "host/io/key_file.hpp"
#include "sim/hil/eeprom_image.hpp"
#include "tests/e2e/e2e_support.hpp"

namespace driftlab::e2e {
namespace {

constexpr int kDeviceErrorExit = 4;

RunResult record(const std::string& port, const std::string& key_file, const TempDir& dir, const std::string& log) {
    std::vector<std::string> args = {"record", "--port", port, "--poll", "0.1", "--duration", "1", "-o", dir.file(log)};
    if (!key_file.empty()) {
        args.push_back("--key");
        args.push_back(key_file);
    }
    return run_driftlab(args, dir.path());
}

TEST(AuthCli, AKeyedBoardObeysItsKeyOnlyAndTheHostSaysWhy) {
    TempDir dir("authcli");
    const std::string k1 = dir.file("board.key");
    const std::string k2 = dir.file("other.key");
    ASSERT_EQ(run_driftlab({"keygen", "-o", k1}, dir.path()).exit_code, 0);
    ASSERT_EQ(run_driftlab({"keygen", "-o", k2}, dir.path()).exit_code, 0);
    host::io::PtyBoardOptions options = paced_board(20.0, 600.0);
    options.eeprom = sim::eeprom_image({}, host::io::read_key_file(k1));
    BoardThread board(options);

    const RunResult none = record(board.path(), "", dir, "none.csv");
    EXPECT_EQ(none.exit_code, kDeviceErrorExit) << none.output;
    EXPECT_NE(none.output.find("the board obeys only authenticated commands: give its key with --key KEY"),
              std::string::npos)
        << none.output;
    const RunResult wrong = record(board.path(), k2, dir, "wrong.csv");
    EXPECT_EQ(wrong.exit_code, kDeviceErrorExit) << wrong.output;
    EXPECT_NE(wrong.output.find("refused CONFIG_SET as unauthenticated: the key given with --key is not this board's"),
              std::string::npos)
        << wrong.output;
    const RunResult own = record(board.path(), k1, dir, "own.csv");
    EXPECT_EQ(own.exit_code, 0) << own.output;

    const RunResult rekey = run_driftlab({"rekey", "--port", board.path(), "--key", k1, "--new-key", k2}, dir.path());
    ASSERT_EQ(rekey.exit_code, 0) << rekey.output;
    EXPECT_NE(rekey.output.find("the board now obeys the key of " + k2), std::string::npos) << rekey.output;
    EXPECT_EQ(record(board.path(), k1, dir, "old.csv").exit_code, kDeviceErrorExit);
    const RunResult renewed = record(board.path(), k2, dir, "new.csv");
    EXPECT_EQ(renewed.exit_code, 0) << renewed.output;
}

}  // namespace
}  // namespace driftlab::e2e
