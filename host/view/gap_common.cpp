// The shared-causes section of a gap result (GapResult::common), in the terminal's text, the report and the JSON;
// see gap_view.hpp.
#include <cstdio>
#include <ostream>
#include <string>

#include "host/util/format_number.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {
namespace {

// "accel_x 0.00123 g (0.98 counts), ...": each loaded channel's coefficient in its display unit.
std::string loadings_text(const gap::GapResult& r, const gap::CommonFit& f) {
    std::string out;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!r.channels[c]) continue;
        const auto channel = static_cast<Channel>(c);
        out += (out.empty() ? "" : ", ") + std::string(kChannelNames[c]) + " " +
               step_size_text(r.base, channel, f.loading[c], 3) + (f.loaded[c] ? "" : " (not loaded)");
    }
    return out;
}

// What a reading says, in one line.
std::string reading_text(const gap::GapResult& r, const gap::CommonFit& f) {
    if (f.reading == "separate") {
        std::string own;
        for (std::size_t c = 0; c < kChannelCount; ++c)
            if (r.channels[c] && f.own_sd[c] > 0.0)
                own += (own.empty() ? "" : ", ") + std::string(kChannelNames[c]) + " sd " +
                       step_size_text(r.base, static_cast<Channel>(c), f.own_sd[c], 3) + " tau " +
                       significant(f.own_tau[c], 3) + " s";
        return "each channel alone: " + (own.empty() ? std::string("white floors only") : own);
    }
    std::string out = "one process, tau " + significant(f.tau_s, 3) + " s, std per channel: " + loadings_text(r, f);
    if (f.reading == "supply_coupling")
        out += "; the supply's relative wander " + significant(100.0 * f.relative_sd, 3) + " % (" +
               significant(1000.0 * 5.0 * f.relative_sd, 3) + " mV of 5 V) times each channel's DC level";
    return out;
}

// "accel_x 0.81 counts (1.6 mg) per degC (criterion -23.4), ...": the coupled channels.
std::string coupling_text(const gap::GapResult& r) {
    std::string out;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (r.temperature.coupled[c])
            out += (out.empty() ? "" : ", ") + std::string(kChannelNames[c]) + " " +
                   step_size_text(r.base, static_cast<Channel>(c), r.temperature.coefficient[c], 3) +
                   " per degC (criterion " + significant(-r.temperature.gain[c], 3) + ")";
    return out;
}

}  // namespace

std::string common_sentence(const gap::GapResult& r) {
    const gap::CommonFit* f = r.common.winner();
    if (!f && r.temperature.any())
        return "the channels follow the temperature the log measured (" + coupling_text(r) +
               "); the replicates do not replay a measured temperature, so a process the search added stays in the "
               "model as its stand-in";
    if (!f) return "";
    std::string out = "the channels share " + reading_text(r, *f) + "; read together it beats each channel read " +
                      "alone by " + significant(r.common.fits[0].criterion - f->criterion, 3) +
                      " in the Schwarz criterion";
    if (!r.common.replaced.empty()) {
        out += "; it replaces ";
        for (std::size_t i = 0; i < r.common.replaced.size(); ++i) out += (i ? ", " : "") + r.common.replaced[i];
    }
    if (f->reading == "shared_process")
        out +=
            "; its loadings do not follow the channels' DC levels, so not the supply's ratiometric path: a "
            "temperature through each channel's coefficient, or supply pickup (log the temperature or a Vcc "
            "divider to tell them apart)";
    return out +
           (r.gap_after_heldout <= r.gap_bound_after ? "; the gap closes" : "; the held-out gap stays above its bound");
}

void print_common_text(const gap::GapResult& r) {
    const gap::CommonFindings& k = r.common;
    if (!k.compared) return;
    std::printf("shared causes: the %s read together (multichannel Whittle likelihood, %s observations)%s\n",
                k.fits.empty() ? "channels" : "analysed channels", significant(k.observations, 3).c_str(),
                k.shared.empty() ? "; no coherence cell located"
                                 : ("; " + std::to_string(k.shared.size()) + " coherence cell" +
                                    (k.shared.size() == 1 ? "" : "s") + " located")
                                       .c_str());
    for (const auto& s : k.shared)
        std::printf("  %-16s %-24s %-7s z %8.1f\n", s.pair.c_str(), s.band.c_str(), s.part.c_str(), s.z);
    if (r.temperature.compared)
        std::printf("  temperature (temp_c, sd %.2f degC after eq. 1): %s\n", r.temperature.temperature_sd_c,
                    r.temperature.any() ? ("taken out of " + coupling_text(r)).c_str() : "no channel follows it");
    for (std::size_t i = 0; i < k.fits.size(); ++i)
        std::printf("  %-16s %s criterion %.1f (%d parameters): %s\n", k.fits[i].reading.c_str(),
                    k.chosen == i ? "CHOSEN " : "       ", k.fits[i].criterion, k.fits[i].parameters,
                    reading_text(r, k.fits[i]).c_str());
}

