// LogAssembler: turns a recording's capture stream (received bytes + recorder events, capture.hpp) into the
// canonical log (host/log). The recorder feeds it live and `driftlab decode` feeds it from the capture file,
// through the same code, so the decoded log equals the recorded one byte for byte. docs/recording.md.
//
// Events it understands (text of 'E' records):
//   "start"          handshake and configuration are done: write the log's metadata and header
//   "lost"           the link went away: forget a cut frame; frames after it wait for "resumed", which follows
//                    the gap line, and the newest STATUS among them decides how tick and seq continue: its
//                    uptime, against how far the board's clock ran by the host's clock, tells whether the
//                    firmware restarted or ran on (across a wrap of its tick, or several)
//   "gap: <text>"    write `# gap: <text>` into the log
//   "resumed"        the recorder finished the handshake after a reconnect
// Rows: one per SAMPLE (joined with the RAW of the same tick in raw mode; a lost RAW leaves raw_* = -1 and
// flags bit 0 set). t_s = unwrapped tick / tick_hz; seq = unwrapped SAMPLE seq.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/receiver/row_assembler.hpp"
#include "driftlab/receiver/seq_tracker.hpp"
#include "driftlab/receiver/tick_unwrapper.hpp"
#include "host/io/board_client.hpp"
#include "host/io/board_rows.hpp"
#include "host/io/capture.hpp"
#include "host/log/log_writer.hpp"

namespace driftlab::host::io {

/// What has been assembled so far (the status line and the final summary read it).
struct AssemblyStats {
    std::uint64_t rows = 0;
    std::uint64_t frames = 0;       ///< valid frames received, duplicates included
    std::uint64_t lost_frames = 0;  ///< sequence numbers never received
    std::uint64_t duplicate_frames = 0;
    std::uint64_t reordered_frames = 0;
    std::uint64_t stale_samples = 0;        ///< SAMPLEs whose time was not after the previous row (repeated answers)
    std::uint64_t unreachable_samples = 0;  ///< SAMPLEs (CRC intact) with a value the converter cannot produce
    std::uint64_t empty_samples = 0;        ///< SAMPLEs of an empty window (n_window 0: answered before a conversion)
    std::uint64_t raw_missing = 0;
    std::uint64_t gaps = 0;
    std::uint64_t firmware_restarts = 0;
    /// Frames sharing a seq with an earlier one of other content (a forged or corrupted frame that passed its CRC):
    /// the second is dropped, and a row either made is kept out of the log when still held back.
    std::uint64_t conflicting_frames = 0;
    std::uint64_t conflicting_rows = 0;     ///< rows kept out of the log for a conflict
    std::uint64_t unexpected_versions = 0;  ///< VERSIONs after the start that differ from the handshake's: ignored
    std::uint64_t unexpected_configs = 0;   ///< CONFIGs after the start that differ from the handshake's: ignored
    /// ACKs of a CONFIG_SET or CAL_SET after the start, outside a reconnect: someone else reconfigured the board. No
    /// SAMPLE after the first is a row (its outputs follow a configuration the log does not state); `record` stops
    /// there.
    std::uint64_t foreign_config_acks = 0;
    /// SAMPLEs whose window (n_window) is not the handshake's once it had filled, outside a reconnect: the board was
    /// reconfigured (its ACK lost) or restarted. As for a foreign ACK, no SAMPLE after it is a row.
    std::uint64_t other_window_samples = 0;
    /// SAMPLEs whose calibration state or id is not the handshake's VERSION's, outside a reconnect: the outputs are
    /// compensated otherwise than the log's metadata says (a CAL_SET with its ACK lost, a warm restart). No row
    /// follows.
    std::uint64_t other_calibration_samples = 0;
    /// Whether the board left the handshake's configuration (a foreign ACK, another window or another calibration):
    /// the rows end there.
    bool board_reconfigured() const {
        return foreign_config_acks + other_window_samples + other_calibration_samples > 0;
    }
    std::optional<double> first_t_s;                  ///< [s] of the first row
    std::optional<double> last_t_s;                   ///< [s] of the newest row
    std::array<double, kChannelCount> last_counts{};  ///< [counts] newest row
    std::uint16_t last_dropped = 0;                   ///< firmware's dropped-conversion counter in the newest SAMPLE
};

class LogAssembler {
public:
    /// `log_path` is created at the "start" event; `capture_header` supplies port, baud, start time...
    LogAssembler(std::string log_path, CaptureHeader capture_header);

    void on_rx(std::uint64_t t_us, const std::uint8_t* bytes, std::size_t count);
    void on_event(std::uint64_t t_us, const std::string& text);
    /// Writes a pending row and closes the log. Throws what LogWriter throws.
    void finish();
    /// The log's pending lines to the disk (LogWriter::sync()).
    void sync();

