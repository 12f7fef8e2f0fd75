// avrdude wrapper: argument vector, PATH search, and the errors a user meets, with a fake avrdude program.
#include "host/io/avrdude.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/util/error.hpp"

namespace fs = std::filesystem;
using namespace driftlab::host;
using namespace driftlab::host::io;

namespace {

class FakeAvrdude : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("driftlab_avrdude_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "bin");
        hex_ = (dir_ / "fw.hex").string();
        std::ofstream(hex_) << ":00000001FF\n";
        port_ = (dir_ / "ttyFAKE").string();
        std::ofstream(port_) << "";
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A stand-in that records its arguments and exits with `status`.
    void install(int status) {
        const fs::path prog = dir_ / "bin" / "avrdude";
        std::ofstream(prog) << "#!/bin/sh\necho \"$@\" > " << (dir_ / "args").string() << "\nexit " << status << "\n";
        fs::permissions(prog, fs::perms::owner_all);
    }
    std::string recorded_args() const {
        std::ifstream in(dir_ / "args");
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    FlashRequest request() const {
        FlashRequest r;
        r.port = port_;
        r.hex_file = hex_;
        return r;
    }

    fs::path dir_;
    std::string hex_, port_;
};

TEST(Avrdude, ArgumentsNameArduinoBootloaderDefaultsAndTheImage) {
    FlashRequest r;
    r.port = "/dev/ttyACM0";
    r.hex_file = "fw.hex";
    const std::vector<std::string> expected = {"avrdude",      "-p", "atmega328p", "-c", "arduino", "-P",
                                               "/dev/ttyACM0", "-b", "115200",     "-D", "-U",      "flash:w:fw.hex:i"};
    EXPECT_EQ(avrdude_arguments(r), expected);
}

TEST_F(FakeAvrdude, FindInPathSkipsDirectoriesWithoutTheProgram) {
    install(0);
    const std::string path = (dir_ / "empty").string() + ":" + (dir_ / "bin").string();
    EXPECT_EQ(find_in_path("avrdude", path), (dir_ / "bin" / "avrdude").string());
    EXPECT_EQ(find_in_path("avrdude", (dir_ / "empty").string()), "");
}

TEST_F(FakeAvrdude, SuccessfulRunPassesTheArgumentsThrough) {
    install(0);
    run_avrdude(request(), (dir_ / "bin").string());
    EXPECT_EQ(recorded_args(), "-p atmega328p -c arduino -P " + port_ + " -b 115200 -D -U flash:w:" + hex_ + ":i\n");
}

TEST_F(FakeAvrdude, FailingAvrdudeIsADeviceErrorNamingThePortAndStatus) {
    install(1);
    try {
        run_avrdude(request(), (dir_ / "bin").string());
        FAIL() << "expected DeviceError";
    } catch (const DeviceError& e) {
        EXPECT_NE(std::string(e.what()).find(port_), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("status 1"), std::string::npos) << e.what();
    }
}

TEST_F(FakeAvrdude, MissingAvrdudeMissingPortAndMissingImageAreClearErrors) {
    EXPECT_THROW(run_avrdude(request(), (dir_ / "bin").string()), DeviceError);  // not installed
    install(0);
    FlashRequest no_port = request();
    no_port.port = (dir_ / "ttyNONE").string();
    EXPECT_THROW(run_avrdude(no_port, (dir_ / "bin").string()), DeviceError);
    FlashRequest no_hex = request();
    no_hex.hex_file = (dir_ / "none.hex").string();
    EXPECT_THROW(run_avrdude(no_hex, (dir_ / "bin").string()), DataError);
}

// The AVR preset's image first; else the one a native build with avr-gcc made in its own tree (avr-fw), which is
// what a user who ran the README's main command has. Each at the path its build writes: a folder walk had taken
// whichever copy it met first (here the stray one in a subfolder).
TEST_F(FakeAvrdude, DefaultImageIsTheSiblingAvrBuildsElseTheNativeTreesOwnAtTheirBuildPaths) {
    fs::create_directories(dir_ / "build/native/bin");
    fs::create_directories(dir_ / "build/avr/firmware/a_stray_copy");
    fs::create_directories(dir_ / "build/native/avr-fw/firmware");
    std::ofstream(dir_ / "build/native/bin/driftlab") << "";
    std::ofstream(dir_ / "build/native/CMakeCache.txt") << "";
    std::ofstream(dir_ / "build/avr/firmware/a_stray_copy/driftlab_fw.hex") << ":00000001FF\n";
    std::ofstream(dir_ / "build/avr/firmware/driftlab_fw.hex") << ":00000001FF\n";
    std::ofstream(dir_ / "build/native/avr-fw/firmware/driftlab_fw.hex") << ":00000001FF\n";
    const std::string exe = (dir_ / "build/native/bin/driftlab").string();
    const std::string preset_image = (dir_ / "build/avr/firmware/driftlab_fw.hex").string();
    EXPECT_EQ(default_hex_file(exe), preset_image);
    fs::remove(preset_image);
    EXPECT_EQ(default_hex_file(exe), (dir_ / "build/native/avr-fw/firmware/driftlab_fw.hex").string());
    fs::remove_all(dir_ / "build/native/avr-fw");
    // Neither: both paths named, and --hex (exit 3).
    try {
        default_hex_file(exe);
        FAIL() << "expected DataError";
    } catch (const DataError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not found at " + preset_image + " (the AVR build's) nor at " +
                            (dir_ / "build/native/avr-fw/firmware/driftlab_fw.hex").string()),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("pass --hex FILE"), std::string::npos) << what;
    }
}

// A binary outside a build tree (copied to /tmp/x/driftlab) had been sent to paths derived from wherever it lay
// (/avr/firmware/driftlab_fw.hex, the "build" two folders up): the image is looked for only beside a build tree
// (its CMakeCache.txt), and elsewhere the error says so and names --hex, even with an image at the derived path.
TEST_F(FakeAvrdude, DefaultImageOfABinaryOutsideABuildTreeIsRefusedNamingHex) {
    fs::create_directories(dir_ / "x/bin");
    fs::create_directories(dir_ / "avr/firmware");
    std::ofstream(dir_ / "x/bin/driftlab") << "";
    std::ofstream(dir_ / "avr/firmware/driftlab_fw.hex") << ":00000001FF\n";  // a stray image where it would look
    const std::string exe = (dir_ / "x/bin/driftlab").string();
    try {
        const std::string image = default_hex_file(exe);
        FAIL() << "expected DataError, got " << image;
    } catch (const DataError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(exe + " is not one (a copy, or installed); pass --hex FILE"), std::string::npos) << what;
    }
}

// The dry run prints a command to paste: an argument with a space or a quote must come back as one word.
TEST(Avrdude, ShellQuotingKeepsEachArgumentOneWord) {
    EXPECT_EQ(shell_quoted("/dev/ttyACM0"), "/dev/ttyACM0");
    EXPECT_EQ(shell_quoted("flash:w:my fw.hex:i"), "'flash:w:my fw.hex:i'");
    EXPECT_EQ(shell_quoted("it's"), "'it'\\''s'");
    EXPECT_EQ(shell_quoted(""), "''");
}

}  // namespace
