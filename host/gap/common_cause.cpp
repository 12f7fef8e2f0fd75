// Causes shared by channels; see common_cause.hpp.
#include "host/gap/common_cause.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <stdexcept>

#include "host/fit/lm_fit.hpp"
#include "host/gap/whittle.hpp"
#include "host/stats/nelder_mead.hpp"
#include "host/util/parallel_for.hpp"
#include "host/util/real_fft.hpp"
#include "sim/effects/supply_coupling.hpp"

namespace driftlab::host::gap {
namespace {

constexpr int kStartEvaluations = 600;  // Nelder-Mead budget per start of a shared reading (deterministic objective)
constexpr int kOwnEvaluations = 300;    // per start of one channel's own process
// A Nelder-Mead search moves its correlation time at nearly every evaluation: a unit periodogram is seldom met again.
constexpr std::size_t kKeptReadings = 2;
constexpr double kWanderProbeV = 0.05;  // the supply wander a shared_process effect is written with [V]
// How much lower a shared reading's criterion must be than each channel read alone: "positive" evidence (Kass and
// Raftery, JASA 90(430), 1995, on differences of the Schwarz criterion).
constexpr double kSharedMargin = 2.0;

// The channels' differenced residuals in the frequency domain, with what every reading's spectrum is built from. The
// expected periodograms are the finite series' own (its taper and length, whittle.hpp), not the spectral density: a
// differenced series has no power at frequency 0, and the density's zero there would read the taper's leakage as
// a slow process. Every fit (one per thread) keeps its own ExpectedPeriodogram of `geometry`.
struct Spectra {
    std::vector<std::size_t> channels;                 // analysed channel indices
    std::vector<std::vector<std::complex<double>>> x;  // per channel: tapered DFT / sqrt(taper energy), bins 1..m
    PartPeriodogram geometry;                          // the shared length and taper
    std::vector<double> floor_acov;
    std::vector<double> floor;             // the unit white floor's expected periodogram f_j
    double log_floor_sum = 0.0;            // sum_j ln f_j
    std::vector<double> power_over_floor;  // per channel: sum_j |x_j|^2 / f_j
    double dt = 1.0;                       // output period [s]
    double span_s = 1.0;                   // the log's length [s]
    int threads = 1;                       // the fits' independent starts and channels run on this many
};

std::size_t bins(const Spectra& s) { return s.floor.size(); }

// A unit-variance Gauss-Markov process's expected periodogram (correlation time `tau`).
std::vector<double> unit_gm(const Spectra& s, ExpectedPeriodogram& e, double tau) {
    OutputSpectrum m;
    m.ar1 = {{1.0, std::exp(-s.dt / tau)}};
    return e(m);
}

double finite_or_huge(double nll) { return std::isfinite(nll) ? nll : 1e300; }

// A shared reading's spectrum, per channel (Spectra::channels order): a floor and a shared rank-1 part.
struct Reading {
    std::vector<double> white, loading;
    double tau = 0.0;  // the shared part's correlation time
};

// Whittle nll of channel i read alone: sum_j ln d_j + |x_j|^2 / d_j, d_j = w f_j + v o_j (o the own process's unit
// periodogram, none for v = 0: then in closed form from the sums kept in Spectra).
double alone_nll(const Spectra& s, ExpectedPeriodogram& e, std::size_t i, double w, double v, double tau) {
    const std::size_t m = bins(s);
    if (v <= 0.0)
        return finite_or_huge(static_cast<double>(m) * std::log(w) + s.log_floor_sum + s.power_over_floor[i] / w);
    const std::vector<double> o = unit_gm(s, e, tau);
    double nll = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
        const double d = w * s.floor[j] + v * o[j];
        nll += std::log(d) + std::norm(s.x[i][j]) / d;
    }
    return finite_or_huge(nll);
}

// Whittle nll of a shared reading over every channel: sum_j ln det S_j + X_j^H S_j^-1 X_j with S_j = f_j W + g_j L L'
// (W the floors, diagonal; Sherman-Morrison: both closed). With a = W^-1 L, A = L'a and t_j = g_j A / f_j, the floors'
// part sums in closed form and each bin adds ln(1 + t_j) - g_j |a'X_j|^2 / (f_j^2 (1 + t_j)).
double shared_nll(const Spectra& s, ExpectedPeriodogram& e, const Reading& r) {
    const std::size_t k = s.channels.size(), m = bins(s);
    double nll = 0.0, size = 0.0;
    std::vector<double> a(k);
    for (std::size_t c = 0; c < k; ++c) {
        nll += static_cast<double>(m) * std::log(r.white[c]) + s.log_floor_sum + s.power_over_floor[c] / r.white[c];
        a[c] = r.loading[c] / r.white[c];
        size += r.loading[c] * a[c];
    }
    if (size == 0.0) return finite_or_huge(nll);
    const std::vector<double> g = unit_gm(s, e, r.tau);
    for (std::size_t j = 0; j < m; ++j) {
        std::complex<double> u = 0.0;
        for (std::size_t c = 0; c < k; ++c) u += a[c] * s.x[c][j];
        const double gf = g[j] / s.floor[j], t = gf * size;
        nll += std::log1p(t) - gf / s.floor[j] * std::norm(u) / (1.0 + t);
    }
    return finite_or_huge(nll);
}

void transform(Spectra& s, const std::array<const std::vector<double>*, kChannelCount>& residuals,
               const GapModel& model, int threads) {
    s.threads = threads;
    s.dt = model.smoothing.sample_period_s;
    s.floor_acov = white_floor_autocovariance(model.smoothing);
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (residuals[c]) s.channels.push_back(c);
    if (s.channels.size() < 2) throw std::invalid_argument("fit_common: needs two channels or more");
    const std::size_t samples = residuals[s.channels[0]]->size();
    s.span_s = s.dt * static_cast<double>(samples);
    s.geometry = part_periodogram(*residuals[s.channels[0]], std::vector<bool>(samples, true));
    const std::size_t n = s.geometry.length;
    for (std::size_t c : s.channels) {
        const std::vector<double>& r = *residuals[c];
        if (r.size() != samples) throw std::invalid_argument("fit_common: channels of different lengths");
        std::vector<double> d(n);
        for (std::size_t t = 0; t < n; ++t) d[t] = s.geometry.taper[t] * (r[t + 1] - r[t]);
        const std::vector<std::complex<double>> f = half_spectrum(d);
        std::vector<std::complex<double>> x(s.geometry.power.size());
        for (std::size_t j = 0; j < x.size(); ++j) x[j] = f[j + 1] / std::sqrt(s.geometry.taper_energy);
        s.x.push_back(std::move(x));
    }
    OutputSpectrum unit_floor;
    unit_floor.white = 1.0;
    s.floor = ExpectedPeriodogram(s.floor_acov, s.geometry)(unit_floor);
    for (double f : s.floor) s.log_floor_sum += std::log(f);
    for (const auto& x : s.x) {
        double sum = 0.0;
        for (std::size_t j = 0; j < x.size(); ++j) sum += std::norm(x[j]) / s.floor[j];
        s.power_over_floor.push_back(sum);
    }
}

// Correlation times a fit starts from: spread over the log's span.
std::array<double, 3> tau_starts(const Spectra& s) { return {s.span_s / 100.0, s.span_s / 20.0, s.span_s / 5.0}; }

// One channel read alone: its floor, or its floor with an own process, whichever has the lower criterion.
struct ChannelAlone {
    double white = 0.0, own_sd = 0.0, own_tau = 0.0, nll = 0.0, criterion = 0.0;
};

ChannelAlone fit_separate_channel(const Spectra& s, std::size_t i, double price) {
    ExpectedPeriodogram e(s.floor_acov, s.geometry, kKeptReadings);
    const double w = s.power_over_floor[i] / static_cast<double>(bins(s));
    ChannelAlone out;
    out.white = w;
    out.nll = alone_nll(s, e, i, w, 0.0, 1.0);
    out.criterion = 2.0 * out.nll + price;
    for (double tau0 : tau_starts(s)) {
        const auto f = [&](const std::vector<double>& p) {
            return alone_nll(s, e, i, std::exp(p[0]), std::exp(p[1]), std::exp(p[2]));
        };
        const auto nm = stats::nelder_mead(f, {std::log(w * 0.8), std::log(w * 0.5), std::log(tau0)}, {0.3, 1.0, 0.7},
                                           kOwnEvaluations);
        if (2.0 * nm.value + 3.0 * price < out.criterion) {
            out = {std::exp(nm.x[0]), std::sqrt(std::exp(nm.x[1])), std::exp(nm.x[2]), nm.value,
                   2.0 * nm.value + 3.0 * price};
        }
    }
    return out;
}

// The channels alone, one to a thread; summed in channel order.
CommonFit fit_separate(const Spectra& s, double price) {
    std::vector<ChannelAlone> alone(s.channels.size());
    parallel_for(alone.size(), s.threads, [&](std::size_t i) { alone[i] = fit_separate_channel(s, i, price); });
    CommonFit fit;
    fit.reading = kCommonReadings[0];
    for (std::size_t i = 0; i < alone.size(); ++i) {
        const std::size_t c = s.channels[i];
        fit.white[c] = alone[i].white;
        fit.own_sd[c] = alone[i].own_sd;
        fit.own_tau[c] = alone[i].own_tau;
        fit.nll += alone[i].nll;
        fit.parameters += alone[i].own_sd > 0.0 ? 3 : 1;
        fit.channel_criterion[c] = alone[i].criterion;
        fit.criterion += alone[i].criterion;
    }
    return fit;
}

double price_of(const Spectra& s) { return std::log(static_cast<double>(bins(s) * s.channels.size())); }

// A shared reading's parameters: ln w per channel, then the loadings (free: one per channel; ratiometric: one
// coefficient times the DC levels), then ln tau.
Reading shared_reading(const Spectra& s, const std::vector<double>& p, const std::vector<double>& dc) {
    const std::size_t k = s.channels.size();
    Reading r;
    for (std::size_t c = 0; c < k; ++c) r.white.push_back(std::exp(p[c]));
    const bool ratio = p.size() == k + 2;
    for (std::size_t c = 0; c < k; ++c) r.loading.push_back(ratio ? p[k] * dc[c] : p[k + c]);
    r.tau = std::exp(p.back());
    return r;
}

CommonFit to_fit(const Spectra& s, const std::string& reading, const Reading& r, double nll, int parameters,
                 double price) {
    CommonFit fit;
    fit.reading = reading;
    for (std::size_t i = 0; i < s.channels.size(); ++i) {
        fit.white[s.channels[i]] = r.white[i];
        fit.loading[s.channels[i]] = r.loading[i];
    }
    fit.tau_s = r.tau;
    fit.nll = nll;
    fit.parameters = parameters;
    fit.criterion = 2.0 * nll + price * parameters;
    // A channel is loaded when leaving its loading out (its floor refitted) costs more than one parameter's price.
    ExpectedPeriodogram e(s.floor_acov, s.geometry, kKeptReadings);
    for (std::size_t i = 0; i < s.channels.size(); ++i) {
        Reading without = r;
        without.loading[i] = 0.0;
        const auto f = [&](const std::vector<double>& p) {
            Reading t = without;
            t.white[i] = std::exp(p[0]);
            return shared_nll(s, e, t);
        };
        const double refit = stats::nelder_mead(f, {std::log(r.white[i])}, {0.3}, 60).value;
        fit.loaded[s.channels[i]] = 2.0 * (refit - nll) > price;
    }
    return fit;
}

// Nelder-Mead from each start, the starts one to a thread; the best optimum (the first of equals).
stats::NelderMeadResult best_of(const Spectra& s, const std::function<Reading(const std::vector<double>&)>& reading,
                                const std::vector<std::vector<double>>& starts, const std::vector<double>& step) {
    std::vector<stats::NelderMeadResult> runs(starts.size());
    parallel_for(starts.size(), s.threads, [&](std::size_t n) {
        ExpectedPeriodogram e(s.floor_acov, s.geometry, kKeptReadings);
        const auto f = [&](const std::vector<double>& p) { return shared_nll(s, e, reading(p)); };
        // A second pass from the first's optimum: Nelder-Mead's simplex collapses in 2k + 1 dimensions.
        const auto nm = stats::nelder_mead(f, starts[n], step, kStartEvaluations);
        runs[n] = stats::nelder_mead(f, nm.x, step, kStartEvaluations);
    });
    stats::NelderMeadResult best;
    best.value = 1e300;
    for (const auto& nm : runs)
        if (nm.value < best.value) best = nm;
    return best;
}

// Where a free loading starts: each channel's own process (a tenth of its floor without one), signed by its
// low-frequency cross-power with the most variable channel.
std::vector<double> loading_starts(const Spectra& s, const CommonFit& sep) {
    const std::size_t k = s.channels.size();
    std::size_t ref = 0;
    for (std::size_t i = 0; i < k; ++i)
        if (sep.own_sd[s.channels[i]] > sep.own_sd[s.channels[ref]]) ref = i;
    std::vector<double> out;
    for (std::size_t i = 0; i < k; ++i) {
        const std::size_t c = s.channels[i];
        std::complex<double> cross = 0.0;
        for (std::size_t j = 0; j < std::max<std::size_t>(4, bins(s) / 20); ++j)
            cross += s.x[i][j] * std::conj(s.x[ref][j]) / s.floor[j];
        const double size = std::max(sep.own_sd[c], 0.1 * std::sqrt(sep.white[c]));
        out.push_back(cross.real() < 0.0 ? -size : size);
    }
    return out;
}

// The shared reading of lowest criterion that beats `separate` by kSharedMargin and is shared: the ratiometric one by
// construction (its one coefficient loads every channel, so beating each channel read alone, at as many parameters
// as one channel's own process, is the evidence that the others see it), a free one where two channels or more
// are loaded on their own.
std::optional<std::size_t> choose_shared(const std::vector<CommonFit>& fits) {
    std::optional<std::size_t> chosen;
    for (std::size_t i = 1; i < fits.size(); ++i) {
        const auto loaded = std::count(fits[i].loaded.begin(), fits[i].loaded.end(), true);
        const bool shared = fits[i].reading == kCommonReadings[1] || loaded >= 2;
        if (shared && fits[0].criterion - fits[i].criterion > kSharedMargin &&
            (!chosen || fits[i].criterion < fits[*chosen].criterion))
            chosen = i;
    }
    return chosen;
}

}  // namespace

