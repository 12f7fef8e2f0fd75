// AvrTarget; see avr_target.hpp.
#include "sim/avr/avr_target.hpp"

#include <algorithm>

#include "driftlab/proto/wire.hpp"
#include "firmware/core/hal.hpp"
#include "sim/avr/avr_error.hpp"
#include "sim/avr/simavr_adc.hpp"

namespace driftlab::sim::avr {
namespace {

constexpr double kTickHz = static_cast<double>(fw::kTickHz);
// From a trigger to the converted sample in the firmware's ring: 13.5 ADC clocks of 128 cycles, then the ADC
// vector; rounded up to 2048 cycles (128 us).
constexpr std::uint64_t kConversionCycles = 2048;

}  // namespace

AvrTarget::AvrTarget(const AvrBoardOptions& options)
    : board_(options, [this](Channel c, std::uint64_t tick) {
          if (source_ == nullptr) {
              throw AvrError("the AVR firmware converted outside advance_to()");
          }
          return millivolts_for_code(source_->code(c, static_cast<double>(tick) / kTickHz));
      }) {
    board_.run_until_armed();
    epoch_cycle_ = *board_.firmware_epoch_cycle();
}

double AvrTarget::s_of_cycle(std::uint64_t cycle) const {
    return static_cast<double>(cycle - std::min(cycle, epoch_cycle_)) / AvrBoard::kCpuHz;
}

double AvrTarget::time_s() const { return s_of_cycle(board_.cycle()); }

std::optional<double> AvrTarget::next_conversion_s() const {
    const double done_s = static_cast<double>(board_.next_trigger_tick()) / kTickHz +
                          static_cast<double>(kConversionCycles) / AvrBoard::kCpuHz;
    // Past already (the vector of a trigger that just happened has not run): ask for the next step instead.
    return std::max(done_s, time_s() + 1.0 / kTickHz);
}

void AvrTarget::advance_to(double t_s, ConversionSource& source, std::vector<TxChunk>& tx) {
    source_ = &source;
    board_.run_until_cycle(epoch_cycle_ + AvrBoard::cycles_for_s(t_s));
    source_ = nullptr;
    gather_frames(tx);
}

void AvrTarget::receive(std::span<const std::uint8_t> bytes, std::vector<TxChunk>& tx) {
    // The firmware answers later, while advance_to() runs it.
    board_.receive(bytes.data(), bytes.size());
    static_cast<void>(tx);
}

void AvrTarget::gather_frames(std::vector<TxChunk>& tx) {
    const std::vector<UartTxByte> sent = board_.transmit_timed();
    partial_.insert(partial_.end(), sent.begin(), sent.end());
    std::size_t i = 0;
    while (i < partial_.size()) {
        std::size_t size = 1;  // a byte outside any frame goes on its own
        if (partial_[i].value == proto::kSync0) {
            if (partial_.size() - i <= proto::kOffsetLen) {
                break;  // header still coming
            }
            if (partial_[i + 1].value == proto::kSync1) {
                size = proto::frame_size(partial_[i + proto::kOffsetLen].value);
                if (partial_.size() - i < size) {
                    break;  // rest of the frame still coming
                }
            }
        }
        TxChunk chunk{s_of_cycle(partial_[i].cycle), {}};
        for (std::size_t k = 0; k < size; ++k) {
            chunk.bytes.push_back(partial_[i + k].value);
        }
        tx.push_back(std::move(chunk));
        i += size;
    }
    partial_.erase(partial_.begin(), partial_.begin() + static_cast<std::ptrdiff_t>(i));
}

}  // namespace driftlab::sim::avr
