// USB serial adapters (FTDI, CH340, CP210x, Arduino CDC-ACM...) found through libusb and matched to their
// device nodes through sysfs; docs/recording.md "Finding the board".
//
// libusb sees the USB side (ids, strings) but not which tty a device became; the kernel publishes that in
// sysfs: /sys/class/tty/ttyUSB0/device points into the USB interface, whose parent holds busnum/devnum.
// The bus number and device address are the key that joins the two views.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace driftlab::host::io {

/// A serial device node the kernel created for a USB device, as read from sysfs.
struct TtyUsbNode {
    std::string tty_name;      ///< e.g. "ttyUSB0", "ttyACM0"
    std::uint8_t bus = 0;      ///< USB bus number (sysfs busnum)
    std::uint8_t address = 0;  ///< device address on that bus (sysfs devnum)
    std::uint16_t vendor_id = 0;
    std::uint16_t product_id = 0;
    std::string manufacturer;  ///< sysfs string descriptors, used when libusb may not open the device
    std::string product;
    std::string serial_number;
};

/// One USB serial adapter with every name the system gives it.
struct UsbSerialPort {
    std::uint16_t vendor_id = 0;
    std::uint16_t product_id = 0;
    std::string manufacturer;
    std::string product;
    std::string serial_number;
    std::uint8_t bus = 0;
    std::uint8_t address = 0;
    std::vector<std::string> device_nodes;  ///< /dev/ttyUSB* or /dev/ttyACM*
    std::vector<std::string> by_id_links;   ///< /dev/serial/by-id/* pointing at those nodes
};

/// Outcome of an enumeration; `usb_note` says why libusb saw nothing when it could not look at all.
struct UsbPortScan {
    std::vector<UsbSerialPort> ports;
    bool usb_available = true;
    std::string usb_note;
};

/// Where the system views live, so tests can point the scan at a fake tree.
struct SystemPaths {
    std::string sysfs_root = "/sys";
    std::string dev_root = "/dev";
};

/// ttyUSB*/ttyACM* nodes under `<sysfs_root>/class/tty` with the USB device each belongs to.
std::vector<TtyUsbNode> scan_sysfs_usb_ttys(const std::string& sysfs_root);

/// `<dev_root>/serial/by-id` links grouped by the tty name they resolve to ("ttyUSB0" -> links).
std::map<std::string, std::vector<std::string>> scan_by_id_links(const std::string& dev_root);

/// The adapters sysfs alone shows (when libusb cannot start): one per USB device (bus and address), with all of
/// its nodes and their by-id links, in the order of `nodes`.
std::vector<UsbSerialPort> ports_from_sysfs(const std::vector<TtyUsbNode>& nodes,
                                            const std::map<std::string, std::vector<std::string>>& by_id,
                                            const std::string& dev_root);

/// True for vendor ids of common USB-serial bridges and Arduino boards (listed even without a tty node,
/// e.g. when the kernel driver is missing).
bool is_known_serial_vendor(std::uint16_t vendor_id);

/// Joins libusb's device list with the sysfs and by-id views. Never throws for an absent USB subsystem:
/// that is reported in the result.
UsbPortScan list_usb_serial_ports(const SystemPaths& paths = {});

}  // namespace driftlab::host::io
