// Config validation and the schedule it implies. Ranges: docs/protocol.md §3.4; timing: docs/firmware.md.
#include "firmware/core/config.hpp"

namespace driftlab {
namespace fw {
namespace {

ConfigCheck reject(proto::ConfigField field) {
  return ConfigCheck{proto::Status::out_of_range, static_cast<uint8_t>(field)};
}

}  // namespace

ConfigCheck validate(const proto::ConfigPayload& payload) {
  if (payload.output_period_ms < proto::kOutputPeriodMinMs || payload.output_period_ms > proto::kOutputPeriodMaxMs) {
    return reject(proto::ConfigField::output_period_ms);
  }
  if (payload.conversions_per_output < 1 || payload.conversions_per_output > proto::kConversionsPerOutputMax) {
    return reject(proto::ConfigField::conversions_per_output);
  }
  if (payload.window < 1 || payload.window > proto::kWindowMax || payload.window > LsWindow::kMaxWindow) {
    return reject(proto::ConfigField::window);
  }
  if (payload.fit_order > proto::kFitOrderMax) {
    return reject(proto::ConfigField::fit_order);
  }
  if (payload.mode > static_cast<uint8_t>(proto::OutputMode::stream)) {
    return reject(proto::ConfigField::mode);
  }
  if (payload.raw > 1) {
    return reject(proto::ConfigField::raw);
  }
  const uint32_t period_ticks = conversion_period_ticks(payload.output_period_ms, payload.conversions_per_output);
  if (period_ticks < kMinConversionPeriodTicks || period_ticks > kMaxConversionPeriodTicks) {
    return reject(proto::ConfigField::conversions_per_output);
  }
  return ConfigCheck{proto::Status::ok, proto::kNakFieldNone};
}

Config config_from_payload(const proto::ConfigPayload& payload) {
  return Config{payload.output_period_ms,
                payload.conversions_per_output,
                payload.window,
                payload.fit_order == 0 ? FitOrder::mean : FitOrder::line,
                payload.mode == 0 ? proto::OutputMode::poll : proto::OutputMode::stream,
                payload.raw != 0};
}

proto::ConfigPayload config_to_payload(const Config& config) {
  return proto::ConfigPayload{config.output_period_ms,
                              config.conversions_per_output,
                              config.window,
                              static_cast<uint8_t>(config.fit_order),
                              static_cast<uint8_t>(config.mode),
                              static_cast<uint8_t>(config.raw ? 1U : 0U)};
}

uint32_t conversion_period_ticks(uint16_t output_period_ms, uint8_t conversions_per_output) {
  const uint32_t output_ticks = static_cast<uint32_t>(output_period_ms) * kTicksPerMs;
  const uint32_t conversions = static_cast<uint32_t>(kChannelCount) * conversions_per_output;
  return conversions == 0 ? 0 : (output_ticks + conversions / 2U) / conversions;
}

AdcSchedule adc_schedule(const Config& config, uint32_t first_trigger_tick) {
  AdcSchedule schedule = {};
  schedule.first_trigger_tick = first_trigger_tick;
  schedule.conversion_period_ticks =
      static_cast<uint16_t>(conversion_period_ticks(config.output_period_ms, config.conversions_per_output));
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    schedule.order[c] = static_cast<Channel>(c);
  }
  return schedule;
}

}  // namespace fw
}  // namespace driftlab
