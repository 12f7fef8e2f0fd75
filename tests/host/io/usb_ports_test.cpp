// usb_ports: the sysfs and by-id views joined on a fake tree laid out like the kernel's.
#include "host/io/usb_ports.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>

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

// Without libusb, sysfs alone lists the adapters: a two-port FT2232 (0403:6010; ttyUSB1 and ttyUSB2 on bus 2,
// address 4) is one adapter with both nodes (it had been listed twice, each entry with both nodes).
TEST_F(FakeSystem, SysfsAloneListsATwoPortAdapterOnceWithBothNodes) {
    const fs::path ft = root_ / "sys/devices/pci0000:00/usb2/2-3";
    fs::create_directories(ft);
    write(ft / "busnum", "2");
    write(ft / "devnum", "4");
    write(ft / "idVendor", "0403");
    write(ft / "idProduct", "6010");
    for (const std::string tty : {"ttyUSB1", "ttyUSB2"}) {
        const std::string interface = tty == "ttyUSB1" ? "2-3:1.0" : "2-3:1.1";
        fs::create_directories(ft / interface / tty);
        fs::create_directories(root_ / "sys/class/tty" / tty);
        fs::create_directory_symlink(ft / interface / tty, root_ / "sys/class/tty" / tty / "device");
    }
    const std::string dev = (root_ / "dev").string();
    const auto ports = ports_from_sysfs(scan_sysfs_usb_ttys((root_ / "sys").string()), scan_by_id_links(dev), dev);
    ASSERT_EQ(ports.size(), 3u);
    const auto ft2232 =
        std::find_if(ports.begin(), ports.end(), [](const UsbSerialPort& p) { return p.product_id == 0x6010; });
    ASSERT_NE(ft2232, ports.end());
    EXPECT_EQ(ft2232->vendor_id, 0x0403);
    EXPECT_EQ(ft2232->device_nodes, (std::vector<std::string>{dev + "/ttyUSB1", dev + "/ttyUSB2"}));
    for (const UsbSerialPort& p : ports) {
        if (&p != &*ft2232) {
            EXPECT_EQ(p.device_nodes.size(), 1u) << p.device_nodes.front();
        }
    }
}

TEST_F(FakeSystem, MissingTreesGiveEmptyResultsNotErrors) {
    EXPECT_TRUE(scan_sysfs_usb_ttys((root_ / "nowhere").string()).empty());
    EXPECT_TRUE(scan_by_id_links((root_ / "nowhere").string()).empty());
}

// Without a USB bus in view (a container run without the host's devices) libusb lists nothing, which had read as no
// board plugged in: the scan says why, and sysfs still names the adapters the kernel knows.
TEST_F(FakeSystem, NoUsbBusInViewIsSaidAndSysfsStillListsTheAdapters) {
    const UsbPortScan scan = list_usb_serial_ports({(root_ / "sys").string(), (root_ / "dev").string()});
    EXPECT_FALSE(scan.usb_available);
    EXPECT_NE(scan.usb_note.find("no USB bus is visible here"), std::string::npos) << scan.usb_note;
    EXPECT_EQ(scan.ports.size(), 2u);
}

TEST(UsbPorts, KnownVendorsAreTheCommonBridgesAndArduino) {
    EXPECT_TRUE(is_known_serial_vendor(0x0403));   // FTDI
    EXPECT_TRUE(is_known_serial_vendor(0x1a86));   // CH340
    EXPECT_TRUE(is_known_serial_vendor(0x2341));   // Arduino
    EXPECT_FALSE(is_known_serial_vendor(0x046d));  // a mouse vendor
}

}  // namespace
