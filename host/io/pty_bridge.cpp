// PtyBridge and WallClockPacer (pty_bridge.hpp).
#include "host/io/pty_bridge.hpp"

#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include "host/util/error.hpp"

namespace driftlab::host::io {
namespace {

double monotonic_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

PtyBridge::PtyBridge(std::string link_path) : link_path_(std::move(link_path)) { open_pty(); }

PtyBridge::~PtyBridge() { unplug(); }

void PtyBridge::open_pty() {
    master_fd_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (master_fd_ < 0) throw DeviceError("/dev/ptmx", std::string("posix_openpt: ") + std::strerror(errno));
    char name[128];
    if (::grantpt(master_fd_) != 0 || ::unlockpt(master_fd_) != 0 || ::ptsname_r(master_fd_, name, sizeof name) != 0) {
        const int err = errno;
        close_pty();
        throw DeviceError("/dev/ptmx", std::string("cannot prepare the pseudo-terminal: ") + std::strerror(err));
    }
    slave_path_ = name;
    slave_keep_fd_ = ::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (slave_keep_fd_ < 0) {
        const int err = errno;
        close_pty();
        throw DeviceError(name, std::string("cannot open the slave side: ") + std::strerror(err));
    }
    termios tio{};
    ::tcgetattr(slave_keep_fd_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(slave_keep_fd_, TCSANOW, &tio);
    if (!link_path_.empty()) {
        std::error_code ec;
        // Only a link is replaced (this board's from an earlier plug or run): a file or folder there is the
        // user's, and a mistyped --pty-link must not delete it.
        const auto type = std::filesystem::symlink_status(link_path_, ec).type();
        if (type != std::filesystem::file_type::not_found && type != std::filesystem::file_type::symlink) {
            close_pty();
            throw UsageError("--pty-link " + link_path_ +
                             ": something other than a symbolic link is there; refusing to replace it");
        }
        remove_link();
        std::filesystem::create_symlink(slave_path_, link_path_, ec);
        if (ec) throw DeviceError(link_path_, "cannot create the link to " + slave_path_ + ": " + ec.message());
    }
}

void PtyBridge::remove_link() {
    std::error_code ec;
    if (!link_path_.empty() && std::filesystem::is_symlink(std::filesystem::symlink_status(link_path_, ec)))
        std::filesystem::remove(link_path_, ec);
}

std::uint64_t PtyBridge::queued_bytes() const {
    int n = 0;
    if (slave_keep_fd_ < 0 || ::ioctl(slave_keep_fd_, FIONREAD, &n) != 0 || n < 0) return 0;
    return static_cast<std::uint64_t>(n);
}

void PtyBridge::close_pty() {
    dropped_bytes_ += queued_bytes();  // closing the terminal discards them
    if (slave_keep_fd_ >= 0) ::close(slave_keep_fd_);
    if (master_fd_ >= 0) ::close(master_fd_);
    slave_keep_fd_ = -1;
    master_fd_ = -1;
    slave_path_.clear();
}

void PtyBridge::unplug() {
    remove_link();
    close_pty();
}

void PtyBridge::plug() {
    if (!plugged()) open_pty();
}

void PtyBridge::write(const std::uint8_t* bytes, std::size_t count) {
    if (!plugged()) {
        dropped_bytes_ += count;
        return;
    }
    std::size_t done = 0;
    while (done < count) {
        const ssize_t n = ::write(master_fd_, bytes + done, count - done);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            break;  // EAGAIN: the terminal's buffer is full, nobody is reading
        }
    }
    dropped_bytes_ += count - done;
}

std::size_t PtyBridge::read(std::uint8_t* out, std::size_t capacity, int timeout_ms) {
    if (!plugged()) {
        if (timeout_ms > 0) ::usleep(static_cast<useconds_t>(timeout_ms) * 1000u);
        return 0;
    }
    pollfd pfd{master_fd_, POLLIN, 0};
    if (::poll(&pfd, 1, timeout_ms) <= 0 || (pfd.revents & POLLIN) == 0) return 0;
    const ssize_t n = ::read(master_fd_, out, capacity);
    return n > 0 ? static_cast<std::size_t>(n) : 0;
}

WallClockPacer::WallClockPacer(double speed) : speed_(speed), start_s_(monotonic_s()) {
    if (!(speed > 0.0)) throw UsageError("--speed must be positive");
}

double WallClockPacer::virtual_now_s() const { return (monotonic_s() - start_s_) * speed_; }

}  // namespace driftlab::host::io
