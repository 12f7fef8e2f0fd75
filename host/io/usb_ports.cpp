// USB serial adapter enumeration: libusb for the USB view, sysfs and /dev/serial/by-id for the node names.
#include "host/io/usb_ports.hpp"

#include <libusb-1.0/libusb.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>

namespace driftlab::host::io {
namespace {

namespace fs = std::filesystem;

std::string read_sysfs_line(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

unsigned long read_sysfs_number(const fs::path& file, int base) {
    const std::string text = read_sysfs_line(file);
    if (text.empty()) return 0;
    try {
        return std::stoul(text, nullptr, base);
    } catch (const std::exception&) {
        return 0;
    }
}

bool is_usb_tty_name(const std::string& name) { return name.rfind("ttyUSB", 0) == 0 || name.rfind("ttyACM", 0) == 0; }

// The USB device directory is the first ancestor of the tty's device link that has busnum and devnum
// (ttyACM: device -> interface; ttyUSB: device -> usb-serial port -> interface).
std::optional<fs::path> usb_device_dir(const fs::path& tty_dir) {
    std::error_code ec;
    fs::path dir = fs::canonical(tty_dir / "device", ec);
    if (ec) return std::nullopt;
    for (int depth = 0; depth < 4 && dir.has_parent_path(); ++depth) {
        if (fs::exists(dir / "busnum") && fs::exists(dir / "devnum")) return dir;
        dir = dir.parent_path();
    }
    return std::nullopt;
}

std::string usb_string(libusb_device_handle* handle, std::uint8_t index) {
    if (handle == nullptr || index == 0) return {};
    std::array<unsigned char, 256> text{};
    const int n = libusb_get_string_descriptor_ascii(handle, index, text.data(), static_cast<int>(text.size()));
    if (n <= 0) return {};
    return std::string(reinterpret_cast<const char*>(text.data()), static_cast<std::size_t>(n));
}

void attach_nodes(UsbSerialPort& port, const std::vector<TtyUsbNode>& nodes,
                  const std::map<std::string, std::vector<std::string>>& by_id, const std::string& dev_root) {
    for (const TtyUsbNode& node : nodes) {
        if (node.bus != port.bus || node.address != port.address) continue;
        port.device_nodes.push_back(dev_root + "/" + node.tty_name);
        if (auto it = by_id.find(node.tty_name); it != by_id.end()) {
            port.by_id_links.insert(port.by_id_links.end(), it->second.begin(), it->second.end());
        }
        if (port.manufacturer.empty()) port.manufacturer = node.manufacturer;
        if (port.product.empty()) port.product = node.product;
        if (port.serial_number.empty()) port.serial_number = node.serial_number;
    }
}

}  // namespace

std::vector<TtyUsbNode> scan_sysfs_usb_ttys(const std::string& sysfs_root) {
    std::vector<TtyUsbNode> nodes;
    std::error_code ec;
    const fs::path tty_class = fs::path(sysfs_root) / "class" / "tty";
    for (fs::directory_iterator it(tty_class, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!is_usb_tty_name(name)) continue;
        const auto dev = usb_device_dir(it->path());
        if (!dev) continue;
        TtyUsbNode node;
        node.tty_name = name;
        node.bus = static_cast<std::uint8_t>(read_sysfs_number(*dev / "busnum", 10));
        node.address = static_cast<std::uint8_t>(read_sysfs_number(*dev / "devnum", 10));
        node.vendor_id = static_cast<std::uint16_t>(read_sysfs_number(*dev / "idVendor", 16));
        node.product_id = static_cast<std::uint16_t>(read_sysfs_number(*dev / "idProduct", 16));
        node.manufacturer = read_sysfs_line(*dev / "manufacturer");
        node.product = read_sysfs_line(*dev / "product");
        node.serial_number = read_sysfs_line(*dev / "serial");
        nodes.push_back(std::move(node));
    }
    std::sort(nodes.begin(), nodes.end(),
              [](const TtyUsbNode& a, const TtyUsbNode& b) { return a.tty_name < b.tty_name; });
    return nodes;
}

std::map<std::string, std::vector<std::string>> scan_by_id_links(const std::string& dev_root) {
    std::map<std::string, std::vector<std::string>> links;
    std::error_code ec;
    const fs::path dir = fs::path(dev_root) / "serial" / "by-id";
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code link_ec;
        if (!it->is_symlink(link_ec)) continue;
        const fs::path target = fs::read_symlink(it->path(), link_ec);
        if (link_ec) continue;
        links[target.filename().string()].push_back(it->path().string());
    }
    for (auto& [tty, paths] : links) std::sort(paths.begin(), paths.end());
    return links;
}

std::vector<UsbSerialPort> ports_from_sysfs(const std::vector<TtyUsbNode>& nodes,
                                            const std::map<std::string, std::vector<std::string>>& by_id,
                                            const std::string& dev_root) {
    std::vector<UsbSerialPort> ports;
    for (const TtyUsbNode& node : nodes) {
        // One adapter per USB device: a two-port bridge (FT2232: ttyUSB0, ttyUSB1) is one device with two nodes.
        const bool listed = std::any_of(ports.begin(), ports.end(), [&](const UsbSerialPort& p) {
            return p.bus == node.bus && p.address == node.address;
        });
        if (listed) continue;
        UsbSerialPort port;
        port.vendor_id = node.vendor_id;
        port.product_id = node.product_id;
        port.bus = node.bus;
        port.address = node.address;
        attach_nodes(port, nodes, by_id, dev_root);
        ports.push_back(std::move(port));
    }
    return ports;
}

bool is_known_serial_vendor(std::uint16_t vendor_id) {
    // FTDI, Silicon Labs CP210x, WCH CH340, Prolific, Arduino, Arduino (clones, SA), Adafruit.
    constexpr std::uint16_t kVendors[] = {0x0403, 0x10c4, 0x1a86, 0x067b, 0x2341, 0x2a03, 0x239a};
    return std::find(std::begin(kVendors), std::end(kVendors), vendor_id) != std::end(kVendors);
}

UsbPortScan list_usb_serial_ports(const SystemPaths& paths) {
    UsbPortScan scan;
    const std::vector<TtyUsbNode> nodes = scan_sysfs_usb_ttys(paths.sysfs_root);
    const auto by_id = scan_by_id_links(paths.dev_root);

    // libusb starts without a USB bus (a container run without the host's devices) and lists nothing, which had
    // read as "no board plugged in".
    std::error_code ec;
    const bool bus_visible =
        fs::exists(fs::path(paths.sysfs_root) / "bus/usb", ec) || fs::exists(fs::path(paths.dev_root) / "bus/usb", ec);
    libusb_context* ctx = nullptr;
    const int init = bus_visible ? libusb_init(&ctx) : LIBUSB_ERROR_NO_DEVICE;
    if (init != LIBUSB_SUCCESS) {
        scan.usb_available = false;
        scan.usb_note = bus_visible ? std::string("libusb cannot open the USB subsystem: ") + libusb_strerror(init)
                                    : "no USB bus is visible here (neither " + paths.sysfs_root + "/bus/usb nor " +
                                          paths.dev_root + "/bus/usb: a container started without the host's devices?)";
        // sysfs alone still names the adapters the kernel knows.
        scan.ports = ports_from_sysfs(nodes, by_id, paths.dev_root);
        return scan;
    }

    libusb_device** list = nullptr;
    const ssize_t count = libusb_get_device_list(ctx, &list);
    if (count < 0) {
        scan.usb_available = false;
        scan.usb_note = std::string("libusb cannot list devices: ") + libusb_strerror(static_cast<int>(count));
    }
    for (ssize_t i = 0; i < count; ++i) {
        libusb_device* dev = list[i];
        libusb_device_descriptor desc{};
        if (libusb_get_device_descriptor(dev, &desc) != LIBUSB_SUCCESS) continue;
        UsbSerialPort port;
        port.vendor_id = desc.idVendor;
        port.product_id = desc.idProduct;
        port.bus = libusb_get_bus_number(dev);
        port.address = libusb_get_device_address(dev);
        const bool has_node = std::any_of(nodes.begin(), nodes.end(), [&](const TtyUsbNode& n) {
            return n.bus == port.bus && n.address == port.address;
        });
        if (!has_node && !is_known_serial_vendor(desc.idVendor)) continue;
        libusb_device_handle* handle = nullptr;
        if (libusb_open(dev, &handle) == LIBUSB_SUCCESS) {
            port.manufacturer = usb_string(handle, desc.iManufacturer);
            port.product = usb_string(handle, desc.iProduct);
            port.serial_number = usb_string(handle, desc.iSerialNumber);
            libusb_close(handle);
        }
        attach_nodes(port, nodes, by_id, paths.dev_root);
        scan.ports.push_back(std::move(port));
    }
    if (list != nullptr) libusb_free_device_list(list, 1);
    libusb_exit(ctx);
    std::sort(scan.ports.begin(), scan.ports.end(), [](const UsbSerialPort& a, const UsbSerialPort& b) {
        return a.bus != b.bus ? a.bus < b.bus : a.address < b.address;
    });
    return scan;
}

}  // namespace driftlab::host::io
