// The views of the Allan analysis; see allan_view.hpp.
#include "host/view/allan_view.hpp"

#include <cmath>
#include <cstdio>

#include "host/view/gnuplot.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {
namespace {

using nlohmann::json;

json curve_json(const stats::AnalysedCurve& c, const char* dev_key) {
    json j;
    j["tau"] = json_array(c.curve.tau_s);
    j[dev_key] = json_array(c.curve.dev);
    j["ci_low"] = json_array(c.ci_low);
    j["ci_high"] = json_array(c.ci_high);
    j["noise"] = c.alpha;
    j["noise_identified"] = c.alpha_identified;
    j["n"] = c.curve.n;
    j["n_skipped"] = c.curve.n_skipped;
    j["edf"] = json_array(c.edf);
    return j;
}

json terms_json(const stats::NoiseTermFit& t, const stats::SampleUnit& u) {
    if (!t.ok) return nullptr;
    const std::string& U = u.name;
    const char* units[stats::kNoiseTermCount] = {"*s", "/sqrt(Hz)", "", "/sqrt(s)", "/s"};
    json j = {{"unit", U},
              {"model", "AVAR = 3Q^2/tau^2 + N^2/tau + (2 ln2/pi) B^2 + K^2 tau/3 + R^2 tau^2/2"},
              {"bias_instability_factor", stats::kBiasInstabilityFactor}};
    for (std::size_t k = 0; k < stats::kNoiseTermCount; ++k) {
        // A term pinned at 0 keeps its value 0 for readers of `value`; the null error and the bound say it is
        // not a measured zero.
        json term = {{"value", json_number(t.value[k])},
                     {"std_error", t.at_bound[k] ? json(nullptr) : json_number(t.std_error[k])},
                     {"unit", U + units[k]}};
        if (t.at_bound[k]) term["upper_bound"] = json_number(t.upper_bound[k]);
        j[stats::kNoiseTermSymbols[k]] = term;
    }
    // An unresolved term's NamedValue::value is NaN: null here, never a 0 to paste into a filter's configuration.
    json phys = json::object();
    for (const auto& nv : stats::physical_terms(t, u.quantity, u.si_per_unit)) phys[nv.key] = json_number(nv.value);
    j["physical"] = phys;
    return j;
}

json version_json(const fit::AllanCurves& v, const stats::SampleUnit& u) {
    json j = curve_json(v.curves.front(), "adev");
    if (const auto* m = v.find(stats::Deviation::mdev)) j["mdev"] = curve_json(*m, "dev");
    if (const auto* h = v.find(stats::Deviation::ohdev)) j["hdev"] = curve_json(*h, "dev");
    j["terms"] = terms_json(v.terms, u);
    json k = json::object();
    for (const auto& nv : stats::kalibr_densities(v.terms, u.quantity, u.si_per_unit))
        k[nv.key] = json_number(nv.value);
    j["kalibr"] = k.empty() ? json(nullptr) : k;
    return j;
}

void print_named(const char* prefix, const stats::NamedValue& nv) {
    const int width = 26 - static_cast<int>(std::string(prefix).size());
    if (nv.resolved)
        std::printf("      %s%-*s %.5g\n", prefix, width, nv.key.c_str(), nv.value);
    else
        std::printf("      %s%-*s not resolved (<= %.5g)\n", prefix, width, nv.key.c_str(), nv.upper_bound);
}

// The table's n hides what the gaps cost: from the first tau where they skip more than 20 % of the terms, say so
// and why the curve may end early (JSON has n_skipped per tau).
void print_skipped_note(const stats::DeviationCurve& c, double longest_gap_free_s) {
    constexpr double kNotable = 0.2;
    const auto share = [&](std::size_t i) {
        const auto all = static_cast<double>(c.n[i] + c.n_skipped[i]);
        return all > 0.0 ? static_cast<double>(c.n_skipped[i]) / all : 0.0;
    };
    std::size_t first = 0;
    while (first < c.m.size() && share(first) <= kNotable) ++first;
    if (first == c.m.size()) return;
    std::size_t most = first;
    for (std::size_t i = first; i < c.m.size(); ++i)
        if (share(i) > share(most)) most = i;
    std::printf(
        "    note: gaps skip more than 20 %% of the terms from tau = %.5g s on (%.0f %% at tau = %.5g s); the longest "
        "gap-free stretch is %.5g s, and a term spans 2 tau (3 tau for mdev and hdev)\n",
        c.tau_s[first], 100.0 * share(most), c.tau_s[most], longest_gap_free_s);
}

void print_version(const char* title, const fit::AllanCurves& v, const stats::SampleUnit& u,
                   double longest_gap_free_s) {
    std::printf("  %s\n", title);
    for (const auto& c : v.curves) {
        std::printf("    %-6s %12s %10s %5s %12s %12s %12s\n", std::string(stats::deviation_name(c.curve.type)).c_str(),
                    "tau [s]", "n", "alpha", "low", "dev", "high");
        for (std::size_t i = 0; i < c.curve.m.size(); ++i) {
            std::printf("    %-6s %12.5g %10lld %5d %12.5g %12.5g %12.5g\n", "", c.curve.tau_s[i],
                        static_cast<long long>(c.curve.n[i]), c.alpha[i], c.ci_low[i], c.curve.dev[i], c.ci_high[i]);
        }
        print_skipped_note(c.curve, longest_gap_free_s);
    }
    if (!v.terms.ok) return;
    const char* units[stats::kNoiseTermCount] = {"*s", "/sqrt(Hz)", " (ADEV floor = 0.664 B)", "/sqrt(s)", "/s"};
    const char* bound_units[stats::kNoiseTermCount] = {"*s", "/sqrt(Hz)", ", the ADEV minimum / 0.664", "/sqrt(s)",
                                                       "/s"};
    std::printf("    IEEE 952 terms [%s]:", u.name.c_str());
    for (std::size_t k = 0; k < stats::kNoiseTermCount; ++k) {
        if (v.terms.at_bound[k])
            std::printf(" %s not resolved (<= %.4g%s)", stats::kNoiseTermSymbols[k], v.terms.upper_bound[k],
                        bound_units[k]);
        else
            std::printf(" %s = %.4g%s", stats::kNoiseTermSymbols[k], v.terms.value[k], units[k]);
        std::printf("%s", k + 1 < stats::kNoiseTermCount ? "," : "\n");
    }
    for (const auto& nv : stats::physical_terms(v.terms, u.quantity, u.si_per_unit)) print_named("", nv);
    for (const auto& nv : stats::kalibr_densities(v.terms, u.quantity, u.si_per_unit)) print_named("kalibr ", nv);
}

Plot allan_plot(const std::string& name, const fit::AllanResult& r, const stats::SampleUnit& u) {
    Plot p;
    p.title = "Allan deviation: " + name;
    p.x_label = "tau [s]";
    p.y_label = "overlapping ADEV [" + u.name + "]";
    p.log_x = p.log_y = true;
    const fit::AllanCurves& main = r.primary();
    const stats::AnalysedCurve& c = main.curves.front();
    PlotSeries band{r.drift_removed ? "drift removed (68 % CI)" : "ADEV (68 % CI)",
                    c.curve.tau_s,
                    c.curve.dev,
                    c.ci_low,
                    c.ci_high,
                    SeriesStyle::error_bars,
                    false,
                    "#1f77b4",
                    1.5};
    p.series.push_back(band);
    if (r.drift_removed) {
        const auto& raw = r.raw.curves.front();
        p.series.push_back(
            {"raw (with drift)", raw.curve.tau_s, raw.curve.dev, {}, {}, SeriesStyle::lines, false, "#7f7f7f", 1.5});
    }
    if (main.terms.ok) {
        p.series.push_back(
            {"IEEE 952 fit", c.curve.tau_s, main.terms.model_adev, {}, {}, SeriesStyle::lines, false, "#d62728", 2.0});
        for (std::size_t k = 0; k < stats::kNoiseTermCount; ++k) {
            if (main.terms.value[k] <= 0.0) continue;
            std::array<double, stats::kNoiseTermCount> only{};
            only[k] = main.terms.value[k];
            std::vector<double> y;
            for (double t : c.curve.tau_s) y.push_back(std::sqrt(stats::noise_term_avar(only, t)));
            p.series.push_back({std::string(stats::kNoiseTermSymbols[k]) + " term",
                                c.curve.tau_s,
                                y,
                                {},
                                {},
                                SeriesStyle::lines,
                                true,
                                "",
                                1.0});
        }
    }
    return p;
}

}  // namespace

