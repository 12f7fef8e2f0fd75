// HilRecord: one row of the canonical log as the host-in-the-loop produces it (docs/log-format.md): the one
// receiver's row (driftlab/receiver/row_assembler.hpp).
#pragma once

#include <functional>

#include "driftlab/receiver/row_assembler.hpp"

namespace driftlab::sim {

using HilRecord = receiver::Row;

/// Receives each record as soon as the host has it complete (in time order).
using RecordSink = std::function<void(const HilRecord&)>;

}  // namespace driftlab::sim
