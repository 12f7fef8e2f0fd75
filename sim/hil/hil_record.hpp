// HilRecord: one row of the canonical log as the host-in-the-loop produces it (docs/log-format.md): time from
// the firmware tick, unwrapped seq, smoothed values in counts, and the optional columns.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "driftlab/channels.hpp"

namespace driftlab::sim {

struct HilRecord {
    double t_s = 0.0;                                 ///< newest conversion's tick / tick_hz [s since power-on]
    std::uint64_t seq = 0;                            ///< SAMPLE frame seq, unwrapped
    std::uint64_t tick = 0;                           ///< newest conversion's tick, unwrapped [ticks]
    std::array<double, kChannelCount> value_counts{}; ///< least-squares estimate, proto::q8_to_counts(value_q8) [counts]
    bool has_raw = false;                             ///< raw mode: raw_counts holds the RAW frame's codes
    std::array<std::uint16_t, kChannelCount> raw_counts{};  ///< newest raw codes [counts]
    std::uint8_t sat_flags = 0;                       ///< bit c: channel c saturated inside its window
    std::uint8_t n_window = 0;                        ///< conversions in the window [conversions]
    std::uint16_t dropped = 0;                        ///< conversions the firmware lost since boot [conversions]
};

/// Receives each record as soon as the host has it complete (in time order).
using RecordSink = std::function<void(const HilRecord&)>;

}  // namespace driftlab::sim