    bool started() const { return writer_ != nullptr; }
    /// What has been assembled so far, the receiver's counts of samples that made no row included.
    AssemblyStats stats() const;
    /// The frame decoder's rejects (bad CRC among them), which AssemblyStats counts only as lost sequence numbers.
    const proto::DecoderCounters& decoder_counters() const { return decoder_.counters(); }
    const std::optional<proto::VersionPayload>& version() const { return version_; }
    const std::optional<proto::ConfigPayload>& config() const { return config_; }

private:
    void handle_frame(std::uint64_t t_us, const Frame& frame);
    void process_frame(std::uint64_t t_us, const Frame& frame);
    void release_held();
    struct Stamped;
    /// How tick and seq continue after a gap, from the board's count at `evidence` (the STATUS uptime, or the first
    /// SAMPLE's tick); true when the firmware restarted.
    bool settle_gap(const Stamped& evidence);
    /// Board ticks elapsed from the newest SAMPLE to host time `t_us`, and how far off that may be.
    std::optional<std::pair<double, double>> board_ticks_since_newest(std::uint64_t t_us) const;
    /// Takes a row of the receiver into the held-back rows; false when a value is one no converter makes.
    bool write(const receiver::Row& row);
    /// Writes the held-back rows down to `keep` of them (the newest), oldest first.
    void write_held_rows(std::size_t keep);
    /// A frame whose seq is new: what it is, read (the handshake's VERSION and CONFIG, a SAMPLE's row...).
    void take_frame(std::uint64_t t_us, const Frame& frame, std::uint64_t unwrapped_seq);
    /// What a VERSION or CONFIG after the start changes of the handshake's ("CONFIG raw 0 -> 1"); "" when nothing,
    /// or before the start, or in a reconnect's verified handshake.
    std::string unexpected_difference(const Frame& frame) const;
    /// A VERSION or CONFIG that changes the handshake's is counted, noted in the log and ignored (how rows are read
    /// and written is the handshake's for the whole recording); true when it was one.
    bool note_if_unexpected(const Frame& frame, std::uint64_t seq);
    /// Whether a frame whose seq was seen before carries other content; if so, counts it and settles which to
    /// believe: a VERSION or CONFIG that changes the handshake's loses to the SAMPLE of its seq (true: take this
    /// SAMPLE); otherwise a held row of that seq is dropped.
    bool check_conflict(std::uint64_t seq, const Frame& frame);
    /// Whether SAMPLE `s` shows a window the handshake did not set, once it had filled: if so, ends the rows.
    bool check_window(const proto::SamplePayload& s, std::uint16_t frame_seq);
    /// Whether SAMPLE `s` shows a calibration the handshake's VERSION did not: if so, ends the rows.
    bool check_calibration(const proto::SamplePayload& s, std::uint16_t frame_seq);
    /// Writes the held rows, then a `# unexpected: WHY` line after them (what follows is the caller's: ignored frames,
    /// or no more rows once stats' board_reconfigured()).
    void write_note(const std::string& why);
    void start_log();

    std::string log_path_;
    CaptureHeader capture_header_;
    std::unique_ptr<LogWriter> writer_;
    proto::Decoder decoder_;
    receiver::SeqTracker seq_;
    receiver::TickUnwrapper ticks_;
    std::optional<proto::VersionPayload> version_;
    std::optional<proto::ConfigPayload> config_;
    std::optional<receiver::RowAssembler> rows_;  ///< from the "start" event on
    /// Rows are written kHeldRows behind the newest, so that a frame of the same seq arriving after a forged one (or
    /// before it) keeps both out of the log.
    static constexpr std::size_t kHeldRows = 2;
    std::deque<receiver::Row> held_rows_;
    /// Recent frames by unwrapped seq (slot seq % size): their content's fingerprint, to tell a repeat from a
    /// conflict, and whether it was an unexpected VERSION or CONFIG.
    struct Seen {
        std::uint64_t seq = 0;
        std::uint64_t print = 0;
        bool unexpected = false;
    };
    std::array<Seen, 256> fingerprints_{};
    /// Whether a SAMPLE has shown the handshake's window full since the start or the last reconnect.
    bool window_filled_ = false;
    bool replaying_held_ = false;  ///< frames held over a reconnect: its handshake may legitimately differ
    struct Stamped {               // host time [us] of something the board sent
        std::uint64_t t_us;
        std::uint64_t tick;  // the board's unwrapped tick (a SAMPLE) or 32-bit uptime (a STATUS)
    };
    bool holding_ = false;
    std::uint64_t lost_t_us_ = 0;
    std::optional<std::uint64_t> first_held_t_us_;
    std::vector<std::pair<std::uint64_t, Frame>> held_;  ///< frames received since the loss, with their host time
    std::optional<Stamped> held_status_;                 ///< the newest STATUS among the held frames (its uptime)
    bool awaiting_evidence_ = false;                     ///< a gap without a STATUS: the next SAMPLE settles it
    std::uint32_t last_epoch_tick_ = 0;                  // newest SAMPLE tick since the last firmware start [ticks]
    std::optional<Stamped> epoch_first_sample_;  ///< the first SAMPLE since the firmware's start (its clock's rate)
    std::optional<Stamped> newest_sample_;
    AssemblyStats stats_;
};

/// Metadata of a log made from a board: `source` (record, hil), firmware facts from VERSION, configuration from
/// CONFIG, then the `extra` pairs (a capture header: port, baud, start time...; or the simulator's own keys).
LogMetadata board_metadata(std::string_view source, const proto::VersionPayload& version,
                           const proto::ConfigPayload& config, const CaptureHeader& extra);

}  // namespace driftlab::host::io