void write_common_markdown(std::ostream& md, const gap::GapResult& r) {
    const gap::CommonFindings& k = r.common;
    if (!k.compared) return;
    md << "## Shared causes\n\nThe analysed channels read together (multichannel Whittle likelihood over "
       << significant(k.observations, 3) << " observations; the lowest Schwarz criterion wins, and a shared reading "
       << "must load two channels or more).\n\n";
    if (!k.shared.empty()) {
        md << "| pair | band | part | z |\n|---|---|---|---|\n";
        for (const auto& s : k.shared)
            md << "| " << s.pair << " | " << s.band << " | " << s.part << " | " << significant(s.z, 3) << " |\n";
        md << "\n";
    }
    if (r.temperature.compared)
        md << "The logged temperature (sd " << fixed_point(r.temperature.temperature_sd_c, 2) << " °C after eq. 1): "
           << (r.temperature.any() ? "taken out of " + coupling_text(r) : std::string("no channel follows it"))
           << ".\n\n";
    md << "| reading | criterion | parameters | what it says |\n|---|---|---|---|\n";
    for (std::size_t i = 0; i < k.fits.size(); ++i)
        md << "| " << (k.chosen == i ? "**" + k.fits[i].reading + "**" : k.fits[i].reading) << " | "
           << fixed_point(k.fits[i].criterion, 1) << " | " << k.fits[i].parameters << " | "
           << reading_text(r, k.fits[i]) << " |\n";
    md << "\n";
}

nlohmann::json common_to_json(const gap::GapResult& r) {
    const gap::CommonFindings& k = r.common;
    if (!k.compared) return nullptr;
    nlohmann::json shared = nlohmann::json::array(), fits = nlohmann::json::array();
    for (const auto& s : k.shared)
        shared.push_back({{"pair", s.pair}, {"band", s.band}, {"segment", s.part}, {"z", json_number(s.z)}});
    for (const auto& f : k.fits) {
        nlohmann::json channels = nlohmann::json::object();
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (!r.channels[c]) continue;
            const double per_count = 1.0 / gap::counts_per_unit(r.base, static_cast<Channel>(c));
            channels[kChannelNames[c]] = {{"white_counts2", json_number(f.white[c])},
                                          {"loading_counts", json_number(f.loading[c])},
                                          {"loading_unit", json_number(f.loading[c] * per_count)},
                                          {"loaded", f.loaded[c]},
                                          {"own_sd_counts", json_number(f.own_sd[c])},
                                          {"own_tau_s", json_number(f.own_tau[c])}};
        }
        fits.push_back({{"reading", f.reading},
                        {"criterion", json_number(f.criterion)},
                        {"nll", json_number(f.nll)},
                        {"parameters", f.parameters},
                        {"tau_s", json_number(f.tau_s)},
                        {"relative_sd", json_number(f.relative_sd)},
                        {"channels", channels}});
    }
    nlohmann::json temperature = nullptr;
    if (r.temperature.compared) {
        temperature = {{"sd_c", json_number(r.temperature.temperature_sd_c)}, {"channels", nlohmann::json::object()}};
        for (std::size_t c = 0; c < kChannelCount; ++c)
            if (r.channels[c])
                temperature["channels"][kChannelNames[c]] = {
                    {"coefficient_counts_per_c", json_number(r.temperature.coefficient[c])},
                    {"criterion_gain", json_number(r.temperature.gain[c])},
                    {"coupled", r.temperature.coupled[c]}};
    }
    return {{"observations", json_number(k.observations)},
            {"temperature", temperature},
            {"shared_cells", shared},
            {"readings", fits},
            {"chosen", k.winner() ? nlohmann::json(k.winner()->reading) : nlohmann::json(nullptr)},
            {"replaced", k.replaced}};
}

}  // namespace driftlab::host::view
