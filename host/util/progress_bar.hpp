// A progress bar with the time left, for a run whose share done is known (an AVR run in simavr can take minutes).
#pragma once

#include <functional>

namespace driftlab::host {

/// A callback that redraws "[####    ]  40%  about 2 min left" on the error output for the share done it is given,
/// ending the line at 1.
std::function<void(double)> progress_bar();

}  // namespace driftlab::host
