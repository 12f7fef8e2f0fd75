// CAL.json reading and writing (cal_file.hpp).
#include "host/cal/cal_file.hpp"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "host/util/error.hpp"
#include "host/util/input_file.hpp"
#include "host/util/output_file.hpp"

namespace driftlab::host::cal {
namespace {

using nlohmann::json;

constexpr int kFormat = 1;
constexpr std::size_t kMaxCalFileBytes = std::size_t{1} << 20;

nlohmann::ordered_json interval(const std::array<double, 2>& ci) {
    if (!std::isfinite(ci[0]) || !std::isfinite(ci[1])) return nullptr;
    return nlohmann::ordered_json::array({ci[0], ci[1]});
}

std::array<double, 2> read_interval(const json& j) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) return {nan, nan};
    return {j[0].get<double>(), j[1].get<double>()};
}

double number(const std::string& path, const json& channel, const std::string& where, const char* key) {
    if (!channel.contains(key) || !channel[key].is_number())
        throw DataError(path, 0, where + "." + key + ": missing or not a number");
    const double v = channel[key].get<double>();
    if (!std::isfinite(v)) throw DataError(path, 0, where + "." + key + ": not finite");
    return v;
}

ChannelCalibration read_channel(const std::string& path, const json& channels, const char* name) {
    const std::string where = std::string("channels.") + name;
    if (!channels.contains(name) || !channels[name].is_object()) throw DataError(path, 0, where + ": missing");
    const json& j = channels[name];
    ChannelCalibration c;
    c.model.c1 = number(path, j, where, "C1");
    c.model.c2 = number(path, j, where, "C2");
    c.model.t_s = number(path, j, where, "T");
    if (!j.contains("zero") || !j["zero"].is_boolean())
        throw DataError(path, 0, where + ".zero: missing or not true/false");
    c.zero = j["zero"].get<bool>();
    c.c1_ci95 = read_interval(j.value("C1_ci95", json()));
    c.c2_ci95 = read_interval(j.value("C2_ci95", json()));
    c.t_ci95 = read_interval(j.value("T_ci95", json()));
    return c;
}

}  // namespace

std::string calibration_json(const Calibration& cal) {
    // In the order a person reads it, not sorted by key.
    nlohmann::ordered_json channels = nlohmann::ordered_json::object();
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const ChannelCalibration& ch = cal.channels[c];
        channels[kChannelNames[c]] = {{"C1", ch.model.c1},
                                      {"C2", ch.model.c2},
                                      {"T", ch.model.t_s},
                                      {"zero", ch.zero},
                                      {"C1_ci95", interval(ch.c1_ci95)},
                                      {"C2_ci95", interval(ch.c2_ci95)},
                                      {"T_ci95", interval(ch.t_ci95)}};
    }
    const nlohmann::ordered_json doc = {{"driftlab_calibration", kFormat},
                                        {"cal_id", cal.id},
                                        {"source", cal.source},
                                        {"units", {{"C1", "counts"}, {"C2", "counts"}, {"T", "s"}}},
                                        {"channels", channels}};
    return doc.dump(2) + "\n";
}

void write_calibration(const std::string& path, const Calibration& cal) {
    write_output_file(path, calibration_json(cal), "calibration");
}

Calibration read_calibration(const std::string& path) {
    json doc;
    try {
        doc = json::parse(read_small_file(path, kMaxCalFileBytes));
    } catch (const json::parse_error& e) {
        throw DataError(path, 0, std::string("not JSON: ") + e.what());
    }
    if (!doc.is_object() || doc.value("driftlab_calibration", json()) != kFormat)
        throw DataError(path, 0, "not a driftlab calibration (no \"driftlab_calibration\": 1)");
    Calibration cal;
    const json id = doc.value("cal_id", json());
    if (!id.is_number_integer() || id.get<std::int64_t>() < 1 || id.get<std::int64_t>() > 65535)
        throw DataError(path, 0, "cal_id: missing or not an integer 1 to 65535");
    cal.id = static_cast<std::uint16_t>(id.get<std::int64_t>());
    cal.source = doc.value("source", json("")).is_string() ? doc.value("source", std::string()) : std::string();
    if (!doc.contains("channels") || !doc["channels"].is_object()) throw DataError(path, 0, "channels: missing");
    for (std::size_t c = 0; c < kChannelCount; ++c)
        cal.channels[c] = read_channel(path, doc["channels"], kChannelNames[c]);
    static_cast<void>(to_payloads(cal, path));
    return cal;
}

}  // namespace driftlab::host::cal
