// Payloads of protocol v2 (HELLO..KEY_SET) as plain structs, with serialize/parse to and from the wire's
// little-endian byte layout. Spec: docs/protocol.md §3. HELLO, CONFIG_GET, POLL and STATUS_GET carry no payload.
//
// serialize() writes exactly the type's fixed length and returns it, or 0 when `out_size` is smaller.
// parse() accepts exactly the fixed length; it checks layout only, ranges are the receiver's business
// (the firmware's config validation, for instance, answers NAK out_of_range with the field index below).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "driftlab/channels.hpp"
#include "driftlab/proto/command_auth.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/nodiscard.hpp"

namespace driftlab {
namespace proto {

/// What the board does with its calibration (docs/protocol.md §3.12), as VERSION, SAMPLE and STATUS report it.
/// Outputs are compensated in the states active and settled only.
enum class CalState : uint8_t {
  none = 0,     ///< no calibration stored (erased entries, or one cleared with cal_id 0): outputs as measured
  active = 1,   ///< the four entries agree and pass their CRC: outputs compensated, t counted from a cold start
  settled = 2,  ///< as active after a warm restart (watchdog, reset pin): the transient taken as over
  damaged = 3,  ///< an entry fails its CRC: outputs as measured
  mixed = 4,    ///< the entries carry different calibration ids (an upload cut short): outputs as measured
};

/// True in the states whose outputs the board compensated.
constexpr bool is_compensated(uint8_t cal_state) {
  return cal_state == static_cast<uint8_t>(CalState::active) || cal_state == static_cast<uint8_t>(CalState::settled);
}

/// Whether the board takes commands that change it from anyone (docs/security.md), as VERSION reports it.
enum class AuthState : uint8_t {
  open = 0,     ///< no key provisioned: CONFIG_SET and CAL_SET are taken without checking their tag; KEY_SET is refused
  keyed = 1,    ///< a key: CONFIG_SET, CAL_SET and KEY_SET must carry its tag and a counter above the last admitted
  damaged = 2,  ///< the key record fails its CRC: every command that changes the board is refused
};

/// VERSION (0x02, fw->host): what the firmware is and how it samples. Sent in answer to HELLO.
struct VersionPayload {
  uint8_t proto_version;  ///< kProtocolVersion of the firmware
  uint8_t fw_major;       ///< firmware version, semantic
  uint8_t fw_minor;
  uint8_t fw_patch;
  uint8_t board_id;                ///< board variant (docs/hardware.md)
  uint8_t adc_bits;                ///< converter resolution [bits]
  uint16_t vref_mv;                ///< converter reference [mV]
  uint32_t tick_hz;                ///< firmware tick rate [Hz]; 250000 on the ATmega328P
  uint8_t channel_count;           ///< channels sampled (kChannelCount)
  uint8_t adc_pin[kChannelCount];  ///< ADC multiplexer input of gyro, accel_x, accel_y, accel_z
  uint8_t reset_cause;             ///< MCUSR bits of the last reset
  uint16_t assert_line;            ///< source line of the assertion that caused the last reset, 0 = none
  uint8_t cal_state;               ///< CalState at the answer
  uint16_t cal_id;                 ///< id of the calibration applied, 0 when cal_state is not compensated
  uint8_t auth_state;              ///< AuthState
  uint32_t auth_counter;           ///< counter of the last command admitted; the next must carry a larger one
};

/// CONFIG (0x05, fw->host), and CONFIG_SET (0x04, host->fw) before its authentication trailer (command_auth.hpp):
/// sampling and output configuration.
struct ConfigPayload {
  uint16_t output_period_ms;       ///< time between outputs [ms], kOutputPeriodMinMs..kOutputPeriodMaxMs
  uint8_t conversions_per_output;  ///< ADC conversions per channel per output, 1..64
  uint8_t window;                  ///< N of the sliding least-squares fit [conversions], 1..64
  uint8_t fit_order;               ///< 0 = mean, 1 = line (estimate at the newest conversion)
  uint8_t mode;                    ///< OutputMode
  uint8_t raw;                     ///< 1 = also send RAW after each SAMPLE
};

/// SAMPLE (0x07, fw->host): the smoothed value of every channel.
///
/// One tick for four values that are not all at that tick: the channels are converted round-robin, and each
/// channel's value is its fit evaluated at *its own* newest conversion, while `tick` is the newest conversion of
/// any channel. In stream mode the SAMPLE follows accel_z's conversion, so accel_z is at `tick` and channel c's
/// value is (3 - c) conversion periods older (gyro 3, accel_x 2, accel_y 1); a POLL answers wherever the round
/// happens to be (docs/protocol.md §3.6).
/// `n_window` = 0 means some channel's window is empty and its value_q8 is 0, not a reading. A POLL before the
/// first conversion or right after an ACKed CONFIG_SET emptied the windows gets 0 on every channel with the last
/// `tick` seen; only n_window tells it from a real estimate (the firmware does not NAK such a POLL).
struct SamplePayload {
  uint32_t tick;                    ///< trigger tick of the newest conversion of any channel [ticks]
  int32_t value_q8[kChannelCount];  ///< least-squares fit of each channel at that channel's own newest conversion,
                                    ///< not at `tick` (above) [counts, Q8 = 1/256 count], Channel order
  uint8_t sat_flags;                ///< bit c: channel c saw code 0 or 1023 inside its window
  uint8_t n_window;                 ///< conversions in the least filled window now [conversions]; < window at start,
                                    ///< 0 = a window is empty, its value is 0 and no reading
  uint16_t dropped;                 ///< conversions lost since boot, saturating [conversions]
  uint8_t cal_state;                ///< CalState: the values are compensated when active or settled
  uint16_t cal_id;                  ///< id of the calibration applied to the values, 0 when not compensated
  uint16_t temp_code;               ///< newest die temperature conversion (ADC8 against 1.1 V; temperature.hpp), taken
                                    ///< at boot and about once a second; kNoTemperature when the schedule has no room
};

/// SamplePayload.temp_code of a board without a current reading (a schedule too fast to take one: docs/firmware.md).
constexpr uint16_t kNoTemperature = 0xFFFF;

/// RAW (0x08, fw->host): the newest raw code of every channel.
struct RawPayload {
  uint32_t tick;                 ///< time of the newest conversion [ticks]
  uint16_t code[kChannelCount];  ///< ADC code [counts], Channel order
};

/// ACK (0x09, fw->host): a request was accepted (and applied).
struct AckPayload {
  uint8_t acked_type;  ///< MsgType id of the request
  uint16_t acked_seq;  ///< seq of the request frame
};

/// NAK (0x0A, fw->host): a request was refused and nothing changed.
struct NakPayload {
  uint8_t nacked_type;  ///< MsgType id of the request (as received, may be unknown)
  uint16_t nacked_seq;  ///< seq of the request frame
  uint8_t status;       ///< Status number (status.hpp)
  uint8_t field;        ///< index of the offending field in the payload's field list, kNakFieldNone = n/a
};

/// STATUS (0x0C, fw->host): firmware health counters, all saturating. There is no counter for the decoder's
/// bad_version: a frame of another protocol version shows only in rx_resync_bytes (docs/protocol.md §4).
struct StatusPayload {
  uint32_t uptime_ticks;     ///< ticks since reset [ticks], wraps
  uint16_t rx_frames;        ///< valid frames received [frames]
  uint16_t rx_bad_crc;       ///< decoder rejects by CRC [frames]
  uint16_t rx_bad_length;    ///< decoder rejects by length [frames]
  uint16_t rx_unknown_type;  ///< decoder rejects by type [frames]
  uint16_t rx_resync_bytes;  ///< bytes the decoder skipped [bytes]
  uint16_t rx_overflow;      ///< bytes lost because the RX ring was full [bytes]
  uint16_t tx_overflow;      ///< bytes lost because the TX ring was full [bytes]
  uint16_t dropped;          ///< conversions lost [conversions]
  uint8_t cal_state;         ///< CalState
  uint16_t cal_id;           ///< id of the calibration applied, 0 when cal_state is not compensated
  uint16_t auth_refused;     ///< commands refused because their tag did not verify (NAK unauthenticated) [commands]
  uint16_t auth_replayed;    ///< commands refused because their counter was not new (NAK replayed) [commands]
};

/// CAL (0x0F, fw->host), and CAL_SET (0x0D, host->fw) before its authentication trailer: one channel's entry of the
/// calibration, eq. 1 in fixed point. The board compensates once all four entries carry the same non-zero cal_id
/// (docs/protocol.md §3.12).
struct CalPayload {
  uint16_t cal_id;  ///< calibration id; 0 clears the entry (no compensation)
  uint8_t channel;  ///< Channel index 0..3
  uint8_t flags;    ///< kCalFlagZero: refer the settled level to mid-scale as well
  int32_t c1_q8;    ///< C1 [counts Q8]
  int32_t c2_q8;    ///< C2 [counts Q8]
  uint32_t t_ms;    ///< T [ms]
};

/// CAL_GET (0x0E, host->fw): which channel's entry to read back.
struct CalGetPayload {
  uint8_t channel;  ///< Channel index 0..3
};

/// CalPayload.flags bits.
constexpr uint8_t kCalFlagZero = 0x01;

/// Ranges of CalPayload (docs/protocol.md §3.12): T from 60 s (the board's interpolation between its grid points keeps
/// its error below 1/100 LSB above it) to 9.4 h (125 T_ms fits 32 bits); |C1| and |C2| within the converter.
constexpr uint32_t kCalTMinMs = 60000;
constexpr uint32_t kCalTMaxMs = 34000000;
constexpr int32_t kCalCountsMaxQ8 = 1023L * 256;

/// Field indices of CalPayload, as NAK.field reports them.
enum class CalField : uint8_t { cal_id = 0, channel = 1, flags = 2, c1_q8 = 3, c2_q8 = 4, t_ms = 5 };

/// ConfigPayload.mode values.
enum class OutputMode : uint8_t { poll = 0, stream = 1 };

/// Field indices of ConfigPayload, as NAK.field reports them.
enum class ConfigField : uint8_t {
  output_period_ms = 0,
  conversions_per_output = 1,
  window = 2,
  fit_order = 3,
  mode = 4,
  raw = 5,
};

constexpr uint8_t kNakFieldNone = 0xFF;

/// A ConfigField's name as docs/protocol.md and model files spell it ("output_period_ms"...); nullptr for a value
/// that names no field (kNakFieldNone, or a corrupt NAK).
const char* config_field_name(uint8_t field);
/// A CalField's name ("t_ms"...), nullptr for a value that names no field.
const char* cal_field_name(uint8_t field);
/// A CalState's name as logs spell it ("active"), nullptr for a number this version does not know.
const char* cal_state_name(uint8_t state);

/// Ranges of ConfigPayload (docs/protocol.md §3.4).
constexpr uint16_t kOutputPeriodMinMs = 10;
constexpr uint16_t kOutputPeriodMaxMs = 60000;
constexpr uint8_t kConversionsPerOutputMax = 64;
constexpr uint8_t kWindowMax = 64;
constexpr uint8_t kFitOrderMax = 1;

/// Wire sizes [bytes]; each equals its table row, checked below.
constexpr uint8_t kVersionPayloadSize = 28;
constexpr uint8_t kConfigPayloadSize = 7;
constexpr uint8_t kSamplePayloadSize = 29;
constexpr uint8_t kRawPayloadSize = 12;
constexpr uint8_t kAckPayloadSize = 3;
constexpr uint8_t kNakPayloadSize = 5;
constexpr uint8_t kStatusPayloadSize = 27;
constexpr uint8_t kCalPayloadSize = 16;
constexpr uint8_t kCalGetPayloadSize = 1;

static_assert(payload_len_of(MsgType::version) == kVersionPayloadSize, "VERSION size differs from the table");
static_assert(payload_len_of(MsgType::config_set) == kConfigPayloadSize + kAuthTrailerBytes,
              "CONFIG_SET size differs from the table");
static_assert(payload_len_of(MsgType::config) == kConfigPayloadSize, "CONFIG size differs from the table");
static_assert(payload_len_of(MsgType::sample) == kSamplePayloadSize, "SAMPLE size differs from the table");
static_assert(payload_len_of(MsgType::raw) == kRawPayloadSize, "RAW size differs from the table");
static_assert(payload_len_of(MsgType::ack) == kAckPayloadSize, "ACK size differs from the table");
static_assert(payload_len_of(MsgType::nak) == kNakPayloadSize, "NAK size differs from the table");
static_assert(payload_len_of(MsgType::status) == kStatusPayloadSize, "STATUS size differs from the table");
static_assert(payload_len_of(MsgType::cal_set) == kCalPayloadSize + kAuthTrailerBytes,
              "CAL_SET size differs from the table");
static_assert(payload_len_of(MsgType::key_set) == kKeySetFieldBytes + kAuthTrailerBytes,
              "KEY_SET size differs from the table");
static_assert(payload_len_of(MsgType::cal_get) == kCalGetPayloadSize, "CAL_GET size differs from the table");
static_assert(payload_len_of(MsgType::cal) == kCalPayloadSize, "CAL size differs from the table");

DRIFTLAB_NODISCARD size_t serialize(const VersionPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const ConfigPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const SamplePayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const RawPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const AckPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const NakPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const StatusPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const CalPayload& p, uint8_t* out, size_t out_size);
DRIFTLAB_NODISCARD size_t serialize(const CalGetPayload& p, uint8_t* out, size_t out_size);

DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, VersionPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, ConfigPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, SamplePayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, RawPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, AckPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, NakPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, StatusPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, CalPayload* out);
DRIFTLAB_NODISCARD bool parse(const uint8_t* in, size_t in_size, CalGetPayload* out);

}  // namespace proto
}  // namespace driftlab
