// The link between the emulated board's UART and the host: one direction is a pipeline of behaviours (baud
// timing, packet loss, byte drops, byte errors, latency), each in its own file.
//
// How to use: call `send(t_s, packet)` with the bytes a sender handed to its UART at time t_s, one packet per
// call (the host-in-the-loop passes one protocol frame per call, so frame-unit losses hit whole frames); ask
// `next_arrival_s()` when the next byte reaches the receiver and `deliver_until(t_s, out)` for every byte due by
// then, in arrival order. `counters()` says exactly what the link destroyed, so a test can compare it with the
// receiver's view (seq gaps, CRC rejects). docs/sim.md §Link.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "sim/link/link_params.hpp"

namespace driftlab::sim {

/// One byte in flight: its value and the time it is (so far) due at the receiver [s].
struct TimedByte {
    double t_s;
    std::uint8_t value;
};

/// A packet travelling through the pipeline; behaviours edit the bytes and mark damage.
struct Packet {
    std::vector<TimedByte> bytes;
    bool damaged = false;  ///< at least one byte lost or changed: the receiver cannot accept this packet
};

/// What a direction did to the traffic it carried. Exact counts, not estimates.
struct LinkCounters {
    std::uint64_t packets_sent = 0;     ///< packets handed to send()
    std::uint64_t bytes_sent = 0;       ///< bytes handed to send()
    std::uint64_t packets_lost = 0;     ///< whole packets removed by frame-unit packet loss
    std::uint64_t packets_damaged = 0;  ///< packets that lost or changed at least one byte (incl. packets_lost)
    std::uint64_t bytes_lost = 0;       ///< bytes removed by packet loss (either unit)
    std::uint64_t bytes_dropped = 0;    ///< bytes removed by byte drops
    std::uint64_t bytes_corrupted = 0;  ///< bytes delivered with a changed value
    std::uint64_t bytes_delivered = 0;  ///< bytes handed to the receiver so far
};

/// One behaviour of a direction. Implementations: baud_timing, packet_loss, dropped_bytes, byte_errors, latency.
class LinkStage {
public:
    virtual ~LinkStage() = default;
    /// Acts on one packet in place; adds what it did to `counters`.
    virtual void process(Packet& packet, LinkCounters& counters) = 0;
};

/// One direction: the behaviours in physical order (UART, air, receiver delay), then a queue to the receiver.
class LinkDirection {
public:
    /// Builds the standard pipeline for `params` at `baud`; `seed`/`stream_base` give each random behaviour its
    /// own substream (stream_base distinguishes the two directions).
    LinkDirection(double baud, const DirectionParams& params, std::uint64_t seed, std::uint64_t stream_base);

    /// The sender's UART accepts `packet` at `t_s` [s].
    void send(double t_s, std::span<const std::uint8_t> packet);
    /// Arrival time of the next byte [s], or nothing when the link is empty.
    std::optional<double> next_arrival_s() const;
    /// Appends every byte due by `t_s` [s] to `out`, in arrival order.
    void deliver_until(double t_s, std::vector<std::uint8_t>& out);

    const LinkCounters& counters() const { return counters_; }

private:
    std::vector<std::unique_ptr<LinkStage>> stages_;
    std::deque<TimedByte> in_flight_;
    LinkCounters counters_;
};

/// Both directions of a link.
class Link {
public:
    Link(const LinkParams& params, std::uint64_t seed);

    LinkDirection& to_host() { return to_host_; }
    LinkDirection& to_firmware() { return to_firmware_; }
    const LinkDirection& to_host() const { return to_host_; }
    const LinkDirection& to_firmware() const { return to_firmware_; }

private:
    LinkDirection to_host_;
    LinkDirection to_firmware_;
};

}  // namespace driftlab::sim
