// TickUnwrapper: the firmware's free-running 32-bit tick (VERSION.tick_hz, 250 kHz on the ATmega328P: it
// wraps every 4.77 h) made into a 64-bit count, so t_s = unwrapped / tick_hz keeps growing over long runs.
// docs/recording.md "Time and sequence numbers".
#pragma once

#include <cstdint>

namespace driftlab::host::io {

class TickUnwrapper {
public:
    /// The 64-bit tick nearest after the previous one for `tick` (a step back of less than 2^31 ticks is
    /// taken as a step back, not as a wrap).
    std::uint64_t unwrap(std::uint32_t tick) {
        if (!started_) {
            started_ = true;
            last_ = base_ + tick;
            return last_;
        }
        const auto delta = static_cast<std::int32_t>(tick - static_cast<std::uint32_t>(last_ - base_));
        const std::int64_t next = static_cast<std::int64_t>(last_) + delta;
        last_ = next < static_cast<std::int64_t>(base_) ? base_ : static_cast<std::uint64_t>(next);
        return last_;
    }

    /// The firmware restarted (its tick began again at 0): later ticks continue after `base_ticks`.
    void restart_epoch(std::uint64_t base_ticks) {
        base_ = base_ticks;
        started_ = false;
    }

    bool started() const { return started_; }
    std::uint64_t last() const { return last_; }

private:
    bool started_ = false;
    std::uint64_t base_ = 0;
    std::uint64_t last_ = 0;
};

}  // namespace driftlab::host::io
