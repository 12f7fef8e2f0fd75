// PtyRelay (pty_relay.hpp): a thread copying bytes between the board's terminal and the recorder's.
#include "tests/e2e/pty_relay.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/messages.hpp"

namespace driftlab::e2e {

template <typename Payload>
std::vector<std::uint8_t> frame_of(proto::MsgType type, std::uint16_t seq, const Payload& payload) {
    std::uint8_t body[proto::kMaxPayload];
    const std::size_t len = proto::serialize(payload, body, sizeof body);
    std::vector<std::uint8_t> frame(proto::kMaxFrameSize);
    // A command that changes the board goes out as a transmitter without the key sends it: a zero tag, counter 1.
    const std::uint8_t id = proto::type_id(type);
    frame.resize(proto::is_authenticated(id)
                     ? proto::encode_authenticated(id, seq, body, len, {nullptr, 1}, frame.data(), frame.size())
                     : proto::encode_frame(id, seq, body, len, frame.data(), frame.size()));
    if (len == 0 || frame.empty()) throw std::logic_error("frame_of: payload does not fit its type");
    return frame;
}
template std::vector<std::uint8_t> frame_of(proto::MsgType, std::uint16_t, const proto::VersionPayload&);
template std::vector<std::uint8_t> frame_of(proto::MsgType, std::uint16_t, const proto::ConfigPayload&);
template std::vector<std::uint8_t> frame_of(proto::MsgType, std::uint16_t, const proto::SamplePayload&);

namespace {

void write_all(int fd, const std::uint8_t* bytes, std::size_t n) {
    while (n > 0) {
        const ssize_t w = ::write(fd, bytes, n);
        if (w < 0 && errno == EINTR) continue;
        if (w < 0) {
            if (errno != EAGAIN) return;  // the recorder has gone: nobody left to deceive
            ::usleep(1000);
            continue;
        }
        bytes += w;
        n -= static_cast<std::size_t>(w);
    }
}

}  // namespace

PtyRelay::PtyRelay(const std::string& board_path, Injector injector) : injector_(std::move(injector)) {
    board_fd_ = ::open(board_path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (board_fd_ < 0) throw std::runtime_error(board_path + ": " + std::strerror(errno));
    termios tio{};
    ::tcgetattr(board_fd_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(board_fd_, TCSANOW, &tio);
    thread_ = std::thread([this] { run(); });
}

PtyRelay::~PtyRelay() {
    stop_ = true;
    thread_.join();
    ::close(board_fd_);
}

void PtyRelay::relay_board_bytes(const std::uint8_t* bytes, std::size_t n) {
    std::size_t sent = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!decoder_.feed(bytes[i])) continue;
        // The frame goes on first, whole; what the injector adds follows it, so no real frame is cut.
        client_.write(bytes + sent, i + 1 - sent);
        sent = i + 1;
        do {
            const Injection more = injector_(decoder_);
            if (!more.to_host.empty()) client_.write(more.to_host.data(), more.to_host.size()), ++to_host_;
            if (!more.to_board.empty()) write_all(board_fd_, more.to_board.data(), more.to_board.size()), ++to_board_;
        } while (decoder_.next());
    }
    client_.write(bytes + sent, n - sent);
}

void PtyRelay::run() {
    std::uint8_t buf[4096];
    while (!stop_) {
        pollfd p{board_fd_, POLLIN, 0};
        if (::poll(&p, 1, 1) > 0 && (p.revents & POLLIN)) {
            const ssize_t n = ::read(board_fd_, buf, sizeof buf);
            if (n > 0) relay_board_bytes(buf, static_cast<std::size_t>(n));
        }
        const std::size_t n = client_.read(buf, sizeof buf, 0);
        if (n > 0) write_all(board_fd_, buf, n);
    }
}

}  // namespace driftlab::e2e
