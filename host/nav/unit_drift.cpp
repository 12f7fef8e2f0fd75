#include "host/nav/unit_drift.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "host/fit/allan_pipeline.hpp"
#include "host/fit/drift_analysis.hpp"
#include "host/stats/noise_terms.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"
#include "host/util/input_file.hpp"

namespace driftlab::host::nav {

using nlohmann::json;

double flicker_walk_psd(double b, double tau_s) {
    const double floor = stats::kBiasInstabilityFactor * b;
    return 3.0 * floor * floor / tau_s;
}

double AxisModel::bias_walk_psd() const {
    double q = rate_random_walk * rate_random_walk;
    if (bias_instability > 0.0 && bias_instability_tau_s > 0.0)
        q += flicker_walk_psd(bias_instability, bias_instability_tau_s);
    return q;
}

namespace {

// A resolved term's value, else 0: an unresolved term (std_error null) is a bound, not a measurement.
double resolved(const json& terms, const char* key) {
    if (!terms.contains(key)) return 0.0;
    const json& t = terms[key];
    if (!t.contains("std_error") || t["std_error"].is_null() || !t["value"].is_number()) return 0.0;
    return t["value"].get<double>();
}

double number_at(const json& j, const std::string& path, const std::string& file, const std::string& where) {
    const json::json_pointer p(path);
    if (!j.contains(p) || !j[p].is_number())
        throw DataError(file, 0,
                        where + ": no number at " + path + " (is this the output of fit --json or allan --json?)");
    return j[p].get<double>();
}

// A JSON array of numbers, null (a value that was not finite) as NaN.
std::vector<double> numbers(const json& a) {
    std::vector<double> out;
    for (const json& v : a) out.push_back(v.is_number() ? v.get<double>() : NAN);
    return out;
}

// The averaging time of the smallest ADEV: where the flicker floor B shows.
double tau_of_minimum(const std::vector<double>& tau, const std::vector<double>& adev) {
    double best = INFINITY, at = 0.0;
    for (std::size_t i = 0; i < std::min(tau.size(), adev.size()); ++i)
        if (std::isfinite(adev[i]) && adev[i] < best) best = adev[i], at = tau[i];
    return at;
}

AxisModel axis_from_fit_json(const json& c, const std::string& file, const std::string& name) {
    AxisModel a;
    a.drift = {number_at(c, "/C1/value", file, name), number_at(c, "/C2/value", file, name),
               number_at(c, "/T/value", file, name)};
    a.drift_sd_counts = number_at(c, "/C2/stderr_widened", file, name);
    a.white_density = number_at(c, "/rms", file, name) * std::sqrt(number_at(c, "/sample_period_s", file, name));
    return a;
}

AxisModel axis_from_allan_json(const json& c, const std::string& file, const std::string& name) {
    AxisModel a;
    if (!c.contains("drift"))
        throw DataError(file, 0, name + ": no eq. 1 drift (allan ran without removing it: drop --keep-drift)");
    a.drift = {number_at(c, "/drift/C1", file, name), number_at(c, "/drift/C2", file, name),
               number_at(c, "/drift/T_s", file, name)};
    if (!c.contains("terms") || c["terms"].is_null()) throw DataError(file, 0, name + ": no noise terms were fitted");
    const json& terms = c["terms"];
    a.white_density = resolved(terms, "N");
    if (a.white_density <= 0.0) throw DataError(file, 0, name + ": the white noise N is not resolved");
    a.bias_instability = resolved(terms, "B");
    a.rate_random_walk = resolved(terms, "K");
    if (c.contains("tau") && c.contains("adev"))
        a.bias_instability_tau_s = tau_of_minimum(numbers(c["tau"]), numbers(c["adev"]));
    a.walks_known = true;
    return a;
}

}  // namespace

UnitDrift read_unit_drift(const std::string& path) {
    const std::string text = read_small_file(path, kMaxJsonFileBytes);
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        throw DataError(path, 0,
                        "not JSON (byte " + std::to_string(e.byte) + "): give what fit --json or allan --json print");
    }
    if (!j.is_object() || !j.contains("channels") || !j["channels"].is_object())
        throw DataError(path, 0, "no 'channels' object: give what fit --json or allan --json print");
    UnitDrift u;
    u.source = path;
    bool walks = true;
    for (std::size_t k = 0; k < kNavAxes; ++k) {
        const std::string name = kChannelNames[channel_index(kNavChannels[k])];
        if (!j["channels"].contains(name)) {
            if (k == 0) throw DataError(path, 0, "no channel 'gyro': navigation needs at least the gyro");
            u.axes[k].present = false;  // a gyro-only recording: heading only
            continue;
        }
        const json& c = j["channels"][name];
        if (c.contains("error")) throw DataError(path, 0, name + ": the fit failed there: " + c["error"].dump());
        u.axes[k] = c.contains("C1") ? axis_from_fit_json(c, path, name) : axis_from_allan_json(c, path, name);
        walks = walks && u.axes[k].walks_known;
    }
    if (!walks)
        u.notes.push_back(
            "a fit file has no Allan terms: the filters' white noise is the fit's residual rms and their biases do not "
            "walk (give allan --json, or --fit-from a rest log, for bias instability and rate random walk)");
    return u;
}

