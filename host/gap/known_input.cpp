// The known input of a log in motion; see known_input.hpp.
#include "host/gap/known_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>

#include <Eigen/QR>

#include "firmware/core/config.hpp"
#include "firmware/core/hal.hpp"
#include "host/gap/calibrate.hpp"
#include "sim/model/board_outputs.hpp"
#include "sim/motion/trajectories.hpp"

namespace driftlab::host::gap {
namespace {

using MotionAt = std::function<sim::MotionInput(double t_s)>;

double quantity(const sim::MotionInput& in, MotionQuantity q) {
    switch (q) {
    case MotionQuantity::yaw_rate: return in.yaw_rate_dps;
    case MotionQuantity::accel_x: return in.accel_x_g;
    case MotionQuantity::accel_y: return in.accel_y_g;
    }
    return 0.0;
}

// Linear interpolation between the truth's rows (held before the first and after the last).
MotionAt interpolated(const TruthFile& truth) {
    return [&truth](double t) {
        const auto it = std::upper_bound(truth.t_s.begin(), truth.t_s.end(), t);
        const std::size_t hi =
            std::min<std::size_t>(static_cast<std::size_t>(it - truth.t_s.begin()), truth.size() - 1);
        const std::size_t lo = hi == 0 ? 0 : hi - 1;
        const double span = truth.t_s[hi] - truth.t_s[lo];
        const double w = span > 0.0 ? std::clamp((t - truth.t_s[lo]) / span, 0.0, 1.0) : 0.0;
        auto at = [&](const std::vector<double>& v) { return v[lo] + w * (v[hi] - v[lo]); };
        return sim::MotionInput{at(truth.yaw_rate_dps), at(truth.accel_x_g), at(truth.accel_y_g)};
    };
}

// The trajectory the truth names, rebuilt as hil built it (the log's seed draws stop-and-go's stretches), if it
// gives every truth row to the truth's printed precision; else nothing, and `why` says so.
std::shared_ptr<const sim::Trajectory> rebuilt(const TruthFile& truth, const LogData& log, std::string& why) {
    if (truth.trajectory.empty()) {
        why = "the truth names no trajectory";
        return nullptr;
    }
    const auto seed_text = log.metadata.get("seed");
    const std::uint64_t seed = seed_text ? std::strtoull(seed_text->c_str(), nullptr, 10) : 1;
    std::shared_ptr<const sim::Trajectory> trajectory;
    try {
        trajectory = std::make_shared<const sim::Trajectory>(
            sim::make_trajectory(truth.trajectory, truth.t_s.back() + 60.0, truth.rest_before_s, seed));
    } catch (const std::exception& e) {
        why = "trajectory " + truth.trajectory + " cannot be rebuilt (" + e.what() + ")";
        return nullptr;
    }
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const sim::MotionInput in = trajectory->input_at(truth.t_s[i]);
        if (std::fabs(in.yaw_rate_dps - truth.yaw_rate_dps[i]) > 2e-6 ||
            std::fabs(in.accel_x_g - truth.accel_x_g[i]) > 2e-9 ||
            std::fabs(in.accel_y_g - truth.accel_y_g[i]) > 2e-9) {
            why = "trajectory " + truth.trajectory + " rebuilt does not give the truth's line " +
                  std::to_string(truth.lines[i]);
            return nullptr;
        }
    }
    return trajectory;
}

// The board's conversion instants around a row: one channel every `period_s`, in channel order, so channel c's
// newest conversion before a row is `back(c)` periods before it, and its window's conversions 4 periods apart.
struct RoundRobin {
    double period_s = 0.0;        ///< one conversion (of any channel) [s]
    std::vector<double> weights;  ///< of the window's conversions, newest first: the firmware's least-squares value

    // The smoothed value of f over channel c's window for the row at t_s, `phase` placing the round robin.
    double smooth(double t_s, std::size_t c, int phase, const std::function<double(double)>& f) const {
        const long long n = std::llround(t_s / period_s);
        const auto newest = static_cast<std::size_t>(((n + phase) % 4 + 4) % 4);
        const double t0 = t_s - static_cast<double>((newest + kChannelCount - c) % kChannelCount) * period_s;
        double sum = 0.0;
        for (std::size_t j = 0; j < weights.size(); ++j)
            sum += weights[j] * f(t0 - static_cast<double>(j * kChannelCount) * period_s);
        return sum;
    }
};

// The weights of the firmware's estimate (fw::LsWindow): the mean, or the line through the window evaluated at its
// newest conversion, of N conversions.
std::vector<double> least_squares_weights(int window, int fit_order) {
    const auto n = static_cast<std::size_t>(std::max(1, window));
    std::vector<double> w(n, 1.0 / static_cast<double>(n));
    if (fit_order != 1 || n < 2) return w;
    const double nd = static_cast<double>(n);
    const double mean_x = -(nd - 1.0) / 2.0;  // x_j = -j
    const double sxx = nd * (nd * nd - 1.0) / 12.0;
    for (std::size_t j = 0; j < n; ++j) w[j] += (-static_cast<double>(j) - mean_x) * (-mean_x) / sxx;
    return w;
}

RoundRobin round_robin(const LogData& log) {
    const Smoothing sm = smoothing_from_log(log);
    const double tick_hz = log.metadata.get_double("tick_hz").value_or(fw::kTickHz);
    const auto output_ms = static_cast<std::uint16_t>(std::lround(sm.output_period_s() * 1000.0));
    const std::uint32_t ticks =
        fw::conversion_period_ticks(output_ms, static_cast<std::uint8_t>(sm.conversions_per_output));
    RoundRobin rr;
    rr.period_s = ticks > 0 ? ticks / tick_hz : sm.conversion_period_s() / kChannelCount;
    rr.weights = least_squares_weights(sm.window, sm.fit_order);
    return rr;
}

}  // namespace

