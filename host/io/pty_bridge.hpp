// PtyBridge: an emulated board's UART exposed as a pseudo-terminal (posix_openpt/grantpt/unlockpt), so
// `driftlab record --port /dev/pts/N` talks to a simulated board through LibSerial exactly as to a real one.
// docs/recording.md "Recording a simulated board".
//
// The bridge holds the master side and also keeps one descriptor of the slave side open in raw mode: the
// terminal settings then survive between clients (a fresh slave would echo the board's bytes back), and the
// board's output does not fail while nobody listens (it is dropped when the terminal's buffer is full, as a
// UART with nobody on the line). unplug() closes both sides: the client sees a hang-up, as when a USB adapter
// is pulled; plug() makes a new pseudo-terminal and re-points the optional stable link (a symlink, like
// /dev/serial/by-id) at it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace driftlab::host::io {

class PtyBridge {
public:
    /// Creates the pseudo-terminal. `link_path` (optional) becomes a symlink to its slave path; only a symlink
    /// already there is replaced (UsageError for a file or folder). Throws DeviceError when the system has no
    /// pseudo-terminals left.
    explicit PtyBridge(std::string link_path = {});
    ~PtyBridge();
    PtyBridge(const PtyBridge&) = delete;
    PtyBridge& operator=(const PtyBridge&) = delete;

    /// Slave path (/dev/pts/N) of the current pseudo-terminal; empty while unplugged.
    const std::string& slave_path() const { return slave_path_; }
    /// The path clients should open: the stable link when there is one, else the slave path.
    std::string client_path() const { return link_path_.empty() ? slave_path_ : link_path_; }

    /// Board -> host. Never blocks; bytes that do not fit are dropped and counted.
    void write(const std::uint8_t* bytes, std::size_t count);
    /// Host -> board: what the client wrote, up to `capacity` bytes, waiting at most `timeout_ms` [ms].
    std::size_t read(std::uint8_t* out, std::size_t capacity, int timeout_ms);

    /// Simulated unplug: closes the pseudo-terminal and removes the link (if still a symlink).
    void unplug();
    /// Simulated replug: a new pseudo-terminal (a new /dev/pts/N), the link re-pointed at it.
    void plug();
    bool plugged() const { return master_fd_ >= 0; }

    /// Board output nobody will read: dropped for want of room or while unplugged, discarded unread with a closed
    /// terminal, and what the terminal still holds now (a client that has left reads it no more).
    std::uint64_t dropped_bytes() const { return dropped_bytes_ + queued_bytes(); }

private:
    void open_pty();
    void close_pty();
    void remove_link();                  // the stable link, if a symbolic link is what is there
    std::uint64_t queued_bytes() const;  // written to the terminal, not yet read from it

    std::string link_path_;
    std::string slave_path_;
    int master_fd_ = -1;
    int slave_keep_fd_ = -1;
    std::uint64_t dropped_bytes_ = 0;
};

/// Paces virtual time to the wall clock: virtual second t is due at start + t / speed.
class WallClockPacer {
public:
    /// `speed` = virtual seconds per wall second (1 = real time; 20 = twenty times faster).
    explicit WallClockPacer(double speed);
    /// Virtual time [s] that is due now.
    double virtual_now_s() const;

private:
    double speed_;
    double start_s_;
};

}  // namespace driftlab::host::io
