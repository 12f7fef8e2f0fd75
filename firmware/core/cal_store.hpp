// CalStore: the calibration in EEPROM, one entry per channel (a CAL payload and its CRC), checked when read: an
// erased, damaged or incomplete set leaves the outputs as measured and says why (proto::CalState). Layout and
// rules: docs/protocol.md §3.12, docs/firmware.md "Drift compensation".
#pragma once

#include <stdint.h>

#include "driftlab/channels.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/nodiscard.hpp"
#include "driftlab/proto/status.hpp"
#include "firmware/core/cal_entry.hpp"
#include "firmware/core/drift_comp.hpp"

namespace driftlab {
namespace fw {

/// Result of validate(): Status::ok, or out_of_range and the proto::CalField of the first offending field.
struct CalCheck {
  proto::Status status;
  uint8_t field;
};

/// CAL_SET's ranges: the channel and flags always; C1, C2 and T unless cal_id is 0 (an entry cleared).
DRIFTLAB_NODISCARD CalCheck validate(const proto::CalPayload& payload);

/// Writes `payload` as the entry of its channel (validated), with its CRC.
void store_entry(const proto::CalPayload& payload);

/// Reads channel `channel`'s entry into `*out`: erased (every byte 0xFF), damaged (CRC, channel byte or a range wrong)
/// or valid.
RecordState read_entry(uint8_t channel, proto::CalPayload* out);

/// The four entries judged together.
struct StoredCal {
  proto::CalState state;  ///< none, active, damaged or mixed (settled is the firmware's, after a warm restart)
  uint16_t cal_id;        ///< the entries' id when active, else 0
  ChannelModel models[kChannelCount];
};

StoredCal read_calibration();

}  // namespace fw
}  // namespace driftlab