std::vector<double> common_residual(const std::vector<double>& t_s, const std::vector<double>& y,
                                    const std::vector<double>& shapes) {
    std::vector<double> v(y);
    for (std::size_t k = 0; k < v.size() && k < shapes.size(); ++k) v[k] -= shapes[k];
    return fit::fit_drift(t_s, v).residual;
}

CommonFindings fit_common(const std::array<const std::vector<double>*, kChannelCount>& residuals,
                          const std::array<double, kChannelCount>& dc_counts, const GapModel& model, int threads) {
    Spectra s;
    transform(s, residuals, model, threads);
    const std::size_t k = s.channels.size();
    CommonFindings out;
    out.compared = true;
    out.observations = static_cast<double>(bins(s) * k);
    const double price = price_of(s);
    out.fits.push_back(fit_separate(s, price));
    const CommonFit sep = out.fits[0];  // a copy: the readings pushed after it move the vector

    std::vector<double> dc;
    for (std::size_t c : s.channels) dc.push_back(dc_counts[c]);
    const std::vector<double> start_loading = loading_starts(s, sep);
    double ratio0 = 0.0, dc2 = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
        ratio0 += start_loading[i] * dc[i];
        dc2 += dc[i] * dc[i];
    }
    ratio0 /= dc2;

    const auto reading_of = [&](const std::vector<double>& p) { return shared_reading(s, p, dc); };
    std::vector<double> step(k, 0.3);
    // The ratiometric reading: one coefficient.
    std::vector<std::vector<double>> starts;
    for (double tau0 : tau_starts(s)) {
        std::vector<double> p;
        for (std::size_t i = 0; i < k; ++i) p.push_back(std::log(sep.white[s.channels[i]]));
        p.push_back(ratio0);
        p.push_back(std::log(tau0));
        starts.push_back(p);
    }
    std::vector<double> ratio_step = step;
    ratio_step.push_back(std::max(std::abs(ratio0), 1e-6) * 0.5);
    ratio_step.push_back(0.7);
    const auto ratio = best_of(s, reading_of, starts, ratio_step);
    out.fits.push_back(
        to_fit(s, kCommonReadings[1], shared_reading(s, ratio.x, dc), ratio.value, static_cast<int>(k) + 2, price));
    out.fits.back().relative_sd = std::abs(ratio.x[k]);

    // The free reading: from the ratiometric optimum and from the channels' own processes.
    std::vector<std::vector<double>> free_starts(2);
    for (std::size_t i = 0; i < k; ++i) {
        free_starts[0].push_back(ratio.x[i]);
        free_starts[1].push_back(starts[1][i]);
    }
    for (std::size_t i = 0; i < k; ++i) {
        free_starts[0].push_back(ratio.x[k] * dc[i]);
        free_starts[1].push_back(start_loading[i]);
    }
    free_starts[0].push_back(ratio.x.back());
    free_starts[1].push_back(starts[1].back());
    std::vector<double> free_step = step;
    for (std::size_t i = 0; i < k; ++i)
        free_step.push_back(std::max(std::abs(start_loading[i]), 0.1 * std::sqrt(sep.white[s.channels[i]])) * 0.5);
    free_step.push_back(0.7);
    const auto free = best_of(s, reading_of, free_starts, free_step);
    out.fits.push_back(
        to_fit(s, kCommonReadings[2], shared_reading(s, free.x, dc), free.value, 2 * static_cast<int>(k) + 1, price));

    out.chosen = choose_shared(out.fits);
    return out;
}

