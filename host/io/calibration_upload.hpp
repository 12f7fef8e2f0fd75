// The calibration into a board and back out: the four CAL_SET entries, each acknowledged, each read back with
// CAL_GET and compared byte for byte, then the board's own word (VERSION) that it compensates with that id, or that
// it no longer compensates after a clear. docs/calibration.md "Upload".
#pragma once

#include <array>
#include <string>

#include "driftlab/proto/messages.hpp"
#include "host/io/board_client.hpp"

namespace driftlab::host::io {

struct UploadResult {
    bool ok = false;
    std::string problem;              ///< why not, in words for the user
    proto::VersionPayload version{};  ///< the board's VERSION after the upload
};

/// Uploads `entries` (channel order, one cal_id: non-zero to calibrate, 0 to clear) after a handshake.
UploadResult upload_calibration(BoardClient& client, const std::array<proto::CalPayload, kChannelCount>& entries);

}  // namespace driftlab::host::io
