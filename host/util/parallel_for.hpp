// Independent jobs on a few threads: the replicate pool, gap-eval's logs and a step's candidate fits share it.
#pragma once

#include <cstddef>
#include <functional>

namespace driftlab::host {

/// Calls `body(i)` once for each i in [0, count) on `threads` threads (the caller's among them), handing out the
/// next index to whichever thread is free. Returns when all are done; rethrows the first exception any call threw
/// (the remaining indices are still run, so no thread is left behind).
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

}  // namespace driftlab::host
