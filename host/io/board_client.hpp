// BoardClient: the host side of protocol v2 over any ByteLink (docs/protocol.md, docs/recording.md).
// Handshake (HELLO -> VERSION, refusing another protocol version), configuration (CONFIG_SET answered by
// ACK, then verified by reading it back with CONFIG_GET), STATUS_GET, POLL, and reception of streamed frames
// with sequence accounting (SeqTracker).
//
// How to use:
//   BoardClient client(link);
//   client.set_tap([&](CaptureKind k, const uint8_t* p, size_t n) { capture.write(k, p, n); });
//   client.set_frame_handler([&](const Frame& f) { ... every frame, in order ... });
//   auto v = client.hello();          if (!v.ok) -> v.problem says why
//   auto c = client.configure(cfg);   if (!c.ok) -> c.problem says why
//   loop { client.send_poll(); client.pump(timeout_ms); }   // or only pump() in stream mode
// A LinkStatus::lost from send_poll()/pump() means the device went away: reopen the link, call
// forget_partial_frame(), and do the handshake again. Nothing here throws.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/receiver/seq_tracker.hpp"
#include "host/io/byte_link.hpp"
#include "host/io/capture.hpp"
#include "host/io/key_file.hpp"

namespace driftlab::host::io {

/// One decoded frame, copied out of the decoder.
struct Frame {
    proto::MsgType type = proto::MsgType::hello;
    std::uint16_t seq = 0;
    std::uint8_t payload_len = 0;
    std::array<std::uint8_t, proto::kMaxPayload> payload{};
};

/// The frame `decoder` has just completed (valid until its next feed()/next()), copied out.
Frame copy_frame(const proto::Decoder& decoder);

struct ClientOptions {
    int reply_timeout_ms = 500;  ///< [ms] wait for one answer
    int hello_attempts = 6;      ///< an Arduino resets when the port opens; its bootloader needs ~2 s
    int request_attempts = 3;    ///< CONFIG_SET/CONFIG_GET/STATUS_GET tries
};

struct HelloResult {
    bool ok = false;
    std::string problem;  ///< why not, in words for the user
    proto::VersionPayload version{};
};

struct ConfigResult {
    bool ok = false;
    std::string problem;
    proto::ConfigPayload applied{};  ///< as read back with CONFIG_GET
};

/// Link-level counts for the status line and the bench.
struct ClientCounters {
    std::uint64_t bytes_received = 0;
    std::uint64_t naks = 0;
    std::uint64_t polls_sent = 0;
};

class BoardClient {
public:
    using Tap = std::function<void(CaptureKind, const std::uint8_t*, std::size_t)>;
    using FrameHandler = std::function<void(const Frame&)>;

    explicit BoardClient(ByteLink& link, ClientOptions options = {});

    /// Sees every byte sent ('T') and received ('R') before anything else does (the capture).
    void set_tap(Tap tap) { tap_ = std::move(tap); }
    /// Sees every valid frame received, in order, duplicates included.
    void set_frame_handler(FrameHandler handler) { handler_ = std::move(handler); }

    /// The board's command key (docs/security.md): CONFIG_SET and CAL_SET then carry its tag, and key_change() is
    /// possible. Without one a keyed board's commands are refused here, before anything is sent.
    void set_key(const CommandKey& key) { key_ = key; }

    /// HELLO; VERSION also says whether the board wants authenticated commands and the counter they continue from.
    HelloResult hello();
    /// CONFIG_SET `wanted`, expect ACK, then CONFIG_GET and compare field by field.
    ConfigResult configure(const proto::ConfigPayload& wanted);
    std::optional<proto::StatusPayload> status();

    /// The answer to one request: the reply, a NAK of the request, or (neither) why none came.
    struct Answer {
        std::optional<Frame> reply;
        std::optional<proto::NakPayload> nak;
        std::string problem;
    };
    /// Sends `type` with `payload` up to request_attempts times until a frame of type `reply` (an ACK: of this
    /// request's seq) or a NAK of the request arrives. An authenticated type (CONFIG_SET, CAL_SET) gets its trailer
    /// with a new counter each try (after hello()); a refusal of its authentication is a `problem` in words, not a nak.
    Answer request(proto::MsgType type, std::span<const std::uint8_t> payload, proto::MsgType reply);

    /// KEY_SET: the board takes `next` as its key (sealed under the current one), and so does this client. Returns
    /// why not, "" when ACKed.
    std::string key_change(const CommandKey& next);

    LinkStatus send_poll();
    /// Reads what arrives within `timeout_ms` [ms] and delivers its frames.
    LinkStatus pump(int timeout_ms);
    /// Why the board refused a POLL (a NAK to one has arrived), in words for the user; none while every POLL is
    /// answered. A board in stream mode refuses them all (docs/protocol.md §3.5).
    std::optional<std::string> poll_refusal() const;

    /// Drops a frame cut by a reconnect, so its start cannot join bytes of the new connection.
    void forget_partial_frame() { decoder_.reset(); }

    const receiver::SeqTracker& sequence() const { return seq_; }
    receiver::SeqTracker& sequence() { return seq_; }
    const proto::DecoderCounters& decoder_counters() const { return decoder_.counters(); }
    const ClientCounters& counters() const { return counters_; }

private:
    LinkStatus send(proto::MsgType type, std::span<const std::uint8_t> payload, std::uint16_t* seq_used);
    /// Whether `f` answers request `type` of `seq`: a NAK of it, an ACK of it when `reply` is ACK, else a `reply`.
    static bool answers(const Frame& f, proto::MsgType type, std::uint16_t seq, proto::MsgType reply);
    // Pumps until `match` accepts a frame or the timeout passes; the frame is returned.
    std::optional<Frame> await(const std::function<bool(const Frame&)>& match, int timeout_ms, LinkStatus* status);
    void deliver(const Frame& frame);
    /// A version-1 HELLO, and what comes back within the reply timeout (a v1 board's VERSION names its version).
    void probe_version_one();

    ByteLink& link_;
    ClientOptions options_;
    Tap tap_;
    FrameHandler handler_;
    proto::Decoder decoder_;
    receiver::SeqTracker seq_;
    ClientCounters counters_;
    std::uint16_t tx_seq_ = 0;
    std::function<bool(const Frame&)> waiting_for_;
    std::optional<Frame> awaited_;
    // The version byte after the last sync pair seen, to name the version of a board that speaks another one.
    std::uint8_t sync_state_ = 0;
    std::optional<std::uint8_t> foreign_version_;
    std::optional<proto::NakPayload> poll_nak_;  // the latest NAK of a POLL
    // Authentication: the key given, and from VERSION the board's state and the next counter to use.
    std::optional<CommandKey> key_;
    std::uint8_t auth_state_ = 0;
    std::uint32_t next_counter_ = 1;
    /// Why an authenticated `type` cannot be sent (a keyed board and no key, a damaged key), "" when it can.
    std::string auth_obstacle(const char* name) const;
    /// A NAK `status` of `name` that refuses its authentication, in words; "" for any other status.
    std::string auth_refusal(const char* name, std::uint8_t status) const;
};

/// "out_of_range" and friends, for messages.
const char* status_name(std::uint8_t status);

}  // namespace driftlab::host::io
