// The JSON of the drift fit; see fit_view.hpp and docs/analysis.md §5.
#include "host/util/units.hpp"
#include "host/view/fit_view.hpp"
#include "host/view/json_out.hpp"
#include "host/view/whiteness_view.hpp"

namespace driftlab::host::view {
namespace {

nlohmann::json estimate_json(const fit::Estimate& plain, const fit::Estimate& widened) {
    return {{"value", json_number(plain.value)},
            {"stderr", json_number(plain.stderr_)},
            {"ci95", {json_number(plain.ci95[0]), json_number(plain.ci95[1])}},
            {"stderr_widened", json_number(widened.stderr_)},
            {"ci95_widened", {json_number(widened.ci95[0]), json_number(widened.ci95[1])}}};
}

}  // namespace

nlohmann::json fit_json(const fit::DriftAnalysis& a) {
    const fit::FitResult& f = a.fit;
    nlohmann::json out = {
        {"C1", estimate_json(a.plain.c1, a.widened.c1)},
        {"C2", estimate_json(a.plain.c2, a.widened.c2)},
        {"T", estimate_json(a.plain.t_s, a.widened.t_s)},
        {"initial_slope", estimate_json(a.plain.initial_slope, a.widened.initial_slope)},
        {"unit", a.data.unit},
        {"status", fit::fit_status_name(f.status)},
        {"solver_stop", f.solver_stop},
        {"iterations", f.iterations},
        {"n", f.n},
        {"rms", json_number(f.rms)},
        {"t_first_s", json_number(a.data.t_s.front())},
        {"t_last_s", json_number(a.data.t_s.back())},
        {"sample_period_s", json_number(a.sample_period_s)},
        {"time_gaps", a.time_gaps},
        {"interval_inflation", json_number(a.widened.inflation)},
        {"whiteness", whiteness_json(a.whiteness, false)},
        {"warnings", a.warnings},
    };
    if (a.data.channel) {
        const Channel c = *a.data.channel;
        out["physical"] = {
            {"unit", physical_unit(c).name},
            {"C1", json_number(counts_to_physical(c, a.plain.c1.value))},
            {"C1_stderr", json_number(counts_to_physical(c, a.plain.c1.stderr_))},
            {"C2_offset_from_mid_scale", json_number(level_to_physical(c, a.plain.c2.value))},
            {"C2_stderr", json_number(counts_to_physical(c, a.plain.c2.stderr_))},
            {"rms", json_number(counts_to_physical(c, f.rms))},
        };
    }
    return out;
}

nlohmann::json fit_to_json(const fit::FileAnalysis& file) {
    nlohmann::json out = {{"file", file.path}, {"channels", nlohmann::json::object()}};
    for (const auto& s : file.series)
        out["channels"][s.name] = s.analysis ? fit_json(*s.analysis) : nlohmann::json{{"error", s.error}};
    return out;
}

}  // namespace driftlab::host::view
