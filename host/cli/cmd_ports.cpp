// `driftlab ports`: lists USB serial adapters with the device nodes a recording can use (host/io/usb_ports).
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "host/cli/commands.hpp"
#include "host/io/usb_ports.hpp"

namespace driftlab::host::cli {
namespace {

struct PortsOptions {
    bool json = false;
};

std::string hex4(std::uint16_t v) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", v);
    return text;
}

void print_json(const io::UsbPortScan& scan) {
    nlohmann::json out;
    out["usb_available"] = scan.usb_available;
    out["usb_note"] = scan.usb_note;
    out["ports"] = nlohmann::json::array();
    for (const io::UsbSerialPort& p : scan.ports) {
        out["ports"].push_back({{"vendor_id", hex4(p.vendor_id)},
                                {"product_id", hex4(p.product_id)},
                                {"manufacturer", p.manufacturer},
                                {"product", p.product},
                                {"serial_number", p.serial_number},
                                {"bus", p.bus},
                                {"address", p.address},
                                {"device_nodes", p.device_nodes},
                                {"by_id_links", p.by_id_links}});
    }
    std::cout << out.dump(2) << "\n";
}

void print_text(const io::UsbPortScan& scan) {
    if (!scan.usb_available) std::cout << "note: " << scan.usb_note << "\n";
    if (scan.ports.empty()) {
        std::cout << "no USB serial adapter found (is the board plugged in? `dmesg | tail` shows what the "
                     "kernel saw)\n"
                     "a board on a built-in UART is given to `record --port` by its node (/dev/ttyS0, /dev/ttyAMA0); "
                     "`driftlab hil --pty` makes a simulated board on a pseudo-terminal\n";
        return;
    }
    for (const io::UsbSerialPort& p : scan.ports) {
        std::cout << hex4(p.vendor_id) << ":" << hex4(p.product_id) << "  "
                  << (p.manufacturer.empty() ? "?" : p.manufacturer) << " / " << (p.product.empty() ? "?" : p.product)
                  << "  serial " << (p.serial_number.empty() ? "-" : p.serial_number) << "  (bus "
                  << static_cast<int>(p.bus) << " address " << static_cast<int>(p.address) << ")\n";
        if (p.device_nodes.empty()) std::cout << "    no device node (serial driver not loaded?)\n";
        for (const std::string& node : p.device_nodes) std::cout << "    " << node << "\n";
        for (const std::string& link : p.by_id_links) std::cout << "    " << link << "\n";
    }
}

}  // namespace

void register_ports(CLI::App& app) {
    auto opts = std::make_shared<PortsOptions>();
    CLI::App* cmd = app.add_subcommand("ports", "List USB serial adapters and their device nodes");
    cmd->add_flag("--json", opts->json, "Print JSON (keys: usb_available, usb_note, ports[])");
    cmd->callback([opts] {
        const io::UsbPortScan scan = io::list_usb_serial_ports();
        if (opts->json) {
            print_json(scan);
        } else {
            print_text(scan);
        }
    });
}

}  // namespace driftlab::host::cli
