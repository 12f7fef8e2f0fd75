// driftlab::fuzz::as_file: one memfd per process, rewritten for every input, opened by its /proc path.
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "tests/fuzz/fuzz_check.hpp"

namespace driftlab::fuzz {

std::string as_file(const std::uint8_t* data, std::size_t size) {
    static const int fd = memfd_create("driftlab-fuzz-input", 0);
    DRIFTLAB_FUZZ_CHECK(fd >= 0);
    DRIFTLAB_FUZZ_CHECK(ftruncate(fd, 0) == 0);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = pwrite(fd, data + done, size - done, static_cast<off_t>(done));
        DRIFTLAB_FUZZ_CHECK(n > 0);
        done += static_cast<std::size_t>(n);
    }
    return "/proc/self/fd/" + std::to_string(fd);
}

}  // namespace driftlab::fuzz
