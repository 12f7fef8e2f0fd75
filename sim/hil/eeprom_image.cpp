// EEPROM image of a calibration (eeprom_image.hpp).
#include "sim/hil/eeprom_image.hpp"

#include <algorithm>

#include "firmware/core/cal_entry.hpp"
#include "firmware/core/hal.hpp"

namespace driftlab::sim {

std::vector<std::uint8_t> eeprom_image(std::span<const proto::CalPayload> calibration) {
    std::vector<std::uint8_t> image(fw::kEepromBytes, 0xFF);
    for (const proto::CalPayload& entry : calibration) {
        std::uint8_t bytes[fw::kCalEntryBytes];
        fw::entry_bytes(entry, bytes);
        std::copy(std::begin(bytes), std::end(bytes), image.begin() + fw::entry_address(entry.channel));
    }
    return image;
}

}  // namespace driftlab::sim
