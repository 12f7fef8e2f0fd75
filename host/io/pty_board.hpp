// PtyBoard: the firmware core on the native port (fw::NativeBoard), in virtual time paced to the wall clock,
// with its UART on a pseudo-terminal (PtyBridge). What `driftlab hil --pty` serves, and what the end-to-end
// tests record from. docs/recording.md "Recording a simulated board".
//
// Every frame the firmware sends is also decoded on the board's side of the line and its SAMPLEs written to
// an optional ground-truth log, so a recording made through the pseudo-terminal can be compared with what was
// really sent. Planned unplugs close the pseudo-terminal for a while (the firmware keeps running).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"

namespace driftlab::host::io {

/// ADC code [counts] of channel `c` for the conversion triggered at `trigger_tick` [ticks since power-on].
using CodeSource = std::function<std::uint16_t(Channel c, std::uint64_t trigger_tick)>;

/// A simulated unplug: the pseudo-terminal disappears at `at_s` for `for_s` [s of virtual time].
struct PlannedUnplug {
    double at_s = 0.0;
    double for_s = 0.0;
};

struct PtyBoardOptions {
    double speed = 1.0;       ///< virtual seconds per wall second
    double duration_s = 0.0;  ///< [s] of virtual time to run; 0 = until stopped
    std::string link_path;    ///< optional stable symlink to the current /dev/pts/N
    std::string truth_log;    ///< optional log of every SAMPLE the firmware sent
    std::vector<PlannedUnplug> unplugs;
    /// The board's EEPROM at power-on (fw::kEepromBytes; hil --pty --cal); empty: erased.
    std::vector<std::uint8_t> eeprom;
};

struct PtyBoardSummary {
    double virtual_s = 0.0;           ///< [s] simulated
    std::uint64_t samples_sent = 0;   ///< SAMPLE frames the firmware wrote
    std::uint64_t frames_sent = 0;    ///< all frames the firmware wrote
    std::uint64_t bytes_dropped = 0;  ///< board output nobody read (unplugged, or the terminal buffer full)
};

/// Serves until the duration or `stop`. `on_ready(path)` is called with the client path each time the
/// pseudo-terminal (re)appears. Throws DeviceError when no pseudo-terminal can be made.
PtyBoardSummary serve_pty_board(const PtyBoardOptions& options, const CodeSource& source, const std::atomic<bool>& stop,
                                const std::function<void(const std::string&)>& on_ready);

}  // namespace driftlab::host::io
