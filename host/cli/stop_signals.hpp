// Ctrl-C and SIGTERM end a long run between its steps, so that its output keeps every row whole (a kill mid-write had
// cut the last one) and its summary says how far it got: `record` and `hil` alike.
#pragma once

#include <atomic>

namespace driftlab::host::cli {

/// Installs the handlers (once is enough; again is harmless) and returns the flag they set.
const std::atomic<bool>& stop_on_signals();

}  // namespace driftlab::host::cli
