// Three-node thermal RC network (die -> package -> board -> ambient) heated at the die from power-on; the signal
// is the board node's rise, which after the die's own warm-up (the base eq. 1) appears as a slower, S-shaped
// extra drift. Integrated by exact steps of the linear system (Eigen matrix exponential). truth.hpp.
#include <cmath>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include "host/gap_eval/truth.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {

std::vector<double> truth_thermal_rc(const std::vector<double>& t_s, double size_counts, std::uint64_t seed) {
    sim::Rng rng(seed, 0x71);
    const double span_s = t_s.back() - t_s.front();
    // Node time constants: the board is slow (a quarter to two thirds of the log), the package between.
    const double tau_board = span_s * (0.25 + 0.4 * rng.uniform());
    const double tau_pkg = tau_board * (0.1 + 0.2 * rng.uniform());
    const double tau_die = tau_pkg * 0.2;
    // dT/dt = A T + b: each node relaxes towards its neighbours; heat enters at the die.
    Eigen::Matrix3d a;
    a << -2.0 / tau_die, 1.0 / tau_die, 0.0, 1.0 / tau_pkg, -2.0 / tau_pkg, 1.0 / tau_pkg, 0.0, 1.0 / tau_board,
        -2.0 / tau_board;
    const Eigen::Vector3d b(1.0 / tau_die, 0.0, 0.0);
    const Eigen::Vector3d steady = -a.inverse() * b;
    std::vector<double> out(t_s.size());
    Eigen::Vector3d temp = Eigen::Vector3d::Zero();
    double t_prev = 0.0;
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        // Exact step of the linear ODE: T(t+h) = T* + e^{A h} (T(t) - T*).
        const Eigen::Matrix3d step = (a * (t_s[k] - t_prev)).exp();
        temp = steady + step * (temp - steady);
        t_prev = t_s[k];
        out[k] = size_counts * temp(2) / steady(2);
    }
    if (rng.uniform() < 0.5)
        for (double& v : out) v = -v;
    return out;
}

}  // namespace driftlab::host::gap
