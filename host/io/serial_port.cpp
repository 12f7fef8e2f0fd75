// SerialPort over LibSerial: LibSerial opens and configures the device; poll(2) on its descriptor gives
// the timeout and the hang-up that LibSerial's blocking reads do not report.
#include "host/io/serial_port.hpp"

#include <fcntl.h>
#include <libserial/SerialPort.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>

#include "host/io/port_holders.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::io {
namespace {

const std::map<int, LibSerial::BaudRate>& baud_table() {
    using B = LibSerial::BaudRate;
    static const std::map<int, B> table = {
        {1200, B::BAUD_1200},       {2400, B::BAUD_2400},      {4800, B::BAUD_4800},     {9600, B::BAUD_9600},
        {19200, B::BAUD_19200},     {38400, B::BAUD_38400},    {57600, B::BAUD_57600},   {115200, B::BAUD_115200},
        {230400, B::BAUD_230400},   {460800, B::BAUD_460800},  {500000, B::BAUD_500000}, {921600, B::BAUD_921600},
        {1000000, B::BAUD_1000000}, {2000000, B::BAUD_2000000}};
    return table;
}

// Why a path cannot be a board's port, in words a user can act on.
std::string open_failure_cause(const std::string& path, const std::string& libserial_what) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        return std::string("cannot open: ") + std::strerror(errno) + " (see `driftlab ports` for adapters)";
    }
    if (!S_ISCHR(st.st_mode)) return "not a serial device (expected a character device such as /dev/ttyUSB0)";
    return "cannot open as a serial port: " + libserial_what +
           " (busy, no permission: add yourself to group "
           "dialout, or not a tty)";
}

}  // namespace

bool is_supported_baud(int baud) { return baud_table().count(baud) != 0; }

SerialPort::SerialPort(const std::string& path, int baud) : path_(path), baud_(baud) {
    if (!is_supported_baud(baud)) {
        throw UsageError("--baud " + std::to_string(baud) + ": not a standard rate (e.g. 9600, 57600, 115200)");
    }
    open_or_throw();
}

SerialPort::~SerialPort() { close(); }

// The port is the recording's alone: a second program that opened it could reconfigure the board behind its back.
// An advisory lock refuses a second driftlab (or any program that locks), TIOCEXCL every later open(2) but root's.
void SerialPort::take_exclusively(int fd) const {
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const std::string holders = port_holders(path_);
        throw DeviceError(path_, "in use by another program" + (holders.empty() ? std::string() : ": " + holders) +
                                     " (a recording needs the port to itself)");
    }
    ::ioctl(fd, TIOCEXCL);
}

void SerialPort::open_or_throw() {
    // LibSerial throws from its destructor when Open() failed half-way on a non-tty (tcgetattr), which would
    // end the program: check first that the path is a terminal at all.
    const int fd = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0 && errno == EBUSY) {
        const std::string holders = port_holders(path_);
        throw DeviceError(path_, "in use by another program, which holds it exclusively" +
                                     (holders.empty() ? std::string() : ": " + holders));
    }
    if (fd < 0) throw DeviceError(path_, open_failure_cause(path_, std::strerror(errno)));
    const bool tty = ::isatty(fd) == 1;
    ::close(fd);
    if (!tty) throw DeviceError(path_, "not a serial port (not a terminal device; expected e.g. /dev/ttyUSB0)");

    auto port = std::make_unique<LibSerial::SerialPort>();
    try {
        port->Open(path_);
        port->SetBaudRate(baud_table().at(baud_));
        port->SetCharacterSize(LibSerial::CharacterSize::CHAR_SIZE_8);
        port->SetParity(LibSerial::Parity::PARITY_NONE);
        port->SetStopBits(LibSerial::StopBits::STOP_BITS_1);
        port->SetFlowControl(LibSerial::FlowControl::FLOW_CONTROL_NONE);
        port->FlushInputBuffer();
        take_exclusively(port->GetFileDescriptor());
    } catch (const DeviceError&) {
        static_cast<void>(port.release());
        throw;
    } catch (const std::exception& e) {
        // Same destructor hazard as above: abandon the half-open object rather than risk terminate().
        static_cast<void>(port.release());
        throw DeviceError(path_, open_failure_cause(path_, e.what()));
    }
    port_ = std::move(port);
}

bool SerialPort::reopen() {
    close();
    try {
        open_or_throw();
        return true;
    } catch (const DeviceError&) {
        return false;
    }
}

void SerialPort::close() {
    if (!port_) return;
    try {
        if (port_->IsOpen()) port_->Close();
    } catch (const std::exception&) {
        // Closing a device that vanished can fail, and LibSerial's destructor would then close again and throw
        // out of a destructor (std::terminate): abandon the object, as open_or_throw does. It is gone either way.
        static_cast<void>(port_.release());
        return;
    }
    port_.reset();
}

bool SerialPort::is_open() const { return port_ && port_->IsOpen(); }

LinkStatus SerialPort::write(const std::uint8_t* bytes, std::size_t count) {
    if (!is_open()) return LinkStatus::lost;
    try {
        port_->Write(LibSerial::DataBuffer(bytes, bytes + count));
        port_->DrainWriteBuffer();
    } catch (const std::exception&) {
        return LinkStatus::lost;
    }
    return LinkStatus::ok;
}

ReadResult SerialPort::read(std::uint8_t* out, std::size_t capacity, int timeout_ms) {
    if (!is_open()) return {0, LinkStatus::lost};
    pollfd pfd{port_->GetFileDescriptor(), POLLIN, 0};
    const int ready = ::poll(&pfd, 1, timeout_ms);
    if (ready < 0) return {0, errno == EINTR ? LinkStatus::timeout : LinkStatus::lost};
    if (ready == 0) return {0, LinkStatus::timeout};
    if ((pfd.revents & POLLIN) == 0) return {0, LinkStatus::lost};  // POLLHUP/POLLERR alone: unplugged
    try {
        const int available = port_->GetNumberOfBytesAvailable();
        if (available <= 0) return {0, LinkStatus::lost};  // readable with nothing to read: hang-up
        const std::size_t n = std::min(capacity, static_cast<std::size_t>(available));
        LibSerial::DataBuffer data;
        port_->Read(data, n, 100);
        std::memcpy(out, data.data(), data.size());
        return {data.size(), LinkStatus::ok};
    } catch (const std::exception&) {
        return {0, LinkStatus::lost};
    }
}

}  // namespace driftlab::host::io
