// The ground truth table; see truth_table.hpp.
#include "sim/motion/truth_table.hpp"

#include <cstdio>

namespace driftlab::sim {

std::string truth_path_for(const std::string& log_path) {
    const std::string ext = ".csv";
    const bool csv =
        log_path.size() > ext.size() && log_path.compare(log_path.size() - ext.size(), ext.size(), ext) == 0;
    return (csv ? log_path.substr(0, log_path.size() - ext.size()) : log_path) + ".truth.csv";
}

std::string truth_table(const Trajectory& trajectory, const std::string& name, double rest_before_s,
                        const std::vector<double>& rows_t_s) {
    char line[256];
    std::snprintf(line, sizeof line, "# driftlab ground truth v1\n# trajectory: %s\n# rest_before_s: %g\n",
                  name.c_str(), rest_before_s);
    std::string out = line;
    out += "t_s,x_m,y_m,heading_deg,speed_mps,yaw_rate_dps,accel_x_g,accel_y_g,accel_z_g\n";
    for (const double t : rows_t_s) {
        const MotionState s = trajectory.state_at(t);
        std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f\n", t, s.x_m, s.y_m,
                      s.heading_deg, s.speed_mps, s.input.yaw_rate_dps, s.input.accel_x_g, s.input.accel_y_g, 1.0);
        out += line;
    }
    return out;
}

}  // namespace driftlab::sim
