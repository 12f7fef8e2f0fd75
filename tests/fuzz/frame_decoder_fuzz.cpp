// libFuzzer harness: the frame decoder (common/proto/decoder) on any byte stream. Beyond memory and UB errors it
// checks the decoder's promises: a delivered frame is of a known type and version, its length that type's, its CRC
// (with the type's seed) that of its bytes; and every byte fed ends up in a delivered frame, the resync count or the
// bytes held.
#include <cstddef>
#include <cstdint>

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"
#include "driftlab/proto/decoder.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

void check_frame(const driftlab::proto::Decoder& decoder) {
    using namespace driftlab::proto;
    MsgSpec spec{};
    DRIFTLAB_FUZZ_CHECK(find_spec(decoder.type_id(), &spec));
    DRIFTLAB_FUZZ_CHECK(decoder.payload_len() == spec.payload_len);
    const std::uint8_t* f = decoder.frame();
    DRIFTLAB_FUZZ_CHECK(f[kOffsetSync0] == kSync0 && f[kOffsetSync1] == kSync1);
    // Version 2, or a version-1 HELLO (the one v1 frame a v2 decoder takes, docs/protocol.md §1.1).
    DRIFTLAB_FUZZ_CHECK(f[kOffsetVersion] == kProtocolVersion ||
                        (f[kOffsetVersion] == kLegacyProtocolVersion && decoder.type() == MsgType::hello));
    DRIFTLAB_FUZZ_CHECK(decoder.version() == f[kOffsetVersion]);
    const std::size_t crc_at = decoder.frame_size() - kCrcSize;
    std::uint16_t crc = crc16_ibm3740(f + kCrcStart, crc_at - kCrcStart);
    crc = crc16_ibm3740_update(crc, spec.crc_seed);
    DRIFTLAB_FUZZ_CHECK(crc == get_u16_le(f + crc_at));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    driftlab::proto::Decoder decoder;
    std::uint64_t delivered_bytes = 0;
    std::uint64_t delivered_frames = 0;
    for (std::size_t i = 0; i < size; ++i) {
        if (!decoder.feed(data[i])) continue;
        do {
            check_frame(decoder);
            delivered_bytes += decoder.frame_size();
            ++delivered_frames;
        } while (decoder.next());
    }
    const driftlab::proto::DecoderCounters& c = decoder.counters();
    DRIFTLAB_FUZZ_CHECK(c.frames_ok == delivered_frames);
    DRIFTLAB_FUZZ_CHECK(delivered_bytes + c.resync_bytes + decoder.bytes_held() == size);
    return 0;
}
