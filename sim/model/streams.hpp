// RNG substream numbers of the base model and the link (effects derive theirs from their names,
// effect_stream_id()). Fixed numbers keep a run's draws unchanged when an unrelated component is switched on.
#pragma once

#include <cstdint>

namespace driftlab::sim {

inline constexpr std::uint64_t kNoiseStreamBase = 0x100;       ///< + channel index: white noise
inline constexpr std::uint64_t kToHostStreamBase = 0x200;      ///< + behaviour: firmware -> host link
inline constexpr std::uint64_t kToFirmwareStreamBase = 0x300;  ///< + behaviour: host -> firmware link
inline constexpr std::uint64_t kTrajectoryStream = 0x400;      ///< stop-and-go's stretches

}  // namespace driftlab::sim
