// The planar navigation filter: an extended Kalman filter (Eigen) on the total state: the pose, the
// velocity in the start frame and the three sensor biases. Its prediction is the strapdown itself (heading from the
// yaw rate, velocity from the body's specific force rotated by the heading, position from the velocity, trapezoidal
// over each step); its updates are the aids. docs/nav.md §The filter.
#pragma once

#include <array>

#include <Eigen/Dense>

namespace driftlab::host::nav {

/// What the unit reads at an instant, in the body frame, its input correction applied: yaw rate [rad/s], forward and
/// lateral specific force [m/s^2].
struct ImuReading {
    double yaw_rate = 0.0;
    double ax = 0.0, ay = 0.0;
};

/// Per axis (yaw rate, forward, lateral): white noise density [rad/s sqrt(s), m/s^2 sqrt(s)] and the power spectral
/// density of the bias walk [(rad/s)^2/s, (m/s^2)^2/s].
struct FilterNoise {
    std::array<double, 3> white_density{};
    std::array<double, 3> bias_walk_psd{};
};

class PlanarEkf {
public:
    static constexpr int kStates = 8;
    enum Index { x = 0, y = 1, heading = 2, vx = 3, vy = 4, bias_gyro = 5, bias_ax = 6, bias_ay = 7 };
    using State = Eigen::Matrix<double, kStates, 1>;
    using Covariance = Eigen::Matrix<double, kStates, kStates>;

    /// At the origin, heading 0, at rest, biases 0 with standard deviations `initial_bias_sd` (their units).
    PlanarEkf(const FilterNoise& noise, const std::array<double, 3>& initial_bias_sd);

    /// Moves the state from the reading `begin` to `end`, `dt` seconds later.
    void predict(double dt, const ImuReading& begin, const ImuReading& end);

    /// Whether the velocity estimate is within `gate` (a chi-square quantile for 2 degrees of freedom) of zero known
    /// to `sd` [m/s]: whether the filter can believe it stands. If so and `apply`, zero velocity is its update.
    bool update_zero_velocity(double sd, double gate, bool apply = true);
    /// At a stop the reading is the bias plus white noise over a step of `dt` seconds (PX4's "zero gyro update").
    void update_bias_at_rest(const ImuReading& reading, double dt);
    /// Wheel odometry: forward speed `speed` [m/s] with `speed_sd`, lateral speed 0 with `lateral_sd` (no slip).
    void update_odometry(double speed, double speed_sd, double lateral_sd);
    /// An absolute position fix [m] with standard deviation `sd` on each axis.
    void update_position(double px, double py, double sd);

    const State& state() const { return x_; }
    const Covariance& covariance() const { return p_; }
    /// The normalised estimation error squared of the pose (x, y, heading) against the truth: chi-square with 3
    /// degrees of freedom when the filter is consistent.
    double pose_nees(double true_x, double true_y, double true_heading_rad) const;
    /// The same for the heading alone (1 degree of freedom): a log without accelerometers navigates nothing else.
    double heading_nees(double true_heading_rad) const;

private:
    template <int M>
    void update(const Eigen::Matrix<double, M, 1>& innovation, const Eigen::Matrix<double, M, kStates>& h,
                const Eigen::Matrix<double, M, M>& r);

    FilterNoise noise_;
    State x_ = State::Zero();
    Covariance p_ = Covariance::Zero();
};

/// The strapdown over one step, biases taken out: the state `dt` seconds after `x`, from the readings `begin` to `end`.
PlanarEkf::State strapdown_step(const PlanarEkf::State& x, double dt, const ImuReading& begin, const ImuReading& end);
/// Its Jacobian by the state, the filter's transition matrix.
PlanarEkf::Covariance strapdown_jacobian(const PlanarEkf::State& x, double dt, const ImuReading& begin,
                                         const ImuReading& end);

}  // namespace driftlab::host::nav
