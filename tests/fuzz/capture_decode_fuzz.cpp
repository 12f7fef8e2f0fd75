// libFuzzer harness: a capture file (host/io/capture) decoded through the log assembler (host/io/log_assembler), as
// `driftlab decode` does. A capture it cannot read is refused with a DataError; a log it writes must be one the log
// reader takes whole (never a silent wrong row: a row the reader would refuse is a row the assembler let through).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "host/io/capture.hpp"
#include "host/io/log_assembler.hpp"
#include "host/log/log_reader.hpp"
#include "host/util/error.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

/// Where the assembler writes: a file of this process in memory (/dev/shm), replaced by every input.
const std::string& log_path() {
    static const std::string path = "/dev/shm/driftlab-fuzz-" + std::to_string(::getpid()) + ".csv";
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace driftlab::host;
    std::uint64_t rows = 0;
    try {
        io::CaptureReader reader(driftlab::fuzz::as_file(data, size));
        io::LogAssembler assembler(log_path(), reader.header());
        while (auto rec = reader.next()) {
            if (rec->kind == io::CaptureKind::rx)
                assembler.on_rx(rec->t_us, rec->payload.data(), rec->payload.size());
            else if (rec->kind == io::CaptureKind::event)
                assembler.on_event(rec->t_us, rec->text());
        }
        if (!assembler.started()) return 0;
        assembler.finish();
        rows = assembler.stats().rows;
    } catch (const DataError&) {
        return 0;  // not a capture, or one the assembler refuses with its reason
    }
    if (rows == 0) return 0;  // the reader refuses a log without rows, as documented
    try {
        DRIFTLAB_FUZZ_CHECK(read_log(log_path()).size() == rows);
    } catch (const DataError& e) {
        std::fprintf(stderr, "the assembler wrote a log the reader refuses: %s\n", e.what());
        std::abort();
    }
    return 0;
}
