// libFuzzer harness: the plain numeric table reader (host/log/numeric_table) on any text. A table it takes has
// columns of one length, each a finite number, and a file line for every row.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "host/log/numeric_table.hpp"
#include "host/util/error.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const driftlab::host::NumericTable table = driftlab::host::parse_numeric_table(in, "fuzz.txt");
        DRIFTLAB_FUZZ_CHECK(table.names.size() == table.columns.size());
        DRIFTLAB_FUZZ_CHECK(table.row_lines.size() == table.rows());
        for (const auto& column : table.columns) {
            DRIFTLAB_FUZZ_CHECK(column.size() == table.rows());
            for (const double v : column) DRIFTLAB_FUZZ_CHECK(std::isfinite(v));
        }
    } catch (const driftlab::host::DataError&) {
        // a refusal naming its line
    }
    return 0;
}
