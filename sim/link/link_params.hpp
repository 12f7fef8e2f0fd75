// Parameters of the link model, one struct per behaviour, as read from a model file's [link] table.
// Every rate is a probability per byte or per packet; times are seconds. docs/sim.md §Link.
#pragma once

#include <cstdint>

namespace driftlab::sim {

/// What one Gilbert–Elliott trial decides about: a whole packet (frame) or a single byte.
enum class LossUnit : std::uint8_t { frame, byte };

/// Bursty loss (`packet_loss`): a two-state Markov chain, good G and bad B, stepped once per unit; in each state
/// a unit is lost with that state's probability. Stationary P(B) = p_good_to_bad / (p_good_to_bad + p_bad_to_good).
struct PacketLossParams {
    LossUnit unit = LossUnit::frame;
    double p_good_to_bad = 0.0;  ///< transition probability G -> B per unit, 0..1
    double p_bad_to_good = 1.0;  ///< transition probability B -> G per unit, 0..1 (> 0 when p_good_to_bad > 0)
    double loss_in_good = 0.0;   ///< loss probability in G, 0..1
    double loss_in_bad = 1.0;    ///< loss probability in B, 0..1
};

/// One direction of the link (firmware -> host or host -> firmware).
struct DirectionParams {
    double latency_s = 0.0;        ///< fixed delay added after serialisation [s], >= 0
    double byte_error_rate = 0.0;  ///< probability that a byte arrives corrupted (`byte_errors`), 0..1
    double byte_drop_rate = 0.0;   ///< probability that a byte is lost (dropped bytes), 0..1
    PacketLossParams packet_loss;
};

/// The whole link: a UART at `baud` (8N1: 10 bits per byte) in both directions.
struct LinkParams {
    double baud = 9600.0;         ///< line rate [bit/s], > 0
    DirectionParams to_host;      ///< firmware -> host
    DirectionParams to_firmware;  ///< host -> firmware
};

}  // namespace driftlab::sim
