// Config: the sampling and output configuration the firmware runs with, its defaults, its validation, and the
// conversion schedule it implies. Wire form: proto::ConfigPayload (docs/protocol.md §3.4); timing rules:
// docs/firmware.md "Timing".
#pragma once

#include <stdint.h>

#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/nodiscard.hpp"
#include "driftlab/proto/status.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/core/ls_window.hpp"

namespace driftlab {
namespace fw {

struct Config {
  uint16_t output_period_ms;       ///< time between outputs [ms]
  uint8_t conversions_per_output;  ///< conversions per channel per output [conversions]
  uint8_t window;                  ///< N of the sliding least-squares fit [conversions]
  FitOrder fit_order;
  proto::OutputMode mode;
  bool raw;  ///< also send RAW after each SAMPLE
};

/// Defaults, chosen after the paper's set-up:
///  - 100 ms output period: the paper's Fig. 2 rate (1000 samples every 0.1 s);
///  - 25 conversions per channel per output: 100 ms / (4 x 25) = 1 ms = exactly 250 ticks per conversion, so the
///    effective output period is exactly 100 ms;
///  - window 25 = conversions_per_output: each output fits exactly the conversions since the previous one, so
///    successive outputs share no noise and white sensor noise stays white for the whiteness test (eqs. 2-4);
///  - order 0: the unit sits still, so a line only adds variance (2(2N-1)/(N(N+1)) vs 1/N of sigma^2);
///  - poll mode, no RAW: the paper's PC asks for each sample over a slow radio link.
constexpr Config kDefaultConfig = {100, 25, 25, FitOrder::mean, proto::OutputMode::poll, false};

/// Shortest conversion period the firmware accepts [ticks] (200 us): an auto-triggered conversion takes 13.5 ADC
/// clocks at 125 kHz (108 us), the rest is for the ADC interrupt and the main loop's window update.
constexpr uint16_t kMinConversionPeriodTicks = 50;
/// Longest conversion period [ticks] (262 ms): Timer1's 16-bit compare register at 250 kHz.
constexpr uint16_t kMaxConversionPeriodTicks = 65535;

/// Result of validate(): Status::ok, or the reason and the ConfigField index of the first offending field.
struct ConfigCheck {
  proto::Status status;
  uint8_t field;  ///< proto::ConfigField value, proto::kNakFieldNone when ok
};

/// Checks every range of docs/protocol.md §3.4, then that the implied conversion period lies in
/// [kMinConversionPeriodTicks, kMaxConversionPeriodTicks]; a period outside it is reported against
/// conversions_per_output, the field that sets the conversion rate for a given output period.
DRIFTLAB_NODISCARD ConfigCheck validate(const proto::ConfigPayload& payload);

/// Wire form to Config. Precondition: validate(payload) returned ok.
Config config_from_payload(const proto::ConfigPayload& payload);
proto::ConfigPayload config_to_payload(const Config& config);

/// Conversion period the config implies [ticks]: output_period / (4 x conversions_per_output), rounded to the
/// nearest tick; the effective output period is 4 x conversions_per_output x this.
uint32_t conversion_period_ticks(uint16_t output_period_ms, uint8_t conversions_per_output);

/// The ADC schedule hal_init() receives for `config`: first trigger at `first_trigger_tick` [ticks], the
/// config's period, channels in Channel order.
AdcSchedule adc_schedule(const Config& config, uint32_t first_trigger_tick);

}  // namespace fw
}  // namespace driftlab
