// Whittle fits of the Gaussian noise candidates; see spectral_fit.hpp.
#include "host/gap/spectral_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "host/gap/candidates.hpp"
#include "host/stats/nelder_mead.hpp"
#include "sim/effects/flicker.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kRefineEvaluationsPerParameter = 80;

// The white-floor variance that makes the floor alone match the periodogram from frequency index `from` up.
double floor_only_white(const PartPeriodogram& p, const std::vector<double>& unit_floor, std::size_t from) {
    double sum = 0.0;
    for (std::size_t j = from; j < p.power.size(); ++j) sum += p.power[j] / unit_floor[j];
    return sum / static_cast<double>(p.power.size() - from);
}

// The flicker candidate's Gauss-Markov components, as the library builds them for the candidate's band.
std::vector<double> flicker_taus(Channel c, const GapModel& model) {
    const sim::EffectSpec spec = make_candidate_effect("flicker", c, {1.0}, model);
    sim::FlickerParams fp;
    fp.f_low_hz = spec.table["f_low_hz"].value_or(fp.f_low_hz);
    fp.f_high_hz = spec.table["f_high_hz"].value_or(fp.f_high_hz);
    return sim::Flicker(fp).component_tau_s();
}

std::size_t param_count(const std::string& effect) { return candidate(effect).param_keys.size(); }

// Starting values of one effect's parameters (physical units) over its plausible range, given the output's white
// standard deviation `out_sd` in the channel's unit and the part's span.
std::vector<std::vector<double>> start_grid(const std::string& effect, double out_sd, double dt, double span) {
    std::vector<std::vector<double>> g;
    if (effect == "gauss_markov") {
        for (double tau = 2.0 * dt; tau < 4.0 * span; tau *= 4.0)
            for (double s : {0.1, 0.3, 1.0, 3.0}) g.push_back({s * out_sd, tau});
    } else if (effect == "flicker") {
        for (double s : {0.03, 0.1, 0.3, 1.0, 3.0}) g.push_back({s * out_sd});
    } else {
        for (double s : {0.003, 0.01, 0.03, 0.1, 0.3}) g.push_back({s * out_sd / std::sqrt(dt)});
    }
    return g;
}

}  // namespace

OutputSpectrum model_spectrum(const std::vector<std::string>& effects, Channel c, const std::vector<double>& params,
                              const GapModel& model, double white) {
    OutputSpectrum s;
    s.white = white;
    const double cpu = counts_per_unit(model, c);
    const double dt = model.smoothing.sample_period_s;
    std::size_t k = 0;
    for (const std::string& effect : effects) {
        if (effect == "gauss_markov") {
            s.ar1.push_back({std::pow(params.at(k) * cpu, 2), std::exp(-dt / params.at(k + 1))});
        } else if (effect == "flicker") {
            const double v = std::pow(params.at(k) * cpu * sim::Flicker::component_sigma_per_b(), 2);
            for (double tau : flicker_taus(c, model)) s.ar1.push_back({v, std::exp(-dt / tau)});
        } else if (effect == "rate_random_walk") {
            s.walk_increment_variance += std::pow(params.at(k) * cpu, 2) * dt;
        } else {
            throw std::invalid_argument("not a spectral candidate: " + effect);
        }
        k += param_count(effect);
    }
    const HeldNoise& held = model.held[channel_index(c)];
    for (const auto& g : held.gauss_markov) s.ar1.push_back({g.variance_counts2, std::exp(-dt / g.tau_s)});
    s.walk_increment_variance += held.walk_counts2_per_s * dt;
    return s;
}

