// Shared helpers of the effect tests: drive an effect over a uniform time grid, and independent estimators
// (overlapping Allan variance, least-squares tone fit, moments) written from their textbook definitions.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "sim/effects/effect.hpp"

namespace driftlab::sim::test {

/// Per-channel series of what an effect adds to a zero input over n instants dt_s apart (all four channels per
/// instant, first instant at t = 0 with dt = 0).
inline std::vector<std::vector<double>> run_added(Effect& effect, std::size_t n, double dt_s,
                                                  const ChannelValues& input = {},
                                                  const ChannelValues& true_physical = {}) {
    std::vector<std::vector<double>> out(kChannelCount, std::vector<double>(n));
    EffectContext ctx;
    ctx.true_physical = true_physical;
    for (std::size_t k = 0; k < n; ++k) {
        ctx.t_s = static_cast<double>(k) * dt_s;
        ctx.dt_s = k == 0 ? 0.0 : dt_s;
        ChannelValues v = input;
        effect.apply(v, ctx);
        for (std::size_t c = 0; c < kChannelCount; ++c) out[c][k] = v[c] - input[c];
    }
    return out;
}

// One non-default configuration per effect (also the examples of docs/effects.md).
inline const std::map<std::string, std::string> kEffectExamples = {
    {"thermal_second_tc", "c3_dps = 0.2\nc3_g = [0.004, -0.003, 0.01]\nt2_s = 2400.0"},
    {"ambient_cycle",
     "waveform = \"square\"\namplitude_k_pp = 1.5\nperiod_s = 1800.0\nlag_s = 400.0\n"
     "coupling_dps_per_k = 0.03\ncoupling_g_per_k = [0.001, 0.001, 0.002]"},
    {"scale_factor", "error_pct = [1.5, -0.8, 0.5, 2.0]"},
    {"bandwidth", "cutoff_hz = [7.0, 20.0, 20.0, 20.0]"},
    {"temp_scale_factor", "scale_pct_per_k = [0.03, 0.01, 0.01, 0.02]\nreference_degc = 25.0"},
    {"flicker", "b_dps = 0.03\nb_g = 0.0005\nf_low_hz = 0.0005\nf_high_hz = 1.0"},
    {"rate_random_walk", "k_dps_per_sqrt_s = 0.001\nk_g_per_sqrt_s = [2e-5, 2e-5, 3e-5]"},
    {"gauss_markov", "sigma_dps = 0.05\nsigma_g = 0.001\ntau_s = [300.0, 100.0, 100.0, 150.0]"},
    {"adc_dnl", "dnl_rms_lsb = 0.15\nmissing_codes = [511]\ncarry_bits = 8\ncarry_dnl_lsb = 0.4\npattern_seed = 7"},
    {"adc_inl", "a2_lsb = 0.8\na3_lsb = -0.3\na4_lsb = 0.1"},
    {"supply_coupling",
     "sensor_ratiometric = [0.0, 1.0, 1.0, 1.0]\nripple_v = 0.01\nripple_hz = 100.0\n"
     "drift_v = -0.02\ndrift_tau_s = 900.0\nwander_v = 0.005\nwander_tau_s = 300.0"},
    {"cross_axis", "matrix_pct = [[0.0, 1.2, -0.5], [0.8, 0.0, 2.0], [-1.0, 0.3, 0.0]]"},
    {"g_sensitivity", "g_dps_per_g = [0.05, 0.05, 0.1]\ng2_dps_per_g2 = [0.0, 0.0, 0.02]"},
    {"vibration",
     "tone_hz = [29.0]\ntone_g_z = [0.01]\nrandom_rms_g = [0.002, 0.002, 0.004]\n"
     "band_low_hz = 10.0\nband_high_hz = 80.0"},
    {"mains_alias",
     "amplitude_v = 0.002\nfrequency_hz = 50.0\nharmonic_ratio = [0.3, 0.1]\n"
     "mux_skew_s = [0.0, 0.0001, 0.0002, 0.0003]"},
    {"clock_jitter", "drift_ppm = 30.0\njitter_s = 2e-6"},
    {"saturation", "min_dps = -90.0\nmax_dps = 90.0\nmin_g = [-1.0, -1.0, 0.0]\nmax_g = [1.0, 1.0, 2.0]"},
    {"spikes", "rate_hz = 0.001\ndistribution = \"student_t\"\nscale_counts = 3.0\nstudent_dof = 3"},
};

/// Effect built from TOML text (the body of its table).
inline std::unique_ptr<Effect> effect_from(std::string_view name, std::string_view toml_text) {
    const toml::table t = toml::parse(toml_text);
    return make_effect(name, t, std::string("effects.") + std::string(name));
}

inline double mean(const std::vector<double>& y) {
    return std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
}

inline double variance(const std::vector<double>& y) {
    const double m = mean(y);
    double s = 0.0;
    for (double v : y) s += (v - m) * (v - m);
    return s / static_cast<double>(y.size() - 1);
}

/// Biased sample autocorrelation r(lag) = R(lag) / R(0) (paper eq. 3).
inline double autocorrelation(const std::vector<double>& y, std::size_t lag) {
    const double m = mean(y);
    double r0 = 0.0, rl = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k) {
        r0 += (y[k] - m) * (y[k] - m);
        if (k + lag < y.size()) rl += (y[k] - m) * (y[k + lag] - m);
    }
    return rl / r0;
}

