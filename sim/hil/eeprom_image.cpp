// EEPROM image of a calibration and a key (eeprom_image.hpp).
#include "sim/hil/eeprom_image.hpp"

#include <algorithm>

#include "firmware/core/cal_entry.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/key_record.hpp"

namespace driftlab::sim {

std::vector<std::uint8_t> eeprom_image(std::span<const proto::CalPayload> calibration,
                                       const std::optional<BoardKey>& key) {
    std::vector<std::uint8_t> image(fw::kEepromBytes, 0xFF);
    for (const proto::CalPayload& entry : calibration) {
        std::uint8_t bytes[fw::kCalEntryBytes];
        fw::entry_bytes(entry, bytes);
        std::copy(std::begin(bytes), std::end(bytes), image.begin() + fw::entry_address(entry.channel));
    }
    if (const KeyBytes bytes(key); bytes.get() != nullptr) {
        std::uint8_t record[fw::kKeyRecordBytes];
        fw::key_record_bytes(*bytes.get(), record);
        std::copy(std::begin(record), std::end(record), image.begin() + fw::kKeyEepromAddress);
    }
    return image;
}

}  // namespace driftlab::sim
