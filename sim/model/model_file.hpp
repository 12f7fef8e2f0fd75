// Model files: TOML <-> SimModel. A file overlays the paper's unit (paper_model()), so it names only what
// differs; every key carries its unit in its name (_v, _s, _dps, _g, _counts, _ms) or is documented in
// docs/sim.md §Model file. Unknown keys, wrong types and out-of-range values are errors naming file, line and
// key. Effects are parsed by the effect registry (sim/effects/effect.hpp).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "sim/model/sim_model.hpp"

namespace driftlab::sim {

/// Why the firmware would refuse `fw` (its own CONFIG check, whose limits join fields: a conversion rate too fast
/// for the output period), naming the field as the firmware's NAK does; none when it accepts it.
struct FirmwareRefusal {
    std::string field;
    std::string reason;
};
std::optional<FirmwareRefusal> firmware_refusal(const proto::ConfigPayload& fw);

/// Changes to the file's firmware CONFIG (a command line's --period, --conversions...), made before the firmware's
/// own check of the joined fields, so that the configuration checked is the one that will run; `check` false when
/// none will (hil --pty: the recorder configures the board).
struct FirmwareAdjust {
    std::function<void(proto::ConfigPayload&)> change;
    bool check = true;
};

/// The largest model file load_model_file() reads [bytes]; the project's own are under 4 KB.
inline constexpr std::size_t kMaxModelFileBytes = std::size_t{1} << 20;

/// Reads `path`. Throws ModelFileError ("file:line: key: what") on any bad content, and when the file cannot
/// be read.
SimModel load_model_file(const std::string& path, const FirmwareAdjust& adjust = {});

/// Parses model-file text; `source_name` names it in errors.
SimModel parse_model(std::string_view toml_text, const std::string& source_name, const FirmwareAdjust& adjust = {});

/// Model-file text that parse_model() reads back to `model`: every key (so the file does not depend on the built-in
/// model it would overlay), numbers in their shortest exact form, and an effect named more than once (one instance
/// per channel, as the gap diagnosis fits them) as an array of tables. `comment` opens the file, each line after "# ".
std::string write_model(const SimModel& model, std::string_view comment = {});

/// The model file text compiled into the program (sim/models/paper.toml).
std::string_view paper_model_text();

}  // namespace driftlab::sim
