// Presets; see hil_preset.hpp.
#include "sim/hil/hil_preset.hpp"

namespace driftlab::sim {

std::optional<Preset> preset_from_name(std::string_view name) {
    if (name == "fig3") return Preset::fig3;
    if (name == "fig2") return Preset::fig2;
    return std::nullopt;
}

void apply_preset_firmware(Preset preset, proto::ConfigPayload& fw) {
    switch (preset) {
    case Preset::fig3: break;  // the model's own output period (paper.toml: 1 s) is kept
    case Preset::fig2:
        fw.output_period_ms = 100;
        fw.conversions_per_output = 25;  // 1 ms = 250 ticks per conversion
        fw.window = kFig2Window;
        fw.fit_order = 0;
        fw.raw = 1;
        break;
    }
}

void apply_preset_run(Preset preset, HilOptions& options) {
    switch (preset) {
    case Preset::fig3:
        options.duration_s = 4000.0;
        options.warm_up_s = 0.0;
        break;
    case Preset::fig2:
        options.duration_s = 100.0;
        options.warm_up_s = 3600.0;
        break;
    }
}

void apply_preset(Preset preset, HilOptions& options) {
    apply_preset_run(preset, options);
    apply_preset_firmware(preset, options.model.firmware);
}

}  // namespace driftlab::sim
