// TickUnwrapper: the firmware's free-running 32-bit tick (VERSION.tick_hz, 250 kHz on the ATmega328P: it
// wraps every 4.77 h) made into a 64-bit count, so t_s = unwrapped / tick_hz keeps growing over long runs.
// docs/recording.md "Time and sequence numbers".
#pragma once

#include <cstdint>
#include <optional>

namespace driftlab::receiver {

class TickUnwrapper {
public:
    /// The 64-bit tick nearest after the previous one for `tick` (a step back of less than 2^31 ticks is
    /// taken as a step back, not as a wrap), or nearest the expectation set by expect_near().
    std::uint64_t unwrap(std::uint32_t tick) {
        if (!started_) {
            started_ = true;
            last_ = base_ + tick;
            return last_;
        }
        const std::uint64_t reference = expected_ ? *expected_ : last_;
        expected_.reset();
        const auto delta = static_cast<std::int32_t>(tick - static_cast<std::uint32_t>(reference - base_));
        const std::int64_t next = static_cast<std::int64_t>(reference) + delta;
        last_ = next < static_cast<std::int64_t>(base_) ? base_ : static_cast<std::uint64_t>(next);
        return last_;
    }

    /// The next tick is unwrapped nearest `expected` (the board's count after a link gap, which may have
    /// wrapped once or more, or run on by more than 2^31 ticks) instead of nearest the previous one.
    void expect_near(std::uint64_t expected) {
        if (started_) expected_ = expected;
    }

    /// The firmware restarted (its tick began again at 0): later ticks continue after `base_ticks`.
    void restart_epoch(std::uint64_t base_ticks) {
        base_ = base_ticks;
        started_ = false;
        expected_.reset();
    }

    bool started() const { return started_; }
    std::uint64_t last() const { return last_; }

private:
    bool started_ = false;
    std::uint64_t base_ = 0;
    std::uint64_t last_ = 0;
    std::optional<std::uint64_t> expected_;
};

/// How many ticks a firmware ran from a row at tick `last` to a STATUS reporting `uptime`, if it ran on without
/// restarting: the forward distance from `last` to `uptime` with whole wraps (2^32) added, the one within
/// `tolerance` of `elapsed` (the same interval measured by the host's clock, in board ticks). Empty when none is:
/// the firmware restarted, or the host's clock cannot tell.
inline std::optional<std::uint64_t> ticks_run_on(std::uint32_t last, std::uint32_t uptime, double elapsed,
                                                 double tolerance) {
    constexpr double kWrap = 4294967296.0;
    const double forward = static_cast<double>(static_cast<std::uint32_t>(uptime - last));
    const double wraps =
        elapsed > forward ? static_cast<double>(static_cast<std::uint64_t>((elapsed - forward) / kWrap + 0.5)) : 0.0;
    const double run_on = forward + wraps * kWrap;
    if (!(run_on - elapsed <= tolerance && elapsed - run_on <= tolerance)) return std::nullopt;
    return static_cast<std::uint64_t>(run_on);
}

}  // namespace driftlab::receiver
