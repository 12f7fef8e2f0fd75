// What the fuzz harnesses share: a property check that stops the fuzzer with the failed condition (libFuzzer then
// writes the input that broke it as a crash artifact), whatever NDEBUG says.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#define DRIFTLAB_FUZZ_CHECK(cond)                                                            \
    do {                                                                                     \
        if (!(cond)) {                                                                       \
            std::fprintf(stderr, "%s:%d: property failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                                    \
        }                                                                                    \
    } while (0)

namespace driftlab::fuzz {

/// A file holding `data` that the readers can open by path (an in-memory file: nothing on the disk), valid until the
/// next call.
std::string as_file(const std::uint8_t* data, std::size_t size);

}  // namespace driftlab::fuzz
