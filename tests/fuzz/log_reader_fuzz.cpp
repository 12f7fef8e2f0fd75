// libFuzzer harness: the canonical log reader (host/log/log_reader) on any text. A file it refuses must be refused
// with a DataError (a named line); one it takes must hold what docs/log-format.md promises of a log read.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "host/log/log_reader.hpp"
#include "host/util/error.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

void check_log(const driftlab::host::LogData& log) {
    DRIFTLAB_FUZZ_CHECK(log.size() > 0);
    DRIFTLAB_FUZZ_CHECK(log.seq.size() == log.size());
    for (const auto& channel : log.counts) {
        DRIFTLAB_FUZZ_CHECK(channel.size() == log.size());
        for (const double v : channel) DRIFTLAB_FUZZ_CHECK(std::isfinite(v));
    }
    for (const auto& [name, column] : log.optional_columns) DRIFTLAB_FUZZ_CHECK(column.size() == log.size());
    for (std::size_t i = 0; i < log.size(); ++i) {
        DRIFTLAB_FUZZ_CHECK(std::isfinite(log.t_s[i]));
        if (i > 0) DRIFTLAB_FUZZ_CHECK(log.t_s[i] > log.t_s[i - 1]);
    }
    for (const auto& gap : log.gaps) DRIFTLAB_FUZZ_CHECK(gap.before_row <= log.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // As the commands read: strict, and with --drop-cut-line and a converter assumed where the log names none.
    driftlab::host::ReadOptions lenient;
    lenient.drop_truncated_tail = true;
    lenient.assumed_adc_bits = 10;
    for (const auto& options : {driftlab::host::ReadOptions{}, lenient}) {
        std::istringstream in(text);
        try {
            check_log(driftlab::host::parse_log(in, "fuzz.csv", options));
        } catch (const driftlab::host::DataError&) {
            // a refusal naming its line: what the reader promises for bad input
        }
    }
    return 0;
}
