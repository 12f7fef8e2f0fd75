// The yaw-rate plot of a run in motion; see motion_view.hpp.
#include "host/view/motion_view.hpp"

#include "host/view/gnuplot.hpp"

namespace driftlab::host::view {

void write_yaw_rate_plot(const std::string& dir, const std::vector<double>& t_s, const std::vector<double>& truth_dps,
                         const std::vector<double>& measured_dps) {
    Plot plot;
    plot.title = "Yaw rate: the truth and the gyro's reading";
    plot.x_label = "t [s of the board's clock]";
    plot.y_label = "yaw rate [deg/s]";
    plot.series.push_back({"gyro (counts less eq. 1, over counts per deg/s)",
                           t_s,
                           measured_dps,
                           {},
                           {},
                           SeriesStyle::lines,
                           false,
                           "#1f77b4",
                           1.5});
    plot.series.push_back({"truth", t_s, truth_dps, {}, {}, SeriesStyle::lines, true, "#d62728", 1.5});
    render_plot(plot, dir, "hil_yaw_rate");
}

}  // namespace driftlab::host::view
