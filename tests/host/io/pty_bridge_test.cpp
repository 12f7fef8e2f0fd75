// PtyBridge's stable link: it replaces only a symbolic link (its own from an earlier run), never a file that a
// mistyped --pty-link names, and it goes away with the bridge.
#include "host/io/pty_bridge.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>

#include <unistd.h>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "host/util/error.hpp"

namespace fs = std::filesystem;
using driftlab::host::UsageError;
using driftlab::host::io::PtyBridge;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("driftlab_pty_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

}  // namespace

TEST(PtyBridge, AFileWhereTheLinkShouldGoIsRefusedAndKept) {
    const fs::path file = scratch("precious.csv");
    std::ofstream(file) << "t_s,seq\n";
    EXPECT_THROW(PtyBridge bridge(file.string()), UsageError);
    ASSERT_TRUE(fs::is_regular_file(file));
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "t_s,seq");
    fs::remove_all(file.parent_path());
}

TEST(PtyBridge, AStaleLinkIsRepointedAndTheLinkGoesWithTheBridge) {
    const fs::path link = scratch("board");
    fs::create_symlink("/dev/pts/no-such-terminal", link);
    {
        PtyBridge bridge(link.string());
        ASSERT_TRUE(fs::is_symlink(fs::symlink_status(link)));
        EXPECT_EQ(fs::read_symlink(link).string(), bridge.slave_path());
        EXPECT_EQ(bridge.client_path(), link.string());
    }
    EXPECT_FALSE(fs::exists(fs::symlink_status(link)));
    fs::remove_all(link.parent_path());
}

namespace {

// The line discipline hands a write on to the slave side asynchronously: wait (up to 2 s) for it to arrive.
std::uint64_t dropped_once_arrived(const PtyBridge& bridge, std::uint64_t expected) {
    for (int i = 0; i < 200 && bridge.dropped_bytes() != expected; ++i) ::usleep(10000);
    return bridge.dropped_bytes();
}

}  // namespace

// Bytes the board wrote that no client read count as dropped, whether the terminal still holds them or an unplug
// discarded them; what a client read does not count.
TEST(PtyBridge, BoardOutputNobodyReadIsCountedAsDropped) {
    PtyBridge bridge;
    const std::uint8_t frame[100] = {};
    bridge.write(frame, sizeof frame);
    EXPECT_EQ(dropped_once_arrived(bridge, 100), 100u);  // nobody has read them (yet)

    const int client = ::open(bridge.slave_path().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(client, 0);
    std::uint8_t got[64];
    ASSERT_EQ(::read(client, got, 40), 40);
    EXPECT_EQ(bridge.dropped_bytes(), 60u);
    ::close(client);

    bridge.unplug();  // the 60 still queued go with the terminal
    EXPECT_EQ(bridge.dropped_bytes(), 60u);
    bridge.write(frame, 10);  // unplugged: nowhere to go
    EXPECT_EQ(bridge.dropped_bytes(), 70u);
    bridge.plug();
    EXPECT_EQ(bridge.dropped_bytes(), 70u);
}