nlohmann::json allan_json(const fit::AllanSeriesResult& s) {
    const fit::AllanResult& r = s.result;
    json c = version_json(r.primary(), s.unit);
    c["tau0_s"] = s.tau0_s;
    c["samples"] = r.samples;
    c["t_first_s"] = s.t_first_s;  // as fit gives them: the rows --from/--to kept
    c["t_last_s"] = s.t_last_s;
    c["gap_samples"] = r.gap_samples;
    c["packed_samples"] = r.packed_samples;
    c["packed_most_slots"] = r.packed_most_slots;
    c["packing_warning"] = s.packing_warning ? json(*s.packing_warning) : json(nullptr);
    c["lone_values_warning"] = s.lone_values_warning ? json(*s.lone_values_warning) : json(nullptr);
    c["drift_removed"] = r.drift_removed.has_value();
    c["drift_status"] = r.drift_status_name();
    if (r.drift) c["drift"] = {{"C1", r.drift->c1}, {"C2", r.drift->c2}, {"T_s", r.drift->t_s}};
    if (r.drift_removed) c["raw"] = version_json(r.raw, s.unit);
    return c;
}

void print_allan_text(const std::string& path, const fit::AllanSeriesResult& s) {
    const fit::AllanResult& r = s.result;
    std::printf("%s: %s, tau0 = %.6g s, %zu samples, %zu gap samples, drift: %s\n", path.c_str(), s.name.c_str(),
                s.tau0_s, r.samples, r.gap_samples,
                r.drift_removed ? "removed (eq. 1)" : r.drift_status_words().c_str());
    if (s.lone_values_warning) std::printf("  warning: %s\n", s.lone_values_warning->c_str());
    if (s.packing_warning) std::printf("  warning: %s\n", s.packing_warning->c_str());
    if (r.drift_removed) print_version("drift removed", *r.drift_removed, s.unit, r.longest_gap_free_s);
    print_version(r.drift_removed ? "raw" : "as given", r.raw, s.unit, r.longest_gap_free_s);
}

void write_allan_plot(const fit::AllanSeriesResult& s, const std::string& dir) {
    render_plot(allan_plot(s.name, s.result, s.unit), dir, "allan_" + s.name);
}

}  // namespace driftlab::host::view
