// How the driftlab command's threads share the heap.
#pragma once

namespace driftlab::host {

/// Makes every thread allocate from the one heap (glibc's M_ARENA_MAX = 1; elsewhere nothing). The analyses make
/// series-sized vectors (megabytes per hour of log) on their worker threads, and glibc gives each thread an arena of
/// its own that keeps what was freed in it for that arena alone: gap on an hour's log held 377 MB resident for a heap
/// that never exceeded 249 MB. Allocations are few next to the arithmetic, so one heap costs no time
/// (docs/performance.md). Call it first, before any thread starts.
void share_one_heap();

}  // namespace driftlab::host
