// Frames to log rows; see row_assembler.hpp.
#include "driftlab/receiver/row_assembler.hpp"

#include <utility>

#include "driftlab/proto/q8_counts.hpp"

namespace driftlab::receiver {

RowAssembler::RowAssembler(const RowOptions& options, Sink sink) : options_(options), sink_(std::move(sink)) {}

void RowAssembler::sample(const proto::SamplePayload& sample, std::uint64_t seq, std::uint64_t tick) {
    ++counts_.samples;
    if (waiting_) without_raw(*waiting_);
    waiting_.reset();
    // An empty window's 0 is no reading (a POLL before any conversion, or right after CONFIG restarted the
    // windows): a row of it would read as 0 counts.
    if (sample.n_window == 0) {
        ++counts_.empty_samples;
        return;
    }
    Row row;
    row.tick = tick;
    row.t_s = static_cast<double>(tick) / static_cast<double>(options_.tick_hz);
    row.seq = seq;
    for (std::size_t c = 0; c < kChannelCount; ++c) row.value_counts[c] = proto::q8_to_counts(sample.value_q8[c]);
    row.sat_flags = sample.sat_flags;
    row.n_window = sample.n_window;
    row.temp_code = sample.temp_code;
    row.dropped = sample.dropped;
    if (!options_.raw) {
        emit(row);
        return;
    }
    waiting_ = row;
    waiting_tick32_ = sample.tick;
}

void RowAssembler::raw(const proto::RawPayload& raw) {
    // A RAW belongs to the SAMPLE of its tick, sent just before it; a lone RAW whose SAMPLE was lost is dropped.
    if (!waiting_ || waiting_tick32_ != raw.tick) return;
    Row row = *waiting_;
    waiting_.reset();
    row.has_raw = true;
    for (std::size_t c = 0; c < kChannelCount; ++c) row.raw_counts[c] = raw.code[c];
    emit(row);
}

void RowAssembler::end_of_stream() {
    if (waiting_) without_raw(*waiting_);
    waiting_.reset();
}

void RowAssembler::without_raw(const Row& row) {
    if (options_.missing_raw == MissingRaw::drop) {
        ++counts_.dropped_rows;
        return;
    }
    emit(row);
}

void RowAssembler::emit(const Row& row) {
    if (last_t_s_ && row.t_s <= *last_t_s_) {
        ++counts_.stale_samples;
        return;
    }
    if (sink_(row)) last_t_s_ = row.t_s;
}

}  // namespace driftlab::receiver
