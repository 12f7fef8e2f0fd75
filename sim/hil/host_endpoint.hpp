// HostEndpoint: what a real host program does on its end of the serial line, in virtual time. It decodes the
// firmware's bytes (common/ decoder), unwraps seq and tick, and talks to the firmware like `driftlab record`:
//   HELLO -> VERSION, CONFIG_SET -> ACK (NAK ends the run), CONFIG_GET -> CONFIG (must equal what was set),
//   then POLL every output period (poll mode, the paper's) or just listen (stream mode) until the duration,
//   then, in stream mode, CONFIG_SET back to poll mode so nothing is in flight, and STATUS_GET -> STATUS.
// Every request is retried after a timeout; losses are counted from seq gaps, never assumed. A SAMPLE with n_window
// 0 carries zeros that are no reading (docs/protocol.md §3.6): it is counted, not logged, as `record` does.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/receiver/row_assembler.hpp"
#include "driftlab/receiver/seq_tracker.hpp"
#include "driftlab/receiver/tick_unwrapper.hpp"
#include "sim/hil/board_key.hpp"
#include "sim/hil/hil_record.hpp"

namespace driftlab::sim {

/// What the host asks for.
struct HostPlan {
    proto::ConfigPayload config{};  ///< sent with CONFIG_SET
    double duration_s = 0.0;        ///< polls at k · period for k = 1 .. duration/period; listens until then
    double reply_timeout_s = 0.5;   ///< a request unanswered this long is sent again [s]
    int max_tries = 8;              ///< tries per request before the run fails
    /// The board's command key: CONFIG_SET carries its tag, each try a counter above VERSION's (docs/security.md).
    std::optional<BoardKey> key;
};

/// Counts of the host's side.
struct HostCounters {
    std::uint64_t frames_received = 0;  ///< valid frames decoded
    std::uint64_t frames_lost = 0;      ///< seq numbers never received (SeqTracker: a late frame is not lost)
    std::uint64_t polls_sent = 0;
    std::uint64_t samples_received = 0;  ///< SAMPLE frames received while running
    std::uint64_t empty_samples = 0;     ///< SAMPLEs with n_window 0 (no estimate behind a value): not logged
    std::uint64_t rows = 0;              ///< records handed to the sink
    std::uint64_t rows_missing_raw = 0;  ///< raw mode: SAMPLEs dropped because their RAW frame was lost
    std::uint64_t retries = 0;           ///< requests sent again after a timeout
    std::uint64_t last_seq = 0;          ///< the newest unwrapped seq received
};

class HostEndpoint {
public:
    enum class Phase { hello, config_set, config_get, running, stop_stream, status, done };

    /// Callback for the verified configuration (see HilOptions::on_ready).
    using ReadyFn = std::function<void(const proto::VersionPayload&, const proto::ConfigPayload&)>;

    HostEndpoint(const HostPlan& plan, RecordSink sink, ReadyFn on_ready = {});

    /// Time of the next thing the host does on its own (send, resend, poll) [s], or nothing.
    std::optional<double> next_action_s() const;
    /// Does what is due at `t_s`; appends frames to send (one frame per element) to `out`.
    void act(double t_s, std::vector<std::vector<std::uint8_t>>& out);
    /// Bytes from the link at `t_s`.
    void receive(double t_s, std::span<const std::uint8_t> bytes);

    Phase phase() const { return phase_; }
    bool done() const { return phase_ == Phase::done; }
    /// The host's counts, those of its seq tracker and row assembler included.
    HostCounters counters() const;
    const proto::DecoderCounters& decoder_counters() const { return decoder_.counters(); }
    /// VERSION and the final STATUS as received (valid once past their phases).
    const proto::VersionPayload& version() const { return version_; }
    const proto::StatusPayload& status() const { return status_; }

private:
    void handle_frame(double t_s);
    void request(double t_s, std::vector<std::vector<std::uint8_t>>& out);
    void enter(Phase next, double t_s);
    std::size_t encode_config_set(const proto::ConfigPayload& config, std::span<std::uint8_t> frame);
    double period_s() const { return plan_.config.output_period_ms / 1000.0; }

    HostPlan plan_;
    RecordSink sink_;
    ReadyFn on_ready_;
    proto::Decoder decoder_;
    Phase phase_ = Phase::hello;
    std::optional<double> send_at_s_ = 0.0;  // next (re)send of the current request
    int tries_ = 0;
    std::uint16_t tx_seq_ = 0;
    std::uint16_t request_seq_ = 0;
    std::uint32_t next_counter_ = 1;  // of the next authenticated command, from VERSION on
    std::uint64_t next_poll_k_ = 1;
    std::uint64_t poll_count_ = 0;
    double run_start_s_ = 0.0;  // configuration verified: polls at run_start + k · period
    double run_end_s_ = 0.0;
    receiver::SeqTracker seq_;
    receiver::TickUnwrapper ticks_;
    std::optional<receiver::RowAssembler> rows_;  // from the verified configuration on
    proto::VersionPayload version_{};
    proto::StatusPayload status_{};
    HostCounters counters_;
};

}  // namespace driftlab::sim
