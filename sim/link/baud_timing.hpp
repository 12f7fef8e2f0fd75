// Baud-rate timing of an 8N1 UART: each byte occupies the line for 10 bit times and is complete at the
// receiver when its stop bit ends; a byte handed over while the line is busy waits. docs/sim.md §Link.
#pragma once

#include "sim/link/link.hpp"

namespace driftlab::sim {

/// Bits on the line per byte: start + 8 data + stop.
inline constexpr double kBitsPerByte = 10.0;

/// Serialises bytes: arrival_k = max(t_k, arrival_{k-1}) + 10 / baud.
class BaudTiming final : public LinkStage {
public:
    explicit BaudTiming(double baud) : byte_time_s_(kBitsPerByte / baud) {}
    void process(Packet& packet, LinkCounters& counters) override;

private:
    double byte_time_s_;
    double line_free_s_ = 0.0;
};

}  // namespace driftlab::sim
