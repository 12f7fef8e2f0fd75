// Level-step test; see level_step.hpp.
#include "host/gap/level_step.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <Eigen/Dense>

#include "host/gap/candidates.hpp"
#include "host/gap/mean_shapes.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/spectral_fit.hpp"
#include "host/stats/nelder_mead.hpp"
#include "host/util/fft_length.hpp"
#include "host/util/real_fft.hpp"

namespace driftlab::host::gap {

namespace {

constexpr double kEdgeFraction = 0.02;  // a step this close to an end is half absorbed by the eq. 1 fit

// Outputs kept clear of each end of an n-output series when placing a step.
std::size_t edge_outputs(std::size_t n) {
    return std::max<std::size_t>(2, static_cast<std::size_t>(kEdgeFraction * static_cast<double>(n)));
}

// x less its projection onto the span of the orthonormal columns q (eq. 1 refitted beside, linearised).
std::vector<double> off_span(const Eigen::MatrixXd& q, Eigen::VectorXd x) {
    x -= q * (q.transpose() * x);
    return {x.data(), x.data() + x.size()};
}

constexpr double kMemoryShare = 0.1;   // the whitening's memory, as a share of the log
constexpr int kFloorEvaluations = 40;  // Nelder-Mead budget of the explanation's one free parameter, its floor

struct Largest {
    std::size_t index = 0;  ///< difference index: the step lies between samples index and index + 1
    double t = 0.0;         ///< standardised statistic
    double size = 0.0;      ///< estimated impulse [counts]
};

// The largest standardised impulse |T(theta)| = |(S^-1 d)_theta| / sqrt((S^-1)_theta,theta) of the differenced
// residual `r` (n + 1 samples; a step is an impulse there) under the differenced spectral density `density` of its
// mirror extension (length 2n). The mirror makes the series circular without a jump where it wraps; the whitening
// filter then acts as on an infinite series, and the ends are kept clear of the maximum anyway.
Largest largest_step(const std::vector<double>& r, const std::vector<double>& density) {
    const std::size_t m = density.size(), n = m / 2;
    std::vector<double> d(m);
    for (std::size_t t = 0; t < n; ++t) {
        d[t] = r[t + 1] - r[t];
        d[m - 1 - t] = -d[t];
    }
    // The mirrored series is real and the density even (density[j] = density[m - j]): the half spectrum holds it all.
    std::vector<std::complex<double>> spec = half_spectrum(d);
    double kappa = 0.0;
    spec[0] = 0.0;  // the mean difference carries no step location
    for (std::size_t j = 1; j < spec.size(); ++j) spec[j] /= density[j];
    for (std::size_t j = 1; j < m; ++j) kappa += 1.0 / density[j];
    kappa /= static_cast<double>(m);
    const std::vector<double> u = real_series(spec, m);
    Largest best;
    const std::size_t edge = edge_outputs(n);
    for (std::size_t t = edge; t + edge < n; ++t) {
        const double stat = std::abs(u[t]) / std::sqrt(kappa);
        if (stat > best.t) best = {t, stat, u[t] / kappa};
    }
    return best;
}

// Change points in mean fitted together with the columns of `q` (orthonormal: eq. 1's tangent, whose constant is
// the pieces' common level, or the constant alone): the residual sum of squares of `r` (orthogonal to q) on q and
// the steps' columns h_c (1 from index c on), from suffix sums. A hop bends the eq. 1 fit toward it, and the bend,
// fitted alone, leaves a step-like remainder near the start that the cuts would otherwise take for the hop's return.
struct StepsBesideColumns {
    std::vector<double> tail_r;  // sum_{k >= c} r_k, size n + 1
    Eigen::MatrixXd tail_q;      // row c: sum_{k >= c} q_k (the columns' share of h_c)
    double rr = 0.0;

