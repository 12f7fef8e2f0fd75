// RowAssembler: the host end of protocol v1 that turns a board's SAMPLE (and, in raw mode, RAW) frames into rows of
// the canonical log (docs/log-format.md §4): time from the unwrapped tick, values from Q8, the RAW paired with the
// SAMPLE of its tick. The one row assembly of `record`, `decode` (host/io/log_assembler), `hil`
// (sim/hil/host_endpoint) and the pseudo-terminal board's truth log; they unwrap seq and tick with SeqTracker and
// TickUnwrapper beside it and hand it each frame's unwrapped numbers.
//
// Rules (docs/recording.md "Time and sequence numbers"):
// - a SAMPLE with n_window 0 holds zeros that are no reading: counted, never a row;
// - a SAMPLE whose time is not after the previous row's (a POLL answered twice from one output) is counted stale;
// - in raw mode a SAMPLE waits for the RAW of the same tick; when the next SAMPLE (or finish()) comes first, its
//   RAW was lost: the row is kept without raw codes (MissingRaw::mark) or left out (MissingRaw::drop);
// - rows go to the sink in time order; a row the sink refuses (a value no converter makes) is no row.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "driftlab/channels.hpp"
#include "driftlab/proto/messages.hpp"

namespace driftlab::receiver {

/// One row of the canonical log as a board's frames give it.
struct Row {
    double t_s = 0.0;                                       ///< unwrapped tick / tick_hz [s since power-on]
    std::uint64_t seq = 0;                                  ///< the SAMPLE frame's unwrapped seq
    std::uint64_t tick = 0;                                 ///< newest conversion's unwrapped tick [ticks]
    std::array<double, kChannelCount> value_counts{};       ///< least-squares estimate, q8_to_counts [counts]
    bool has_raw = false;                                   ///< raw mode: raw_counts holds the RAW frame's codes
    std::array<std::uint16_t, kChannelCount> raw_counts{};  ///< newest raw codes [counts]
    std::uint8_t sat_flags = 0;                             ///< bit c: channel c saturated inside its window
    std::uint8_t n_window = 0;                              ///< conversions in the window [conversions]
    std::uint16_t dropped = 0;                              ///< conversions the firmware lost since boot
    std::uint16_t temp_code = proto::kNoTemperature;        ///< the board's newest die temperature code
};

/// What becomes of a raw-mode SAMPLE whose RAW frame was lost.
enum class MissingRaw : std::uint8_t {
    mark,  ///< a row without raw codes (has_raw false): `record` and `decode` keep every good value
    drop,  ///< no row: `hil`, whose logs have no flags column
};

struct RowOptions {
    std::uint32_t tick_hz = 0;  ///< VERSION.tick_hz [Hz]
    bool raw = false;           ///< CONFIG.raw: a RAW follows each SAMPLE
    MissingRaw missing_raw = MissingRaw::mark;
};

/// What the assembler saw besides its rows.
struct RowCounts {
    std::uint64_t samples = 0;        ///< SAMPLEs handed in
    std::uint64_t empty_samples = 0;  ///< with n_window 0: no row
    std::uint64_t stale_samples = 0;  ///< time not after the previous row's: no row
    std::uint64_t dropped_rows = 0;   ///< MissingRaw::drop: SAMPLEs left out because their RAW was lost
};

class RowAssembler {
public:
    /// Takes a row; false when it refused it (a value no converter makes), so that it is no row of the log.
    using Sink = std::function<bool(const Row&)>;

    RowAssembler(const RowOptions& options, Sink sink);

    /// A SAMPLE with its frame's unwrapped seq and its unwrapped tick.
    void sample(const proto::SamplePayload& sample, std::uint64_t seq, std::uint64_t tick);
    /// A RAW frame: completes the waiting SAMPLE of the same tick; any other is ignored.
    void raw(const proto::RawPayload& raw);
    /// The stream ended, or broke (a lost link): a SAMPLE still waiting for its RAW is one whose RAW was lost.
    void end_of_stream();

    const RowOptions& options() const { return options_; }
    const RowCounts& counts() const { return counts_; }
    /// Time of the newest row the sink took [s], none before the first.
    const std::optional<double>& last_t_s() const { return last_t_s_; }

private:
    void without_raw(const Row& row);
    void emit(const Row& row);

    RowOptions options_;
    Sink sink_;
    std::optional<Row> waiting_;        // raw mode: a SAMPLE waiting for its RAW
    std::uint32_t waiting_tick32_ = 0;  // its tick as the frames carry it
    std::optional<double> last_t_s_;
    RowCounts counts_;
};

}  // namespace driftlab::receiver