const char* motion_quantity_name(MotionQuantity q) {
    switch (q) {
    case MotionQuantity::yaw_rate: return "yaw_rate";
    case MotionQuantity::accel_x: return "accel_x";
    case MotionQuantity::accel_y: return "accel_y";
    }
    return "?";
}

bool measures(Channel c, MotionQuantity& q) {
    switch (c) {
    case Channel::gyro: q = MotionQuantity::yaw_rate; return true;
    case Channel::accel_x: q = MotionQuantity::accel_x; return true;
    case Channel::accel_y: q = MotionQuantity::accel_y; return true;
    case Channel::accel_z: return false;
    }
    return false;
}

std::vector<double> KnownInput::counts(Channel c, MotionQuantity q) const {
    std::vector<double> out = smoothed[channel_index(c)][static_cast<std::size_t>(q)];
    for (double& v : out) v *= counts_per_unit[channel_index(c)];
    return out;
}

std::vector<double> KnownInput::counts(Channel c) const {
    MotionQuantity q{};
    if (measures(c, q)) return counts(c, q);
    return std::vector<double>(smoothed[channel_index(c)][0].size(), 0.0);
}

namespace {

// Sum over the moving channels of the squared residual of the log less its known input, a cubic in time (the slow
// drift) fitted out: least where the known input's timing is the log's. (First differences would hide a timing
// error of a conversion period or two under the white noise they amplify.)
double misfit(const LogData& log, const RoundRobin& rr, int phase, const MotionAt& motion,
              const std::array<double, kChannelCount>& counts_per_unit) {
    const auto n = static_cast<Eigen::Index>(log.size());
    const double span_s = std::max(log.t_s.back() - log.t_s.front(), 1e-9);
    Eigen::MatrixXd cubic(n, 4);
    for (Eigen::Index k = 0; k < n; ++k) {
        const double x = 2.0 * (log.t_s[static_cast<std::size_t>(k)] - log.t_s.front()) / span_s - 1.0;
        cubic.row(k) << 1.0, x, x * x, x * x * x;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(cubic);
    double sum = 0.0;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        MotionQuantity q{};
        if (!log.recorded[c] || !measures(static_cast<Channel>(c), q)) continue;
        const auto f = [&](double t) { return quantity(motion(t), q); };
        Eigen::VectorXd r(n);
        for (Eigen::Index k = 0; k < n; ++k) {
            const auto i = static_cast<std::size_t>(k);
            r(k) = log.counts[c][i] - counts_per_unit[c] * rr.smooth(log.t_s[i], c, phase, f);
        }
        sum += (r - cubic * qr.solve(r)).squaredNorm();
    }
    return sum;
}

}  // namespace

KnownInput known_input(const LogData& log, const TruthFile& truth, const sim::SimModel& unit) {
    KnownInput out;
    sim::OutputModel model;
    model.unit = unit;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        out.counts_per_unit[c] = counts_per_unit(model, static_cast<Channel>(c));
    std::string why;
    const std::shared_ptr<const sim::Trajectory> trajectory = rebuilt(truth, log, why);
    const MotionAt motion =
        trajectory ? MotionAt([trajectory](double t) { return trajectory->input_at(t); }) : interpolated(truth);
    out.source = trajectory ? "trajectory " + truth.trajectory + " rebuilt (exact between rows)"
                            : "interpolated between the truth's rows (" + why + ")";
    const RoundRobin rr = round_robin(log);
    const long long n0 = std::llround(log.t_s.front() / rr.period_s);
    int phase = static_cast<int>(((3 - n0) % 4 + 4) % 4);  // a streamed row follows the last channel's conversion
    if (log.metadata.get("mode").value_or("poll") != "stream") {
        out.newest_estimated = true;
        double best = std::numeric_limits<double>::infinity();
        for (int p = 0; p < 4; ++p)
            if (const double m = misfit(log, rr, p, motion, out.counts_per_unit); m < best) {
                best = m;
                phase = p;
            }
    }
    out.newest_channel = static_cast<int>(((n0 + phase) % 4 + 4) % 4);
    for (std::size_t c = 0; c < kChannelCount; ++c)
        for (std::size_t q = 0; q < kMotionQuantities; ++q) {
            std::vector<double>& s = out.smoothed[c][q];
            s.resize(log.size());
            const auto f = [&](double t) { return quantity(motion(t), static_cast<MotionQuantity>(q)); };
            for (std::size_t k = 0; k < log.size(); ++k) s[k] = rr.smooth(log.t_s[k], c, phase, f);
        }
    return out;
}

}  // namespace driftlab::host::gap
