// EEPROM image of a calibration and a key (eeprom_image.hpp).
#include "sim/hil/eeprom_image.hpp"

#include <algorithm>

#include "firmware/core/cal_entry.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/key_record.hpp"

namespace driftlab::sim {

std::vector<std::uint8_t> eeprom_image(std::span<const proto::CalPayload> calibration,
                                       const std::optional<std::array<std::uint8_t, auth::kKeyBytes>>& key) {
    std::vector<std::uint8_t> image(fw::kEepromBytes, 0xFF);
    for (const proto::CalPayload& entry : calibration) {
        std::uint8_t bytes[fw::kCalEntryBytes];
        fw::entry_bytes(entry, bytes);
        std::copy(std::begin(bytes), std::end(bytes), image.begin() + fw::entry_address(entry.channel));
    }
    if (key) {
        std::uint8_t raw[auth::kKeyBytes];
        std::copy(key->begin(), key->end(), raw);
        std::uint8_t record[fw::kKeyRecordBytes];
        fw::key_record_bytes(raw, record);
        std::copy(std::begin(record), std::end(record), image.begin() + fw::kKeyEepromAddress);
    }
    return image;
}

}  // namespace driftlab::sim
