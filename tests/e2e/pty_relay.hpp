// PtyRelay: a second program on the line between a board's pseudo-terminal and the recorder, as another transmitter
// on the board's radio channel would be. Every byte passes unchanged both ways; after each whole frame from the board
// the test's injector decides what else goes on the line: frames to the host (a forged CONFIG, VERSION or SAMPLE)
// and frames to the board (a forged CONFIG_SET). docs/security.md names the tests that use it.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "driftlab/proto/decoder.hpp"
#include "host/io/pty_bridge.hpp"

namespace driftlab::e2e {

/// What an injector puts on the line after a board frame: bytes to the host, bytes to the board.
struct Injection {
    std::vector<std::uint8_t> to_host;
    std::vector<std::uint8_t> to_board;
};

/// Called with the decoder holding each whole frame the board sent (type(), seq(), payload()).
using Injector = std::function<Injection(const proto::Decoder& board_frame)>;

/// One frame of `type` and `seq` around `payload`, as a board or host would send it.
template <typename Payload>
std::vector<std::uint8_t> frame_of(proto::MsgType type, std::uint16_t seq, const Payload& payload);

class PtyRelay {
public:
    /// Opens the board's terminal at `board_path` and serves the recorder's on a new pseudo-terminal (path()).
    PtyRelay(const std::string& board_path, Injector injector);
    ~PtyRelay();
    PtyRelay(const PtyRelay&) = delete;
    PtyRelay& operator=(const PtyRelay&) = delete;

    /// The terminal the recorder opens.
    std::string path() const { return client_.client_path(); }
    /// Frames injected so far toward the host and toward the board.
    int injected_to_host() const { return to_host_.load(); }
    int injected_to_board() const { return to_board_.load(); }

private:
    void run();
    void relay_board_bytes(const std::uint8_t* bytes, std::size_t n);

    int board_fd_ = -1;
    host::io::PtyBridge client_;
    Injector injector_;
    proto::Decoder decoder_;
    std::atomic<bool> stop_{false};
    std::atomic<int> to_host_{0}, to_board_{0};
    std::thread thread_;
};

}  // namespace driftlab::e2e
