// The views of the residual's whiteness; see whiteness_view.hpp.
#include "host/view/whiteness_view.hpp"

#include <cstdio>
#include <iostream>

#include "host/view/analysis_notes.hpp"
#include "host/view/analysis_plots.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {

void print_whiteness_table(const fit::FileAnalysis& file) {
    std::cout << file.path << "\n";
    print_file_notes(file, false);
    std::printf("%-10s %9s %9s %8s %11s %9s %11s  %s\n", "channel", "inside", "bound", "M x L", "LB Q(h)", "LB p",
                "tau [smp]", "verdict");
    for (const auto& s : file.series) {
        if (!s.analysis) {
            std::printf("%-10s error: %s\n", s.name.c_str(), s.error.c_str());
            continue;
        }
        const auto& w = s.analysis->whiteness;
        char mxl[32];
        std::snprintf(mxl, sizeof mxl, "%zux%zu", w.sequences_used, w.sequence_samples);
        char q[32];
        std::snprintf(q, sizeof q, "%.2f(%zu)", w.ljung_box.statistic, w.ljung_box.lags);
        std::printf("%-10s %8.1f%% %9.4f %8s %11s %9.3g %11.2f  %s\n", s.name.c_str(), 100.0 * w.fraction_inside,
                    w.bound, mxl, q, w.ljung_box.p_value, w.autocorrelation_time.tau, w.white ? "white" : "NOT white");
        print_analysis_warnings(*s.analysis);
    }
}

nlohmann::json whiteness_json(const stats::WhitenessResult& w, bool arrays) {
    nlohmann::json out = {
        {"fraction_inside", json_number(w.fraction_inside)},
        {"ljung_box_p", json_number(w.ljung_box.p_value)},
        {"white", w.white},
        {"ljung_box_q", json_number(w.ljung_box.statistic)},
        {"ljung_box_lags", w.ljung_box.lags},
        {"bound", json_number(w.bound)},
        {"sequences", w.sequences_used},
        {"sequence_samples", w.sequence_samples},
        {"sequence_length_s", json_number(w.sequence_length_s)},
        {"autocorrelation_time_samples", json_number(w.autocorrelation_time.tau)},
        {"adaptation", w.adaptation},
    };
    if (arrays) {
        std::vector<double> lag_s(w.ensemble_rho.size());
        for (std::size_t d = 0; d < lag_s.size(); ++d) lag_s[d] = static_cast<double>(d) * w.sample_period_s;
        out["ensemble_lag_s"] = json_array(lag_s);
        out["ensemble_autocorrelation"] = json_array(w.ensemble_rho);
        out["autocorrelation"] = json_array(w.rho);
    }
    return out;
}

nlohmann::json whiteness_to_json(const fit::FileAnalysis& file) {
    nlohmann::json out = {{"file", file.path}, {"channels", nlohmann::json::object()}};
    for (const auto& s : file.series)
        out["channels"][s.name] = s.analysis
                                      ? nlohmann::json{{"whiteness", whiteness_json(s.analysis->whiteness, true)},
                                                       {"warnings", s.analysis->warnings}}
                                      : nlohmann::json{{"error", s.error}};
    return out;
}

void write_whiteness_plots(const fit::FileAnalysis& file, const std::string& dir) {
    for (const auto& s : file.series)
        if (s.analysis) render_plot(autocorrelation_plot(*s.analysis), dir, "fig4_" + s.name);
}

}  // namespace driftlab::host::view
