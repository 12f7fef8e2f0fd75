// Recording table of the report; see recording_section.hpp.
#include "host/view/recording_section.hpp"

#include <cmath>
#include <initializer_list>

#include "host/log/compensation.hpp"
#include "host/util/format_number.hpp"
#include "host/util/units.hpp"
#include "host/view/html.hpp"

namespace driftlab::host::view {
namespace {

using Rows = std::vector<std::pair<std::string, std::string>>;

/// What the log's `source` word means, for the known writers (docs/log-format.md §2); another word as it is.
std::string source_text(const std::string& source) {
    if (source == "record") return "record: a board, recorded over its serial link";
    if (source == "decode") return "decode: a board's raw capture, decoded";
    if (source == "hil") return "hil: simulated sensor, firmware in the loop";
    if (source == "sim") return "sim: simulated";
    return source;
}

/// One metadata key in a row's text: the words before and after its value.
struct Part {
    const char* key;
    const char* before;
    const char* after;
};

/// `before value after` for each part whose key the metadata has, ", "-joined; "" when it has none.
std::string parts_text(const LogMetadata& m, std::initializer_list<Part> parts) {
    std::string text;
    for (const Part& p : parts)
        if (const auto value = m.get(p.key))
            text += (text.empty() ? "" : ", ") + std::string(p.before) + *value + p.after;
    return text;
}

/// 3999 s as "3999 s (1 h 6 min 39 s)"; below a minute the seconds alone.
std::string duration_text(double s) {
    std::string text = significant_plain(s, 6) + " s";
    if (s < 60.0) return text;
    const auto whole = static_cast<long long>(std::llround(s));
    const long long h = whole / 3600, min = whole / 60 % 60, sec = whole % 60;
    return text + " (" + (h > 0 ? std::to_string(h) + " h " : "") + std::to_string(min) + " min " +
           std::to_string(sec) + " s)";
}

std::string output_rate_text(const fit::LogOverview& log) {
    const LogMetadata& m = log.metadata;
    if (const auto period_s = m.get_double("sample_period_s"); period_s && *period_s > 0.0) {
        const auto mode = m.get("mode");
        return significant_plain(1.0 / *period_s, 6) + " Hz (sample_period_s " + significant_plain(*period_s, 6) +
               " s" + (mode ? ", " + *mode + " mode" : "") + ")";
    }
    if (log.rows < 2) return "";
    const double mean_s = (log.last_t_s - log.first_t_s) / static_cast<double>(log.rows - 1);
    return significant_plain(1.0 / mean_s, 4) + " Hz (the rows' mean spacing; the header names no sample_period_s)";
}

std::string smoothing_text(const LogMetadata& m) {
    const auto window = m.get_int("window");
    const auto order = m.get_int("fit_order");
    if (!window && !order) return "";
    std::string text = "on-board least squares";
    if (order)
        text += " of order " + std::to_string(*order) + (*order == 0 ? " (a mean)" : *order == 1 ? " (a line)" : "");
    if (window) text += " over " + std::to_string(*window) + " conversions";
    if (const auto per_output = m.get_int("conversions_per_output"))
        text += ", " + std::to_string(*per_output) + " conversions per output";
    return text;
}

std::string channels_text(const fit::LogOverview& log) {
    std::string text;
    for (const std::string& name : log.channels) text += (text.empty() ? "" : ", ") + name;
    text += " [counts]";
    // The scales (host/util/units.hpp), so a reader can take a count to a datasheet's unit.
    bool gyro = false, accel = false;
    for (const std::string& name : log.channels) (name == kChannelNames[0] ? gyro : accel) = true;
    std::string scales;
    for (const Channel c : {Channel::gyro, Channel::accel_x}) {
        if (!(c == Channel::gyro ? gyro : accel)) continue;
        const PhysicalUnit u = physical_unit(c);
        scales += (scales.empty() ? "; a count is " : ", ") + significant_plain(u.per_count, 5) + " " + u.name +
                  (c == Channel::gyro ? " (gyro)" : " (accelerometer)");
    }
    text += scales;
    if (log.raw_codes) text += "; raw converter codes beside them";
    return text;
}

}  // namespace

Rows recording_rows(const fit::LogOverview& log) {
    const LogMetadata& m = log.metadata;
    Rows rows;
    const auto add = [&rows](const char* label, const std::string& text) {
        if (!text.empty()) rows.emplace_back(label, text);
    };
    if (const auto source = m.get("source")) add("source", source_text(*source));
    // Under hil the emulated firmware reports the board variant it was built for; no board took part.
    const bool emulated = m.get("source") == std::optional<std::string>("hil");
    add(emulated ? "board (emulated)" : "board",
        parts_text(m, {{"board_id", emulated ? "firmware built for id " : "id ", ""},
                       {"port", "port ", ""},
                       {"baud", "", " baud"}}));
    add("simulation", parts_text(m, {{"target", "target ", ""},
                                     {"model_name", "model ", ""},
                                     {"model", "model file ", ""},
                                     {"preset", "preset ", ""},
                                     {"seed", "seed ", ""},
                                     {"effects", "effects ", ""}}));
    add("firmware", parts_text(m, {{"firmware_version", "version ", ""}, {"protocol_version", "protocol ", ""}}));
    add("log format", "driftlab log, format " + std::to_string(kLogFormatVersion));
    if (const auto start = m.get("start_utc")) add("start", *start);
    add("duration", duration_text(log.last_t_s - log.first_t_s) + ", t_s " + significant_plain(log.first_t_s, 6) +
                        " to " + significant_plain(log.last_t_s, 6) + " s after power-on");
    add("samples", std::to_string(log.rows) +
                       (log.gap_events == 0 ? "" : ", " + counted(log.gap_events, "link gap") + " (# gap: lines)"));
    add("output rate", output_rate_text(log));
    add("smoothing", smoothing_text(m));
    if (const auto state = m.get("cal_state"))
        add("compensation",
            compensated_on_board(m).value_or("none on board: outputs as measured (calibration " + *state + ")"));
    add("converter",
        parts_text(m, {{"adc_bits", "", "-bit"}, {"vref_v", "", " V reference"}, {"tick_hz", "", " Hz tick"}}));
    add("channels", channels_text(log));
    return rows;
}

std::string recording_section(const fit::LogOverview& log) {
    std::string h = "<h2>Recording</h2>\n<table class=\"recording\">\n";
    for (const auto& [label, text] : recording_rows(log))
        h += "<tr><th>" + html_escape(label) + "</th><td>" + html_escape(text) + "</td></tr>\n";
    return h + "</table>\n";
}

}  // namespace driftlab::host::view