SeparateReading read_channels_alone(const std::array<const std::vector<double>*, kChannelCount>& residuals,
                                    const GapModel& model, int threads) {
    Spectra s;
    transform(s, residuals, model, threads);
    return {fit_separate(s, price_of(s)), price_of(s)};
}

std::vector<SharedBand> shared_bands(const std::vector<LocatedCell>& located, const std::vector<Cell>& layout) {
    std::vector<SharedBand> out;
    for (const auto& l : located) {
        const Cell& c = layout[l.index];
        if (c.statistic == "coh" || c.statistic == "corr")
            out.push_back({c.channel, c.shown(), segment_name(c.segment), l.z});
    }
    return out;
}

sim::EffectSpec common_effect(const CommonFit& fit, const GapModel& model) {
    sim::EffectSpec spec;
    spec.name = "supply_coupling";
    toml::table& t = spec.table;
    const double volts_per_count = model.unit.adc.vref_v / std::ldexp(1.0, model.unit.adc.bits);
    const double v_nom = sim::SupplyCouplingParams{}.nominal_supply_v;
    toml::array ratiometric, pickup;
    if (fit.reading == kCommonReadings[1]) {
        // Sensors on their own reference, the converter on the supply: each channel moves by -v dV / V_nom.
        for (std::size_t c = 0; c < kChannelCount; ++c) ratiometric.push_back(0.0);
        t.insert_or_assign("sensor_ratiometric", ratiometric);
        t.insert_or_assign("adc_ratiometric", 1.0);
        t.insert_or_assign("wander_v", fit.relative_sd * v_nom);
    } else {
        // Matched references (no ratiometric path): each channel picks the wander up with its own coefficient.
        for (std::size_t c = 0; c < kChannelCount; ++c)
            pickup.push_back(fit.loading[c] * volts_per_count / kWanderProbeV);
        t.insert_or_assign("pickup_v_per_v", pickup);
        t.insert_or_assign("wander_v", kWanderProbeV);
    }
    t.insert_or_assign("wander_tau_s", fit.tau_s);
    return spec;
}

}  // namespace driftlab::host::gap
