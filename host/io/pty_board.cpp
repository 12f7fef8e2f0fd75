// PtyBoard serve loop (pty_board.hpp).
#include "host/io/pty_board.hpp"

#include <cstring>
#include <memory>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/receiver/row_assembler.hpp"
#include "driftlab/receiver/seq_tracker.hpp"
#include "driftlab/receiver/tick_unwrapper.hpp"
#include "firmware/core/firmware.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/port/native/native_board.hpp"
#include "host/io/board_rows.hpp"
#include "host/io/pty_bridge.hpp"
#include "host/log/log_writer.hpp"

namespace driftlab::host::io {
namespace {

constexpr int kReadWaitMs = 1;

// Decodes the firmware's own output and writes its SAMPLEs as the receiver makes them rows: the ground truth of what
// was sent.
class TruthLog {
public:
    explicit TruthLog(const std::string& path)
        : rows_({static_cast<std::uint32_t>(fw::kTickHz), false, receiver::MissingRaw::mark},
                [this](const receiver::Row& r) { return write(r); }) {
        if (path.empty()) return;
        LogMetadata m;
        m.set("source", std::string("pty-board-truth"));
        m.set("tick_hz", static_cast<std::int64_t>(fw::kTickHz));
        writer_ = std::make_unique<LogWriter>(path, m, board_columns(false, false));
    }
    void feed(const std::uint8_t* bytes, std::size_t n, PtyBoardSummary& summary) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!decoder_.feed(bytes[i])) continue;
            do {
                ++summary.frames_sent;
                const std::uint64_t seq = seq_.accept(decoder_.seq()).unwrapped;
                proto::SamplePayload s{};
                if (decoder_.type() != proto::MsgType::sample ||
                    !proto::parse(decoder_.payload(), decoder_.payload_len(), &s)) {
                    continue;
                }
                ++summary.samples_sent;
                rows_.sample(s, seq, ticks_.unwrap(s.tick));
            } while (decoder_.next());
        }
    }
    void close() {
        if (writer_) writer_->close();
    }

private:
    bool write(const receiver::Row& r) {
        if (writer_) writer_->write_row(board_log_row(r, false, false));
        return true;
    }

    std::unique_ptr<LogWriter> writer_;
    proto::Decoder decoder_;
    receiver::SeqTracker seq_;
    receiver::TickUnwrapper ticks_;
    receiver::RowAssembler rows_;
};

}  // namespace

PtyBoardSummary serve_pty_board(const PtyBoardOptions& options, const CodeSource& source, const std::atomic<bool>& stop,
                                const std::function<void(const std::string&)>& on_ready) {
    PtyBoardSummary summary;
    fw::NativeBoard board;
    board.load_eeprom(options.eeprom.data(), options.eeprom.size());
    fw::Firmware firmware;
    firmware.start();
    TruthLog truth(options.truth_log);
    PtyBridge bridge(options.link_path);
    if (on_ready) on_ready(bridge.client_path());
    const WallClockPacer pacer(options.speed);
    std::size_t next_unplug = 0;

    std::uint8_t buf[4096];
    while (!stop.load()) {
        double t_s = pacer.virtual_now_s();
        if (options.duration_s > 0.0 && t_s >= options.duration_s) t_s = options.duration_s;
        const auto t_ticks = static_cast<std::uint64_t>(t_s * fw::kTickHz);
        board.advance_to(t_ticks, firmware, [&](Channel c, std::uint64_t tick) { return source(c, tick); });
        for (std::size_t n; (n = board.transmit(buf, sizeof buf)) > 0;) {
            truth.feed(buf, n, summary);
            bridge.write(buf, n);
        }
        if (next_unplug < options.unplugs.size()) {
            const PlannedUnplug& u = options.unplugs[next_unplug];
            if (bridge.plugged() && t_s >= u.at_s && t_s < u.at_s + u.for_s) {
                bridge.unplug();
            } else if (!bridge.plugged() && t_s >= u.at_s + u.for_s) {
                bridge.plug();
                ++next_unplug;
                if (on_ready) on_ready(bridge.client_path());
            }
        }
        if (options.duration_s > 0.0 && t_s >= options.duration_s) break;
        const std::size_t n = bridge.read(buf, sizeof buf, kReadWaitMs);
        if (n > 0) {
            static_cast<void>(board.receive(buf, n));
            board.service(firmware);
        }
    }
    truth.close();
    summary.virtual_s = pacer.virtual_now_s();
    summary.bytes_dropped = bridge.dropped_bytes();
    return summary;
}

}  // namespace driftlab::host::io
