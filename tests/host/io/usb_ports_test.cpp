// usb_ports: the sysfs and by-id views joined on a fake tree laid out like the kernel's.
#include "host/io/usb_ports.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace driftlab::host::io;

namespace {

class FakeSystem : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("driftlab_usb_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        // A CH340 adapter: ttyUSB0 -> usb-serial port -> interface 1-1:1.0 -> device 1-1 (bus 1, address 7).
        const fs::path dev = root_ / "sys/devices/pci0000:00/usb1/1-1";
        fs::create_directories(dev / "1-1:1.0/ttyUSB0");
        write(dev / "busnum", "1");
        write(dev / "devnum", "7");
        write(dev / "idVendor", "1a86");
        write(dev / "idProduct", "7523");
        write(dev / "product", "USB Serial");
        // An Arduino Uno (CDC-ACM): ttyACM0 -> interface 3-2:1.0 -> device 3-2 (bus 3, address 12).
        const fs::path uno = root_ / "sys/devices/pci0000:00/usb3/3-2";
        fs::create_directories(uno / "3-2:1.0");
        write(uno / "busnum", "3");
        write(uno / "devnum", "12");
        write(uno / "idVendor", "2341");
        write(uno / "idProduct", "0043");
        write(uno / "manufacturer", "Arduino (www.arduino.cc)");
        write(uno / "serial", "75830333238351A0B1C1");
        fs::create_directories(root_ / "sys/class/tty/ttyUSB0");
        fs::create_directories(root_ / "sys/class/tty/ttyACM0");
        fs::create_directories(root_ / "sys/class/tty/ttyS0");  // a UART on the mainboard, not USB
        fs::create_directory_symlink(dev / "1-1:1.0/ttyUSB0", root_ / "sys/class/tty/ttyUSB0/device");
        fs::create_directory_symlink(uno / "3-2:1.0", root_ / "sys/class/tty/ttyACM0/device");
        fs::create_directories(root_ / "dev/serial/by-id");
        fs::create_symlink("../../ttyACM0", root_ / "dev/serial/by-id/usb-Arduino_Uno_7583-if00");
        fs::create_symlink("../../ttyUSB0", root_ / "dev/serial/by-id/usb-1a86_USB_Serial-if00-port0");
    }
    void TearDown() override { fs::remove_all(root_); }

    static void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text << "\n"; }

    fs::path root_;
};

}  // namespace

TEST_F(FakeSystem, SysfsScanFindsOnlyUsbTtysWithTheirBusAddressAndIds) {
    const auto nodes = scan_sysfs_usb_ttys((root_ / "sys").string());
    ASSERT_EQ(nodes.size(), 2u);
    EXPECT_EQ(nodes[0].tty_name, "ttyACM0");
    EXPECT_EQ(nodes[0].bus, 3);
    EXPECT_EQ(nodes[0].address, 12);
    EXPECT_EQ(nodes[0].vendor_id, 0x2341);
    EXPECT_EQ(nodes[0].product_id, 0x0043);
    EXPECT_EQ(nodes[0].manufacturer, "Arduino (www.arduino.cc)");
    EXPECT_EQ(nodes[0].serial_number, "75830333238351A0B1C1");
    EXPECT_EQ(nodes[1].tty_name, "ttyUSB0");
    EXPECT_EQ(nodes[1].bus, 1);
    EXPECT_EQ(nodes[1].address, 7);
    EXPECT_EQ(nodes[1].vendor_id, 0x1a86);
    EXPECT_EQ(nodes[1].product, "USB Serial");
}

TEST_F(FakeSystem, ByIdLinksAreGroupedByTheNodeTheyResolveTo) {
    const auto links = scan_by_id_links((root_ / "dev").string());
    ASSERT_EQ(links.size(), 2u);
    ASSERT_EQ(links.at("ttyACM0").size(), 1u);
    EXPECT_EQ(fs::path(links.at("ttyACM0")[0]).filename(), "usb-Arduino_Uno_7583-if00");
    EXPECT_EQ(fs::path(links.at("ttyUSB0")[0]).filename(), "usb-1a86_USB_Serial-if00-port0");
}

TEST_F(FakeSystem, MissingTreesGiveEmptyResultsNotErrors) {
    EXPECT_TRUE(scan_sysfs_usb_ttys((root_ / "nowhere").string()).empty());
    EXPECT_TRUE(scan_by_id_links((root_ / "nowhere").string()).empty());
}

TEST(UsbPorts, KnownVendorsAreTheCommonBridgesAndArduino) {
    EXPECT_TRUE(is_known_serial_vendor(0x0403));   // FTDI
    EXPECT_TRUE(is_known_serial_vendor(0x1a86));   // CH340
    EXPECT_TRUE(is_known_serial_vendor(0x2341));   // Arduino
    EXPECT_FALSE(is_known_serial_vendor(0x046d));  // a mouse vendor
}
