// Host-in-the-loop: the firmware on an emulated board, fed by the sensor model at the exact conversion instants
// it armed, its UART bytes carried by the link model (with baud timing) to a host that handshakes, polls or
// listens, and turns frames into log records. One deterministic event loop in virtual time: the same options
// and seed give the same records bit for bit. docs/sim.md §Host-in-the-loop.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "sim/hil/board_key.hpp"
#include "sim/hil/die_temperature.hpp"
#include "sim/hil/emulated_board.hpp"
#include "sim/hil/hil_record.hpp"
#include "sim/hil/host_endpoint.hpp"
#include "sim/link/link.hpp"
#include "sim/model/sim_model.hpp"
#include "sim/motion/trajectory.hpp"

namespace driftlab::sim {

/// Which emulated board runs the firmware. Only the native core exists today.
enum class TargetKind : std::uint8_t { native };

struct HilOptions {
    SimModel model;              ///< sensor, effects, firmware CONFIG, link
    double duration_s = 4000.0;  ///< recording time after the handshake [s] (output count = duration/period)
    std::uint64_t seed = 1;      ///< every random component derives its substream from it
    double warm_up_s = 0.0;      ///< the sensor was powered this long before the board booted [s] (eq. 1 time)
    /// The robot the unit rides, on the board's clock; null: at rest on the table.
    std::shared_ptr<const Trajectory> trajectory;
    double reply_timeout_s = 0.5;  ///< host's resend timeout for requests [s]
    /// The board's EEPROM at power-on (fw::kEepromBytes, eeprom_image.hpp: `hil --cal`); empty: erased.
    std::vector<std::uint8_t> eeprom;
    /// The key the host signs CONFIG_SET with (the one in `eeprom`: `hil --key`); none: sent unsigned, as to an open
    /// board.
    std::optional<BoardKey> key;
    /// The board's own die temperature, which its firmware reads at boot and about once a second.
    DieTemperature die_temperature;
    TargetKind target = TargetKind::native;
    /// When set, builds the board instead of `target`: how the AVR board (sim/avr, a library that depends on this
    /// one) plugs in for `driftlab hil --target avr`.
    std::function<std::unique_ptr<EmulatedBoard>()> make_board;
    /// Called now and then with the fraction of virtual time done (0..1); may be empty.
    std::function<void(double)> progress;
    /// Called once when the handshake has verified the configuration, before the first record; may be empty
    /// (a log writer needs VERSION for its metadata).
    std::function<void(const proto::VersionPayload&, const proto::ConfigPayload&)> on_ready;
    /// Called with every conversion the sensor model makes: the channel, the board's nominal instant [s since its
    /// start] and the code; may be empty.
    std::function<void(Channel, double board_t_s, std::uint16_t code)> on_conversion;
    /// When it turns true (a Ctrl-C), the run ends at its next event with what it has; may be null.
    const std::atomic<bool>* stop = nullptr;
};

/// Everything a run counted; the JSON summary of `driftlab hil` is made of these.
struct HilSummary {
    HostCounters host;                 ///< frames received, lost (seq gaps), polls, rows
    proto::DecoderCounters decoder{};  ///< host decoder: bad CRC, bad length, resync bytes
    LinkCounters to_host;              ///< what the link did to the firmware's frames (packets = frames)
    LinkCounters to_firmware;          ///< ... and to the host's
    proto::VersionPayload version{};   ///< as the host received it
    proto::StatusPayload status{};     ///< firmware counters at the end of the run
    std::uint64_t conversions = 0;     ///< ADC conversions the sensor model produced
    double simulated_s = 0.0;          ///< virtual time at the end [s since power-on]
    bool interrupted = false;          ///< ended by HilOptions::stop, not by its duration
};

/// Why the link cannot carry the firmware's output (its frames per output period need more than link.baud), with
/// the figures; none when it can.
std::optional<std::string> link_capacity_refusal(const SimModel& model);

/// Runs one host-in-the-loop session; records go to `sink` as the host completes them. The caller refuses a model
/// whose link cannot carry its output (link_capacity_refusal) before: `driftlab hil` does, telling the model file's
/// fault from the command line's, which a check in here could not.
/// Throws BoardError when the emulated board stops answering, ConfigRefused when it refuses the configuration.
HilSummary run_hil(const HilOptions& options, const RecordSink& sink);

}  // namespace driftlab::sim
