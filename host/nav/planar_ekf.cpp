#include "host/nav/planar_ekf.hpp"

#include <cmath>

namespace driftlab::host::nav {

PlanarEkf::PlanarEkf(const FilterNoise& noise, const std::array<double, 3>& initial_bias_sd) : noise_(noise) {
    for (int k = 0; k < 3; ++k) p_(bias_gyro + k, bias_gyro + k) = initial_bias_sd[k] * initial_bias_sd[k];
}

namespace {

// What a step's state change and its Jacobian share: the rate and the specific force less the biases, and the
// rotation at the step's middle heading (second order, as the trapezoid on the rate).
struct Step {
    double rate;
    Eigen::Vector2d a_body;
    Eigen::Matrix2d rot, rot_d;  // body to start frame, and its derivative by the heading
    Step(const PlanarEkf::State& x, double dt, const ImuReading& begin, const ImuReading& end) {
        rate = 0.5 * (begin.yaw_rate + end.yaw_rate) - x(PlanarEkf::bias_gyro);
        a_body = {0.5 * (begin.ax + end.ax) - x(PlanarEkf::bias_ax), 0.5 * (begin.ay + end.ay) - x(PlanarEkf::bias_ay)};
        const double mid = x(PlanarEkf::heading) + 0.5 * rate * dt;
        const double c = std::cos(mid), s = std::sin(mid);
        rot << c, -s, s, c;
        rot_d << -s, -c, c, -s;
    }
};

}  // namespace

PlanarEkf::State strapdown_step(const PlanarEkf::State& x0, double dt, const ImuReading& begin, const ImuReading& end) {
    using E = PlanarEkf;
    const Step st(x0, dt, begin, end);
    const Eigen::Vector2d dv = st.rot * st.a_body * dt;
    PlanarEkf::State x = x0;
    x.segment<2>(E::x) += x0.segment<2>(E::vx) * dt + 0.5 * dv * dt;
    x.segment<2>(E::vx) += dv;
    x(E::heading) += st.rate * dt;
    return x;
}

PlanarEkf::Covariance strapdown_jacobian(const PlanarEkf::State& x0, double dt, const ImuReading& begin,
                                         const ImuReading& end) {
    using E = PlanarEkf;
    const Step st(x0, dt, begin, end);
    const Eigen::Vector2d dv_dheading = st.rot_d * st.a_body * dt;
    PlanarEkf::Covariance f = PlanarEkf::Covariance::Identity();
    f(E::heading, E::bias_gyro) = -dt;
    f.block<2, 1>(E::vx, E::heading) = dv_dheading;
    f.block<2, 1>(E::vx, E::bias_gyro) = dv_dheading * (-0.5 * dt);
    f.block<2, 2>(E::vx, E::bias_ax) = -st.rot * dt;
    f.block<2, 2>(E::x, E::vx) = Eigen::Matrix2d::Identity() * dt;
    f.block<2, 1>(E::x, E::heading) = 0.5 * dt * dv_dheading;
    f.block<2, 1>(E::x, E::bias_gyro) = 0.5 * dt * dv_dheading * (-0.5 * dt);
    f.block<2, 2>(E::x, E::bias_ax) = -0.5 * dt * dt * st.rot;
    return f;
}

void PlanarEkf::predict(double dt, const ImuReading& begin, const ImuReading& end) {
    const Covariance f = strapdown_jacobian(x_, dt, begin, end);
    const Step st(x_, dt, begin, end);
    // White noise of density N averaged over the step has variance N^2 / dt; it enters as the readings do.
    Eigen::Matrix<double, kStates, 3> g = Eigen::Matrix<double, kStates, 3>::Zero();
    g(heading, 0) = -dt;
    g.block<2, 2>(vx, 1) = -st.rot * dt;
    g.block<2, 2>(x, 1) = -0.5 * dt * dt * st.rot;
    Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
    Covariance q = Covariance::Zero();
    for (int k = 0; k < 3; ++k) {
        w(k, k) = noise_.white_density[k] * noise_.white_density[k] / dt;
        q(bias_gyro + k, bias_gyro + k) = noise_.bias_walk_psd[k] * dt;
    }
    q += g * w * g.transpose();
    x_ = strapdown_step(x_, dt, begin, end);
    p_ = f * p_ * f.transpose() + q;
}

template <int M>
void PlanarEkf::update(const Eigen::Matrix<double, M, 1>& innovation, const Eigen::Matrix<double, M, kStates>& h,
                       const Eigen::Matrix<double, M, M>& r) {
    const Eigen::Matrix<double, M, M> s = h * p_ * h.transpose() + r;
    const Eigen::Matrix<double, kStates, M> k = p_ * h.transpose() * s.inverse();
    x_ += k * innovation;
    // Joseph form: the covariance stays symmetric and positive over hours of updates.
    const Covariance a = Covariance::Identity() - k * h;
    p_ = a * p_ * a.transpose() + k * r * k.transpose();
}

bool PlanarEkf::update_zero_velocity(double sd, double gate, bool apply) {
    Eigen::Matrix<double, 2, kStates> h = Eigen::Matrix<double, 2, kStates>::Zero();
    h(0, vx) = h(1, vy) = 1.0;
    const Eigen::Matrix2d r = Eigen::Matrix2d::Identity() * sd * sd;
    const Eigen::Vector2d v = x_.segment<2>(vx);
    const Eigen::Matrix2d s = p_.block<2, 2>(vx, vx) + r;
    if (v.dot(s.ldlt().solve(v)) > gate) return false;
    if (apply) update<2>(-v, h, r);
    return true;
}

void PlanarEkf::update_bias_at_rest(const ImuReading& reading, double dt) {
    // One axis at a time (the noise is independent between them), and none without noise: an axis the log does not
    // record reads nothing about its bias.
    const std::array<double, 3> z = {reading.yaw_rate, reading.ax, reading.ay};
    for (int k = 0; k < 3; ++k) {
        const double r = noise_.white_density[k] * noise_.white_density[k] / dt;
        if (!(r > 0.0)) continue;
        Eigen::Matrix<double, 1, kStates> h = Eigen::Matrix<double, 1, kStates>::Zero();
        h(0, bias_gyro + k) = 1.0;
        update<1>(Eigen::Matrix<double, 1, 1>(z[k] - x_(bias_gyro + k)), h, Eigen::Matrix<double, 1, 1>(r));
    }
}

void PlanarEkf::update_odometry(double speed, double speed_sd, double lateral_sd) {
    const double c = std::cos(x_(heading)), s = std::sin(x_(heading));
    const double vxv = x_(vx), vyv = x_(vy);
    const Eigen::Vector2d predicted(c * vxv + s * vyv, -s * vxv + c * vyv);  // the velocity in the body frame
    Eigen::Matrix<double, 2, kStates> h = Eigen::Matrix<double, 2, kStates>::Zero();
    h(0, heading) = -s * vxv + c * vyv;
    h(1, heading) = -c * vxv - s * vyv;
    h(0, vx) = c, h(0, vy) = s;
    h(1, vx) = -s, h(1, vy) = c;
    Eigen::Matrix2d r = Eigen::Matrix2d::Zero();
    r(0, 0) = speed_sd * speed_sd;
    r(1, 1) = lateral_sd * lateral_sd;
    update<2>(Eigen::Vector2d(speed, 0.0) - predicted, h, r);
}

void PlanarEkf::update_position(double px, double py, double sd) {
    Eigen::Matrix<double, 2, kStates> h = Eigen::Matrix<double, 2, kStates>::Zero();
    h(0, x) = h(1, y) = 1.0;
    update<2>(Eigen::Vector2d(px, py) - x_.segment<2>(x), h, Eigen::Matrix2d::Identity() * sd * sd);
}

double PlanarEkf::heading_nees(double true_heading_rad) const {
    const double e = x_(heading) - true_heading_rad;
    return e * e / p_(heading, heading);
}

double PlanarEkf::pose_nees(double true_x, double true_y, double true_heading_rad) const {
    const Eigen::Vector3d e(x_(x) - true_x, x_(y) - true_y, x_(heading) - true_heading_rad);
    return e.dot(p_.block<3, 3>(x, x).ldlt().solve(e));
}

}  // namespace driftlab::host::nav
