// SerialPort: a board's UART seen through LibSerial (a USB adapter, a radio modem, or a pseudo-terminal),
// as a ByteLink with timeouts and hang-up detection. docs/recording.md "Durability".
#pragma once

#include <memory>
#include <string>

#include "host/io/byte_link.hpp"

namespace LibSerial {
class SerialPort;
}

namespace driftlab::host::io {

class SerialPort : public ByteLink {
public:
    /// Opens `path` at `baud` [bit/s], 8N1, no flow control, raw, and discards stale input.
    /// Throws UsageError for a baud rate termios cannot set, DeviceError when the device is missing,
    /// busy or not a serial port (the message names the path and the cause).
    SerialPort(const std::string& path, int baud);
    ~SerialPort() override;
    SerialPort(const SerialPort&) = delete;
    SerialPort& operator=(const SerialPort&) = delete;

    LinkStatus write(const std::uint8_t* bytes, std::size_t count) override;
    ReadResult read(std::uint8_t* out, std::size_t capacity, int timeout_ms) override;

    /// Closes the device (after a loss) so that reopen() can try again.
    void close();
    /// Tries once to open the same path again; false when it is still absent or unusable.
    bool reopen();
    bool is_open() const;

    const std::string& path() const { return path_; }
    int baud() const { return baud_; }

private:
    void open_or_throw();
    void take_exclusively(int fd) const;

    std::string path_;
    int baud_;
    std::unique_ptr<LibSerial::SerialPort> port_;
};

/// True when termios knows `baud` [bit/s].
bool is_supported_baud(int baud);

}  // namespace driftlab::host::io
