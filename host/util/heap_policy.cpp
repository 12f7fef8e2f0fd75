// One heap for every thread; see heap_policy.hpp.
#include "host/util/heap_policy.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace driftlab::host {

void share_one_heap() {
#if defined(__GLIBC__)
    mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace driftlab::host
