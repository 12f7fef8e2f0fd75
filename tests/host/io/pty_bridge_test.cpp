// PtyBridge's stable link: it replaces only a symbolic link (its own from an earlier run), never a file that a
// mistyped --pty-link names, and it goes away with the bridge.
#include "host/io/pty_bridge.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

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
