// Flashing the firmware through avrdude (docs/hardware.md "Flashing"). The command line is built here, run
// without a shell, and every missing piece (avrdude, port, hex file) is a DeviceError/UsageError that says
// what to do.
#pragma once

#include <string>
#include <vector>

namespace driftlab::host::io {

/// What to flash where. Defaults match an Arduino Uno/Nano (ATmega328P, optiboot at 115200 baud).
struct FlashRequest {
    std::string port;  ///< serial device of the board's bootloader
    std::string programmer = "arduino";
    int baud = 115200;  ///< bootloader baud rate [bit/s] (old Nano bootloader: 57600)
    std::string part = "atmega328p";
    std::string hex_file;             ///< Intel HEX image
    std::string avrdude = "avrdude";  ///< program name or path
    /// Intel HEX of the EEPROM bytes to write as well (the key record, `flash --key`); empty: the EEPROM is left.
    std::string eeprom_hex_file;
};

/// avrdude's argument vector (argv[0] included) for `request`: verify on, no chip erase (-D) as the
/// arduino bootloader requires; the EEPROM image after the flash image when there is one.
std::vector<std::string> avrdude_arguments(const FlashRequest& request);

/// Full path of `program` found in the directories of `path_env` (PATH syntax); empty when absent.
/// A name containing '/' is returned as is when it is executable.
std::string find_in_path(const std::string& program, const std::string& path_env);

/// The firmware image of the AVR build next to the native build that holds `exe_path`
/// (build/native/bin/driftlab -> build/avr/firmware/driftlab_fw.hex) when it exists, else the one the native build
/// made itself (build/native/avr-fw/firmware/driftlab_fw.hex) when that exists. Exact paths, no folder walk. Throws
/// DataError saying to pass --hex FILE, with the paths tried, or, for a binary outside a build tree (copied or
/// installed: no CMakeCache.txt in the folder above its own), with that reason.
std::string default_hex_file(const std::string& exe_path);

/// The checks a flash needs before avrdude: the image is a file (DataError), the port exists (DeviceError); an
/// empty image or port is a UsageError.
void check_image_and_port(const FlashRequest& request);

/// `word` as a POSIX shell reads it back: as is when it holds only safe characters, else in single quotes.
std::string shell_quoted(const std::string& word);

/// Checks the pieces (check_image_and_port, then avrdude), runs avrdude with its output on ours and returns when it
/// succeeded. Throws DeviceError (avrdude missing, port missing, avrdude failed) or DataError (hex missing).
void run_avrdude(const FlashRequest& request, const std::string& path_env);

}  // namespace driftlab::host::io