SpectralFit fit_spectral(const std::vector<std::string>& effects, Channel c, const GapModel& model,
                         const PartPeriodogram& p, const std::vector<double>& known) {
    const std::vector<double> floor_acov = white_floor_autocovariance(model.smoothing);
    // Between evaluations only the sizes and the Gauss-Markov time constants move: the unit periodograms of the
    // model's components (the held ones among them) and two more are all worth keeping, each half the log's length.
    std::size_t params = 0;
    for (const std::string& effect : effects) params += param_count(effect);
    const std::size_t components = model_spectrum(effects, c, std::vector<double>(params, 1.0), model, 1.0).ar1.size();
    ExpectedPeriodogram expected(floor_acov, p, components + 2);
    const std::vector<double> unit_floor = expected({1.0, {}, 0.0});
    SpectralFit out;
    out.effects = effects;
    const HeldNoise& held = model.held[channel_index(c)];
    if (effects.empty() && held.gauss_markov.empty() && held.walk_counts2_per_s == 0.0) {
        out.white = floor_only_white(p, unit_floor, 0);
        out.nll = whittle_nll(p, expected({out.white, {}, 0.0}));
        return out;
    }
    if (effects.empty()) {  // the floor beside the model file's processes
        const auto nll_at = [&](const std::vector<double>& ln_white) {
            return whittle_nll(p, expected(model_spectrum({}, c, {}, model, std::exp(ln_white[0]))));
        };
        const auto nm = stats::nelder_mead(nll_at, {std::log(floor_only_white(p, unit_floor, p.power.size() / 2))},
                                           {0.5}, kRefineEvaluationsPerParameter);
        out.white = std::exp(nm.x[0]);
        out.nll = nm.value;
        return out;
    }
    const double cpu = counts_per_unit(model, c);
    const double dt = model.smoothing.sample_period_s;
    const double span = dt * static_cast<double>(p.length);
    // Starting scales: the white floor from the upper half of the band (where slow noise has least power), and
    // the output's white standard deviation in the channel's physical unit.
    const double white0 = floor_only_white(p, unit_floor, p.power.size() / 2);
    const double out_sd = std::sqrt(white0 * floor_acov[0]) / cpu;
    // Log-parameters; a correlation time is kept within [dt/2, 100 spans] (beyond it a Gauss-Markov process is a
    // random walk, below it white noise: the likelihood is flat there).
    const double ln_tau_lo = std::log(0.5 * dt), ln_tau_hi = std::log(100.0 * span);
    auto params_of = [&](const std::vector<double>& x) {
        std::vector<double> q(x.size() - 1);
        std::size_t k = 1;
        for (const std::string& effect : effects) {
            q[k - 1] = std::exp(x[k]);
            if (effect == "gauss_markov") q[k] = std::exp(std::clamp(x[k + 1], ln_tau_lo, ln_tau_hi));
            k += param_count(effect);
        }
        return q;
    };
    auto nll_at = [&](const std::vector<double>& x) {
        return whittle_nll(p, expected(model_spectrum(effects, c, params_of(x), model, std::exp(x[0]))));
    };
    std::vector<double> earlier;  // log-parameters of all effects but the last
    for (std::size_t e = 0, k = 0; e + 1 < effects.size(); ++e) {
        const auto defaults = start_grid(effects[e], out_sd, dt, span);
        for (std::size_t i = 0; i < param_count(effects[e]); ++i, ++k)
            earlier.push_back(std::log(k < known.size() ? known[k] : defaults[defaults.size() / 2][i]));
    }
    std::vector<double> best;
    double best_value = INFINITY;
    // Both floors at one start together: they share its time constant's unit periodogram.
    for (const auto& s : start_grid(effects.back(), out_sd, dt, span)) {
        for (double w : {1.0, 0.7}) {
            std::vector<double> x{std::log(w * white0)};
            x.insert(x.end(), earlier.begin(), earlier.end());
            for (double v : s) x.push_back(std::log(v));
            const double value = nll_at(x);
            if (value < best_value) best_value = value, best = x;
        }
    }
    const auto nm = stats::nelder_mead(nll_at, best, std::vector<double>(best.size(), 0.5),
                                       kRefineEvaluationsPerParameter * static_cast<int>(best.size()));
    out.white = std::exp(nm.x[0]);
    out.params = params_of(nm.x);
    out.nll = nm.value;
    out.free_parameters = static_cast<int>(nm.x.size());
    return out;
}

double spectral_nll(const SpectralFit& fit, Channel c, const GapModel& model, const PartPeriodogram& p,
                    std::vector<double>* terms) {
    return whittle_nll(p,
                       expected_periodogram(model_spectrum(fit.effects, c, fit.params, model, fit.white),
                                            white_floor_autocovariance(model.smoothing), p),
                       terms);
}

const char* criterion_name(InformationCriterion ic) { return ic == InformationCriterion::aic ? "aic" : "bic"; }

double parameter_price(InformationCriterion ic, double observations) {
    return ic == InformationCriterion::aic ? 2.0 : std::log(observations);
}

}  // namespace driftlab::host::gap