/// Overlapping Allan variance of rate samples y at averaging factor m (NIST SP 1065 eq. 11, via phase x).
inline double oavar(const std::vector<double>& y, double tau0_s, std::size_t m) {
    std::vector<double> x(y.size() + 1, 0.0);
    for (std::size_t k = 0; k < y.size(); ++k) x[k + 1] = x[k] + y[k] * tau0_s;
    const std::size_t n = x.size();
    double s = 0.0;
    for (std::size_t k = 0; k + 2 * m < n; ++k) {
        const double d = x[k + 2 * m] - 2.0 * x[k + m] + x[k];
        s += d * d;
    }
    const double tau = static_cast<double>(m) * tau0_s;
    return s / (2.0 * tau * tau * static_cast<double>(n - 2 * m));
}

/// Amplitude and phase of y_k ~ a sin(2 pi f t_k + phase) + c by linear least squares (sin, cos, 1).
struct Tone {
    double amplitude;
    double phase_rad;
};
inline Tone fit_tone(const std::vector<double>& y, const std::vector<double>& t_s, double f_hz) {
    double ss = 0, sc = 0, cc = 0, s1 = 0, c1 = 0, n = 0, ys = 0, yc = 0, y1 = 0;
    for (std::size_t k = 0; k < y.size(); ++k) {
        const double s = std::sin(2.0 * std::numbers::pi * f_hz * t_s[k]);
        const double c = std::cos(2.0 * std::numbers::pi * f_hz * t_s[k]);
        ss += s * s;
        sc += s * c;
        cc += c * c;
        s1 += s;
        c1 += c;
        n += 1.0;
        ys += y[k] * s;
        yc += y[k] * c;
        y1 += y[k];
    }
    // Solve the 3x3 normal equations by Cramer's rule.
    const double a[3][3] = {{ss, sc, s1}, {sc, cc, c1}, {s1, c1, n}};
    const double b[3] = {ys, yc, y1};
    auto det = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    double sol[2];
    for (int col = 0; col < 2; ++col) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == col ? b[i] : a[i][j];
        sol[col] = det(m) / d;
    }
    // a_s sin + a_c cos = A sin(wt + phase), A = hypot, phase = atan2(a_c, a_s).
    return {std::hypot(sol[0], sol[1]), std::atan2(sol[1], sol[0])};
}

/// Uniform time grid t_k = k dt.
inline std::vector<double> time_grid(std::size_t n, double dt_s) {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k) * dt_s;
    return t;
}

/// Difference of two angles wrapped to (-pi, pi].
inline double angle_diff(double a, double b) { return std::remainder(a - b, 2.0 * std::numbers::pi); }

}  // namespace driftlab::sim::test
