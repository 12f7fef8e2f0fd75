// Throughput of the protocol v1 codec on the host: frames encoded and decoded per second, clean and damaged
// streams, and the CRC alone. Prints figures; never passes or fails on time.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include "driftlab/proto/crc16.hpp"
#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/encoder.hpp"

namespace {

using namespace driftlab::proto;

constexpr size_t kFramesPerStream = 1000;

std::vector<uint8_t> sample_stream() {
    std::mt19937 rng(1);
    std::vector<uint8_t> out;
    for (size_t i = 0; i < kFramesPerStream; ++i) {
        SamplePayload p{};
        p.tick = static_cast<uint32_t>(i * 1000u);
        for (auto& v : p.value_q8) {
            v = static_cast<int32_t>(rng() % (1024u * 256u));
        }
        uint8_t frame[kMaxFrameSize];
        const size_t n = encode_sample(p, static_cast<uint16_t>(i), frame, sizeof(frame));
        out.insert(out.end(), frame, frame + n);
    }
    return out;
}

std::vector<uint8_t> mixed_stream() {
    std::mt19937 rng(2);
    std::vector<uint8_t> out;
    for (size_t i = 0; i < kFramesPerStream; ++i) {
        const MsgInfo& info = kMsgTable[rng() % kMsgTypeCount];
        uint8_t payload[kMaxPayload];
        for (auto& b : payload) {
            b = static_cast<uint8_t>(rng());
        }
        uint8_t frame[kMaxFrameSize];
        const size_t n =
            encode_frame(type_id(info.type), static_cast<uint16_t>(i), payload, info.payload_len, frame, sizeof(frame));
        out.insert(out.end(), frame, frame + n);
    }
    return out;
}

// One random byte in 200 replaced: roughly one SAMPLE frame in six is damaged, the rest must be re-found.
std::vector<uint8_t> damaged(std::vector<uint8_t> stream) {
    std::mt19937 rng(3);
    for (auto& b : stream) {
        if (rng() % 200 == 0) {
            b = static_cast<uint8_t>(rng());
        }
    }
    return stream;
}

void decode(benchmark::State& state, const std::vector<uint8_t>& stream) {
    int64_t frames = 0;
    for (auto _ : state) {
        Decoder dec;
        for (uint8_t b : stream) {
            if (dec.feed(b)) {
                do {
                    benchmark::DoNotOptimize(dec.payload());
                    ++frames;
                } while (dec.next());
            }
        }
    }
    state.SetItemsProcessed(frames);
    state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(stream.size()));
}

void BM_DecodeSampleFrames(benchmark::State& state) { decode(state, sample_stream()); }
void BM_DecodeMixedFrames(benchmark::State& state) { decode(state, mixed_stream()); }
void BM_DecodeDamagedSampleFrames(benchmark::State& state) { decode(state, damaged(sample_stream())); }

void BM_EncodeSampleFrame(benchmark::State& state) {
    SamplePayload p{};
    p.value_q8[0] = 512 * 256;
    uint8_t frame[kMaxFrameSize];
    uint16_t seq = 0;
    for (auto _ : state) {
        p.tick += 1000;
        benchmark::DoNotOptimize(encode_sample(p, seq++, frame, sizeof(frame)));
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_Crc16Ibm3740(benchmark::State& state) {
    std::vector<uint8_t> data(static_cast<size_t>(state.range(0)), 0x5A);
    for (auto _ : state) {
        benchmark::DoNotOptimize(crc16_ibm3740(data.data(), data.size()));
    }
    state.SetBytesProcessed(state.iterations() * state.range(0));
}

BENCHMARK(BM_DecodeSampleFrames);
BENCHMARK(BM_DecodeMixedFrames);
BENCHMARK(BM_DecodeDamagedSampleFrames);
BENCHMARK(BM_EncodeSampleFrame);
BENCHMARK(BM_Crc16Ibm3740)->Arg(31)->Arg(4096);

}  // namespace
