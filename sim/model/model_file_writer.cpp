// Model-file writer: a SimModel as the model-file text the reader takes back; see model_file.hpp.
#include <algorithm>
#include <sstream>
#include <string>

#include "sim/effects/params.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor.hpp"

namespace driftlab::sim {
namespace {

// Model-file text, a table header and its keys at a time.
class TextWriter {
public:
    void table(const std::string& header) { out_ << "\n[" << header << "]\n"; }
    void key(std::string_view key, const std::string& value) { out_ << key << " = " << value << "\n"; }
    void number(std::string_view key, double value) { this->key(key, toml_number_text(value)); }
    std::ostringstream& stream() { return out_; }

private:
    std::ostringstream out_;
};

void write_direction(TextWriter& w, const std::string& path, const DirectionParams& d) {
    w.table(path);
    w.number("latency_s", d.latency_s);
    w.number("byte_error_rate", d.byte_error_rate);
    w.number("byte_drop_rate", d.byte_drop_rate);
    const PacketLossParams& pl = d.packet_loss;
    w.table(path + ".packet_loss");
    w.key("unit", pl.unit == LossUnit::frame ? "\"frame\"" : "\"byte\"");
    w.number("p_good_to_bad", pl.p_good_to_bad);
    w.number("p_bad_to_good", pl.p_bad_to_good);
    w.number("loss_in_good", pl.loss_in_good);
    w.number("loss_in_bad", pl.loss_in_bad);
}

}  // namespace

std::string write_model(const SimModel& m, std::string_view comment) {
    TextWriter w;
    for (std::size_t start = 0; start < comment.size();) {
        const std::size_t end = std::min(comment.find('\n', start), comment.size());
        w.stream() << "# " << comment.substr(start, end - start) << "\n";
        start = end + 1;
    }
    w.key("name", toml_value_text(toml::value<std::string>(m.name)));
    w.table("adc");
    w.key("bits", std::to_string(m.adc.bits));
    w.number("vref_v", m.adc.vref_v);
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        const std::string u = channel_unit(static_cast<Channel>(i));
        const ChannelModel& ch = m.channels[i];
        w.table(std::string("channels.") + kChannelNames[i]);
        w.number("sensitivity_v_per_" + u, ch.front_end.sensitivity_v_per_unit);
        w.number("null_v", ch.front_end.null_v);
        w.number("span_" + u, ch.front_end.span_unit);
        w.number("center_" + u, ch.front_end.center_unit);
        w.number("input_" + u, ch.input_unit);
        w.number("raw_noise_std_" + u, ch.raw_noise_std_unit);
        w.number("drift_c1_counts", ch.drift.c1_counts);
        w.number("drift_c2_counts", ch.drift.c2_counts);
        w.number("drift_tau_s", ch.drift.tau_s);
    }
    // An effect named once is a table; one named more often, an array of tables with its instances together.
    std::vector<std::string> names;
    for (const EffectSpec& e : m.effects)
        if (std::find(names.begin(), names.end(), e.name) == names.end()) names.push_back(e.name);
    for (const std::string& name : names) {
        const auto same =
            std::count_if(m.effects.begin(), m.effects.end(), [&](const EffectSpec& o) { return o.name == name; });
        for (const EffectSpec& e : m.effects) {
            if (e.name != name) continue;
            w.stream() << (same == 1 ? "\n[effects." + name + "]\n" : "\n[[effects." + name + "]]\n");
            for (const auto& [key, value] : e.table) w.key(key.str(), toml_value_text(value));
        }
    }
    const proto::ConfigPayload& fw = m.firmware;
    w.table("firmware");
    w.key("output_period_ms", std::to_string(fw.output_period_ms));
    w.key("conversions_per_output", std::to_string(fw.conversions_per_output));
    w.key("window", std::to_string(fw.window));
    w.key("fit_order", std::to_string(fw.fit_order));
    w.key("mode", fw.mode == static_cast<std::uint8_t>(proto::OutputMode::poll) ? "\"poll\"" : "\"stream\"");
    w.key("raw", fw.raw ? "true" : "false");
    w.table("link");
    w.number("baud", m.link.baud);
    write_direction(w, "link.to_host", m.link.to_host);
    write_direction(w, "link.to_firmware", m.link.to_firmware);
    return w.stream().str();
}

}  // namespace driftlab::sim