    StepsBesideColumns(const std::vector<double>& r, const Eigen::MatrixXd& q)
        : tail_r(r.size() + 1, 0.0), tail_q(Eigen::MatrixXd::Zero(q.rows() + 1, q.cols())) {
        for (std::size_t k = r.size(); k-- > 0;) {
            const auto i = static_cast<Eigen::Index>(k);
            tail_r[k] = tail_r[k + 1] + r[k];
            tail_q.row(i) = tail_q.row(i + 1) + q.row(i);
            rr += r[k] * r[k];
        }
    }
    std::size_t size() const { return tail_r.size() - 1; }
    // Inner product of h_a and h_b once the columns are projected out.
    double gram(std::size_t a, std::size_t b) const {
        return static_cast<double>(size() - std::max(a, b)) -
               tail_q.row(static_cast<Eigen::Index>(a)).dot(tail_q.row(static_cast<Eigen::Index>(b)));
    }
    double rss(std::size_t c) const {
        const double g = gram(c, c);
        return g > 0.0 ? rr - tail_r[c] * tail_r[c] / g : rr;
    }
    // The normal equations of two steps at c1 and c2: their Gram matrix and their products with r.
    Eigen::Matrix2d gram(std::size_t c1, std::size_t c2, Eigen::Vector2d& u) const {
        u = {tail_r[c1], tail_r[c2]};
        return Eigen::Matrix2d{{gram(c1, c1), gram(c1, c2)}, {gram(c1, c2), gram(c2, c2)}};
    }
    // Two steps at c1 and c2 fitted by least squares: the residual sum of squares and whether their sizes have
    // opposite signs (a hop and its return; false where the two columns are dependent and the fit is the first's).
    struct TwoSteps {
        double rss;
        bool opposite;
    };
    TwoSteps fit(std::size_t c1, std::size_t c2) const {
        Eigen::Vector2d u;
        const Eigen::Matrix2d g = gram(c1, c2, u);
        if (g.determinant() <= 0.0) return {rss(c1), false};
        const Eigen::Vector2d size = g.inverse() * u;
        return {rr - u.dot(size), size(0) * size(1) < 0.0};
    }
    double rss(std::size_t c1, std::size_t c2) const { return fit(c1, c2).rss; }
};

// The best two change points (c1 < c2, each piece at least two outputs, `edge` clear of the ends) by alternating
// scans, exact for either cut given the other (O(n) each): from the best single cut, the best second cut, then each
// again given the other until neither moves. With `hop_and_return` only steps of opposite signs count: two steps
// the same way are a staircase, which a warm-up's unmodelled curvature draws, not a hop and its return.
std::pair<std::size_t, std::size_t> best_two_cuts(const StepsBesideColumns& cost, std::size_t edge,
                                                  bool hop_and_return = false) {
    const std::size_t n = cost.size();
    std::size_t c1 = edge;
    double best_cost = 1e300;
    for (std::size_t c = edge; c + edge < n; ++c) {
        const double v = cost.rss(c);
        if (v < best_cost) best_cost = v, c1 = c;
    }
    // Given one cut, the best other; under `hop_and_return` the best of opposite sign, unless there is none.
    auto best_other = [&](std::size_t fixed) {
        std::size_t arg = 0, any = 0;
        double v_best = 1e300, v_any = 1e300;
        for (std::size_t c = edge; c + edge < n; ++c) {
            if (c + 1 >= fixed && c <= fixed + 1) continue;  // pieces of at least two outputs
            const StepsBesideColumns::TwoSteps f = cost.fit(std::min(c, fixed), std::max(c, fixed));
            if (f.rss < v_any) v_any = f.rss, any = c;
            if (f.rss < v_best && (!hop_and_return || f.opposite)) v_best = f.rss, arg = c;
        }
        return v_best < 1e300 ? arg : any;
    };
    std::size_t c2 = best_other(c1);
    for (int round = 0; round < 8; ++round) {
        const std::size_t new1 = best_other(c2);
        const std::size_t new2 = best_other(new1);
        if (new1 == c1 && new2 == c2) break;
        c1 = new1, c2 = new2;
    }
    return {std::min(c1, c2), std::max(c1, c2)};
}

}  // namespace

StepPValues step_p_values(const Eigen::MatrixXd& null, double impulse, double statistic, double margin) {
    // Each statistic's p is its rank among the log and the replicates, the log's and every replicate's alike, so
    // that their smaller one can be ranked in turn.
    Eigen::MatrixXd ranked(null.rows() + 1, 2);
    ranked.topRows(null.rows()) = null;
    ranked.bottomRows(1) << impulse, statistic;
    const auto rank_p = [&](Eigen::Index col, double value) {
        return static_cast<double>((ranked.col(col).array() >= value).count()) / static_cast<double>(ranked.rows());
    };
    const auto min_p = [&](Eigen::Index row) {
        return std::min(rank_p(0, ranked(row, 0)), ranked(row, 1) > margin ? rank_p(1, ranked(row, 1)) : 1.0);
    };
    const double own = min_p(ranked.rows() - 1);
    int as_small = 0;
    for (Eigen::Index k = 0; k < ranked.rows(); ++k) as_small += min_p(k) <= own;
    return {rank_p(0, impulse), rank_p(1, statistic),
            static_cast<double>(as_small) / static_cast<double>(ranked.rows())};
}

const char* step_reading(const LevelStep& s) {
    if (s.significant) return "a step no library effect makes: the log is unexplained";
    if (s.outsized)
        return "beyond the model's own, but its processes remain beside the steps: their outsized increments";
    return "none beyond the model's own";
}

bool leaves_step(const LevelStep& s, double alpha) { return s.tested && s.p_value <= alpha && !s.process_beside_steps; }

// The explanation as its replicates simulate it, with only its white floor estimated on the real log's periodogram,
// so that the statistic means the same on the log and on the replicates.
SpectralFit explanation_with_floor(const GapModel& model, Channel c, const PartPeriodogram& real_p,
                                   const std::vector<std::string>& spectral_effects,
                                   const std::vector<double>& spectral_params) {
    SpectralFit explanation;
    explanation.effects = spectral_effects;
    explanation.params = spectral_params;
    const double floor_start = fit_spectral({}, c, model, real_p).white;
    const auto floor_nll = [&](const std::vector<double>& ln_white) {
        explanation.white = std::exp(ln_white[0]);
        return spectral_nll(explanation, c, model, real_p);
    };
    explanation.white = std::exp(stats::nelder_mead(floor_nll, {std::log(floor_start)}, {0.3}, kFloorEvaluations).x[0]);
    return explanation;
}

// Is the explanation more than a stand-in for steps? Its processes refitted beside two steps against the floor
// beside them (nested: the Schwarz price of the processes' parameters, `count` frequencies). The steps are the
// least-squares change points in mean placed beside eq. 1's tangent `q`, then refitted together with eq. 1 (linear in
// its level and rise at a given time constant, which is profiled over a grid): the eq. 1 fit has bent toward a hop
// and would otherwise leave a slow remainder for a process to take up.
void test_process_beside_steps(LevelStep& out, const GapModel& model, Channel c, const std::vector<double>& t_s,
                               const std::vector<double>& y, const std::vector<double>& r, const Eigen::MatrixXd& q,
                               const std::vector<std::string>& spectral_effects,
                               const std::vector<double>& spectral_params, std::size_t count) {
    const std::vector<bool> all(r.size(), true);
    const auto [c1, c2] = best_two_cuts(StepsBesideColumns(r, q), edge_outputs(r.size()));
    const std::vector<double> stepped = eq1_and_steps_residual(t_s, y, c1, c2);
    const PartPeriodogram stepped_p = part_periodogram(stepped, all);
    const SpectralFit beside = fit_spectral(spectral_effects, c, model, stepped_p, spectral_params);
    out.process_gain = fit_spectral({}, c, model, stepped_p).nll - beside.nll;
    out.process_margin =
        static_cast<double>(spectral_params.size()) * 0.5 * parameter_price(InformationCriterion::bic, count);
    out.process_beside_steps = out.process_gain > out.process_margin;
}

LevelStep test_level_step(const GapModel& model, Channel c, const std::vector<double>& t_s,
                          const std::vector<double>& y, const std::vector<std::string>& spectral_effects,
                          const std::vector<double>& spectral_params, int replicates, std::uint64_t seed, int threads,
                          double alpha) {
    // Enough replicates that the combined p resolves alpha four times over.
    replicates = std::max(replicates, static_cast<int>(std::ceil(4.0 / alpha)));
    const std::size_t i = channel_index(c);
    const std::vector<double> mean = model_mean_counts(model, c, t_s);
    // The log's residual is what its eq. 1 fit left, so it lacks the slow part that fit took up; a replicate's
    // residual about the same mean still has it. Each (the log's too, for a like statistic) therefore loses its
    // projection onto eq. 1's tangent, the fit linearised: without it a walk's replicates keep the lowest frequencies
    // the log's fit absorbed, and their excursions pass for steps as large as the log's.
    const Eigen::MatrixXd q = eq1_tangent_basis(t_s, model.base[i].drift.tau_s);
    const auto residual_about_mean = [&](const std::vector<double>& x) {
        Eigen::VectorXd e(static_cast<Eigen::Index>(x.size()));
        for (std::size_t k = 0; k < x.size(); ++k) e[static_cast<Eigen::Index>(k)] = x[k] - mean[k];
        return off_span(q, e);
    };
    const std::vector<double> r = residual_about_mean(y);
    const std::vector<bool> all(r.size(), true);
    const PartPeriodogram real_p = part_periodogram(r, all);
    const std::vector<double> floor_acov = white_floor_autocovariance(model.smoothing);
    // The explanation is the model as its replicates simulate it; only its white floor is estimated, on the real
    // log, so that the statistic means the same on the log and on the replicates.
    const SpectralFit explanation = explanation_with_floor(model, c, real_p, spectral_effects, spectral_params);
    // Whitening compares levels before and after each instant over at most a tenth of the log: a slight random walk
    // (its filter's memory is sqrt(white / increment) samples) keeps a stationary spectrum's 1/w^2 low-frequency gain
    // from weighing the whole log's mean, which the eq. 1 fit has already bent. The rival's steps are located under
    // the floor alone; the impulse test whitens with the explanation.
    const std::size_t n = smooth_length_at_most(r.size() - 1);
    const double memory = explanation.white * floor_acov[0] * std::pow(kMemoryShare * static_cast<double>(n), -2.0);
    OutputSpectrum floor;
    floor.white = explanation.white;
    floor.walk_increment_variance = memory;
    const std::vector<double> floor_density = differenced_density(floor, floor_acov, 2 * n);
    OutputSpectrum explained = model_spectrum(spectral_effects, c, spectral_params, model, explanation.white);
    explained.walk_increment_variance += memory;
    const std::vector<double> explained_density = differenced_density(explained, floor_acov, 2 * n);
    // Both statistics of one series; the rival (floor and steps) is fitted to each.
    const auto statistics = [&](std::vector<double> x, std::array<Largest, 2>* found) {
        const double impulse = largest_step(x, explained_density).t;
        const double explained_nll = spectral_nll(explanation, c, model, part_periodogram(x, all));
        for (std::size_t s = 0; s < 2; ++s) {
            const Largest l = largest_step(x, floor_density);
            if (found) (*found)[s] = l;
            for (std::size_t k = l.index + 1; k < x.size(); ++k) x[k] -= l.size;
        }
        return std::vector<double>{impulse, explained_nll - fit_spectral({}, c, model, part_periodogram(x, all)).nll};
    };
    std::array<Largest, 2> steps;
    const std::vector<double> real = statistics(r, &steps);
    std::array<bool, kChannelCount> only{};
    only[i] = true;
    const Eigen::MatrixXd null = simulate_replicates(
        model, t_s, only, replicates, seed, threads,
        [&](const sim::Outputs& sim, const sim::Outputs&) { return statistics(residual_about_mean(sim[i]), nullptr); });
    LevelStep out;
    out.tested = true;
    out.channel = c;
    for (std::size_t s = 0; s < 2; ++s)
        out.steps[s] = {0.5 * (t_s[steps[s].index] + t_s[steps[s].index + 1]), steps[s].size};
    // Two instants and two sizes against the explanation's own parameters (the floor is in both), at half the BIC
    // price each (the statistic is in nll units).
    const double extra = 4.0 - static_cast<double>(spectral_params.size());
    out.margin = std::max(0.0, extra) * 0.5 * parameter_price(InformationCriterion::bic, real_p.count);
    test_process_beside_steps(out, model, c, t_s, y, r, q, spectral_effects, spectral_params, real_p.count);
    out.impulse = real[0];
    out.statistic = real[1];
    const StepPValues p = step_p_values(null, out.impulse, out.statistic, out.margin);
    out.impulse_p = p.impulse;
    out.rival_p = p.rival;
    out.p_value = p.combined;
    out.significant = leaves_step(out, alpha);
    out.outsized = out.p_value <= alpha && out.process_beside_steps;
    return out;
}

StepsOverShape steps_over_shape(const std::vector<double>& t_s, const std::vector<double>& base_residual,
                                const std::vector<double>& shape_residual, int shape_parameters, double long_run_factor,
                                const Eigen::MatrixXd& beside) {
    StepsOverShape out;
    const std::size_t n = base_residual.size();
    const std::size_t edge = edge_outputs(n);
    if (n < 4 * edge + 4 || shape_residual.size() != n) return out;
    double shape_rss = 0.0;
    for (double r : shape_residual) shape_rss += r * r;
    const StepsBesideColumns cost(
        off_span(beside, Eigen::Map<const Eigen::VectorXd>(base_residual.data(), static_cast<Eigen::Index>(n))),
        beside);
    const auto [c1, c2] = best_two_cuts(cost, edge, true);
    Eigen::Vector2d u;
    const Eigen::Vector2d size = cost.gram(c1, c2, u).ldlt().solve(u);
    const double outputs = static_cast<double>(n) / std::max(1.0, long_run_factor);
    out.tested = true;
    out.steps[0] = {t_s[c1], size(0)};
    out.steps[1] = {t_s[c2], size(1)};
    out.statistic = 0.5 * outputs * std::log(shape_rss / std::max(cost.rss(c1, c2), 1e-300));
    out.margin = 0.5 * (4 - shape_parameters) * std::log(outputs);
    out.steps_win = out.statistic > out.margin;
    return out;
}

}  // namespace driftlab::host::gap