UnitDrift fit_unit_drift(const LogData& rest, double from_s, double to_s) {
    UnitDrift u;
    u.source = rest.source_name;
    std::vector<double> t;
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < rest.size(); ++i)
        if (rest.t_s[i] >= from_s && rest.t_s[i] <= to_s) t.push_back(rest.t_s[i]), rows.push_back(i);
    if (t.size() < 16) throw DataError(rest.source_name, 0, "fewer than 16 rows to fit the unit's drift on");
    const double tau0 = stats::mean_spacing_s(t);
    for (std::size_t k = 0; k < kNavAxes; ++k) {
        const Channel c = kNavChannels[k];
        if (!rest.recorded[channel_index(c)]) {
            if (k == 0) throw DataError(rest.source_name, 0, "no gyro channel to fit the unit's drift on");
            u.axes[k].present = false;
            continue;
        }
        std::vector<double> v;
        v.reserve(rows.size());
        for (const std::size_t i : rows) v.push_back(rest.channel(c)[i]);
        const fit::AllanResult r = fit::analyse_allan(t, v, tau0, fit::AllanRequest{});
        if (!r.drift || !r.drift_removed || !r.drift_removed->terms.ok)
            throw DataError(rest.source_name, 0,
                            std::string(kChannelNames[channel_index(c)]) + ": eq. 1 could not be fitted (" +
                                r.drift_status_words() + ")");
        AxisModel& a = u.axes[k];
        a.drift = *r.drift;
        // C2's standard error, widened for a residual that is not white, as fit --json prints it.
        fit::Series s{kChannelNames[channel_index(c)], rest.source_name, "counts", c, t, 0.0, v, {}};
        a.drift_sd_counts = fit::analyse_drift(s).widened.c2.stderr_;
        const stats::NoiseTermFit& terms = r.drift_removed->terms;
        const auto term = [&terms](stats::NoiseTerm n) {
            const auto i = static_cast<std::size_t>(n);
            return terms.at_bound[i] ? 0.0 : terms.value[i];
        };
        a.white_density = term(stats::NoiseTerm::random_walk);
        a.bias_instability = term(stats::NoiseTerm::bias_instability);
        a.rate_random_walk = term(stats::NoiseTerm::rate_random_walk);
        const stats::DeviationCurve& adev = r.drift_removed->curves.front().curve;
        a.bias_instability_tau_s = tau_of_minimum(adev.tau_s, adev.dev);
        a.walks_known = true;
        if (a.white_density <= 0.0)
            throw DataError(rest.source_name, 0,
                            std::string(kChannelNames[channel_index(c)]) + ": its white noise is not resolved");
    }
    return u;
}

}  // namespace driftlab::host::nav
