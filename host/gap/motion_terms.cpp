// The motion terms of `gap --truth`; see motion_terms.hpp.
#include "host/gap/motion_terms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/QR>
#include <boost/math/distributions/students_t.hpp>

#include "host/gap/diagnose.hpp"
#include "host/gap/replicates.hpp"

namespace driftlab::host::gap {
namespace {

// A regressor that moves by less than this over the log cannot size its term [counts, standard deviation].
constexpr double kMinExcitationCounts = 0.05;
// A regressor with less than this share of its variance left once the columns before it are fitted moves with them.
constexpr double kMinOwnVarianceShare = 0.01;

double centred_norm2(const Eigen::VectorXd& v) { return (v.array() - v.mean()).matrix().squaredNorm(); }

Eigen::VectorXd as_vector(const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// One channel's regression: the columns it keeps (a constant, eq. 1's exponential, then its tested terms) and the
// terms' places among them.
struct ChannelRegression {
    std::size_t channel = 0;
    Eigen::MatrixXd design;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
    Eigen::Index first_term = 0;
    std::vector<std::size_t> terms;  ///< indices into the findings' terms, in column order

    Eigen::VectorXd coefficients(const std::vector<double>& y) const {
        return qr.solve(as_vector(y)).tail(design.cols() - first_term);
    }
};

// The constant and, where the calibrated drift has one, the exponential of eq. 1 at the rows.
Eigen::MatrixXd drift_columns(const std::vector<double>& t_s, double tau_s) {
    const auto n = static_cast<Eigen::Index>(t_s.size());
    const bool exponential = std::isfinite(tau_s) && tau_s > 0.0;
    Eigen::MatrixXd b(n, exponential ? 2 : 1);
    for (Eigen::Index k = 0; k < n; ++k) {
        b(k, 0) = 1.0;
        if (exponential) b(k, 1) = std::exp(-t_s[static_cast<std::size_t>(k)] / tau_s);
    }
    return b;
}

// Adds the terms of `channel` that the trajectory excites and that move on their own to its regression.
ChannelRegression channel_regression(std::size_t channel, const LogData& rest, const KnownInput& known,
                                     const GapModel& base, std::vector<MotionTermFit>& fits) {
    ChannelRegression reg;
    reg.channel = channel;
    Eigen::MatrixXd design = drift_columns(rest.t_s, base.base[channel].drift.tau_s);
    reg.first_term = design.cols();
    for (std::size_t i = 0; i < fits.size(); ++i) {
        MotionTermFit& f = fits[i];
        if (channel_index(f.term.channel) != channel) continue;
        const Eigen::VectorXd x = as_vector(known.counts(f.term.channel, f.term.input));
        const double spread = std::sqrt(centred_norm2(x) / static_cast<double>(x.size()));
        if (!(spread >= kMinExcitationCounts)) {
            char why[160];
            std::snprintf(why, sizeof why, "not excited: %s moves the regressor by %.3g counts rms, under %.3g",
                          motion_quantity_name(f.term.input), spread, kMinExcitationCounts);
            f.not_tested = why;
            continue;
        }
        const Eigen::VectorXd left = x - design * design.colPivHouseholderQr().solve(x);
        if (left.squaredNorm() < kMinOwnVarianceShare * centred_norm2(x)) {
            f.not_tested =
                "moves with the terms before it on this trajectory (less than 1 % of its variance is "
                "its own): not separable from them";
            continue;
        }
        design.conservativeResize(Eigen::NoChange, design.cols() + 1);
        design.col(design.cols() - 1) = x;
        f.tested = true;
        reg.terms.push_back(i);
    }
    reg.design = std::move(design);
    reg.qr.compute(reg.design);
    return reg;
}

MotionTerm term(const char* effect, Channel c, MotionQuantity q, std::string parameter, const char* unit,
                double per_coefficient) {
    return {effect, c, q, std::move(parameter), unit, per_coefficient};
}

}  // namespace

const MotionTermFit* MotionFindings::strongest() const {
    const MotionTermFit* best = nullptr;
    for (const MotionTermFit& f : terms)
        if (f.accepted && (!best || std::fabs(f.z) > std::fabs(best->z))) best = &f;
    return best;
}

std::vector<MotionTerm> motion_terms(const std::array<bool, kChannelCount>& channels) {
    using Q = MotionQuantity;
    // scale_factor and cross_axis in %: the regressor is the input in the channel's counts, so a coefficient of
    // 0.01 is 1 %; g_sensitivity: the regressor is the acceleration in the gyro's counts of 1 deg/s per g.
    const std::vector<MotionTerm> all = {
        term("scale_factor", Channel::gyro, Q::yaw_rate, "error_pct[0]", "%", 100.0),
        term("g_sensitivity", Channel::gyro, Q::accel_x, "g_dps_per_g[0]", "deg/s/g", 1.0),
        term("g_sensitivity", Channel::gyro, Q::accel_y, "g_dps_per_g[1]", "deg/s/g", 1.0),
        term("scale_factor", Channel::accel_x, Q::accel_x, "error_pct[1]", "%", 100.0),
        term("cross_axis", Channel::accel_x, Q::accel_y, "matrix_pct[0][1]", "%", 100.0),
        term("scale_factor", Channel::accel_y, Q::accel_y, "error_pct[2]", "%", 100.0),
        term("cross_axis", Channel::accel_y, Q::accel_x, "matrix_pct[1][0]", "%", 100.0),
        term("cross_axis", Channel::accel_z, Q::accel_x, "matrix_pct[2][0]", "%", 100.0),
        term("cross_axis", Channel::accel_z, Q::accel_y, "matrix_pct[2][1]", "%", 100.0),
    };
    std::vector<MotionTerm> out;
    for (const MotionTerm& t : all)
        if (channels[channel_index(t.channel)]) out.push_back(t);
    return out;
}

MotionFindings fit_motion_terms(const LogData& rest, const KnownInput& known, const GapModel& base,
                                const std::array<bool, kChannelCount>& channels, const GapOptions& options) {
    MotionFindings out;
    out.input_source = known.source;
    out.newest_channel = known.newest_channel;
    out.newest_estimated = known.newest_estimated;
    out.replicates = options.replicates;
    for (const MotionTerm& t : motion_terms(channels)) {
        MotionTermFit f;
        f.term = t;
        out.terms.push_back(f);
    }
    std::vector<ChannelRegression> regressions;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (channels[c]) regressions.push_back(channel_regression(c, rest, known, base, out.terms));
    const auto tested = static_cast<std::size_t>(
        std::count_if(out.terms.begin(), out.terms.end(), [](const MotionTermFit& f) { return f.tested; }));
    if (tested == 0) return out;

    auto estimates = [&](const std::array<const std::vector<double>*, kChannelCount>& y) {
        std::vector<double> row;
        for (const ChannelRegression& reg : regressions) {
            const Eigen::VectorXd b = reg.coefficients(*y[reg.channel]);
            row.insert(row.end(), b.data(), b.data() + b.size());
        }
        return row;
    };
    std::array<const std::vector<double>*, kChannelCount> real{};
    for (std::size_t c = 0; c < kChannelCount; ++c) real[c] = &rest.counts[c];
    const std::vector<double> value = estimates(real);
    const Eigen::MatrixXd null =
        simulate_replicates(base, rest.t_s, channels, options.replicates, options.seed, options.threads,
                            [&](const sim::Outputs& simulated, const sim::Outputs&) {
                                std::array<const std::vector<double>*, kChannelCount> y{};
                                for (std::size_t c = 0; c < kChannelCount; ++c) y[c] = &simulated[c];
                                return estimates(y);
                            });

    const boost::math::students_t t_dist(static_cast<double>(options.replicates - 1));
    out.z_threshold =
        boost::math::quantile(boost::math::complement(t_dist, options.alpha / (2.0 * static_cast<double>(tested))));
    Eigen::Index column = 0;
    for (const ChannelRegression& reg : regressions)
        for (const std::size_t i : reg.terms) {
            MotionTermFit& f = out.terms[i];
            const Eigen::VectorXd v = null.col(column);
            const double mean = v.mean();
            const double sd = std::sqrt(centred_norm2(v) / static_cast<double>(v.size() - 1));
            f.value = value[static_cast<std::size_t>(column)] * f.term.per_coefficient;
            f.null_sd = sd * std::fabs(f.term.per_coefficient);
            f.z = sd > 0.0 ? (value[static_cast<std::size_t>(column)] - mean) / sd : 0.0;
            f.accepted = std::fabs(f.z) > out.z_threshold;
            ++column;
        }
    return out;
}

LogData without_accepted(const LogData& rest, const KnownInput& known, const MotionFindings& findings) {
    LogData out = rest;
    for (const MotionTermFit& f : findings.terms) {
        if (!f.accepted) continue;
        const std::vector<double> x = known.counts(f.term.channel, f.term.input);
        std::vector<double>& y = out.counts[channel_index(f.term.channel)];
        const double coefficient = f.value / f.term.per_coefficient;
        for (std::size_t k = 0; k < y.size(); ++k) y[k] -= coefficient * x[k];
    }
    return out;
}

}  // namespace driftlab::host::gap
