// The paper's figures for one channel as Plot descriptions (gnuplot.hpp): Fig. 2 raw vs smoothed,
// Fig. 3 data and fitted eq. 1, Fig. 4 ensemble autocorrelation with its +-2 sigma bounds.
#pragma once

#include <optional>

#include "host/fit/drift_analysis.hpp"
#include "host/view/gnuplot.hpp"

namespace driftlab::host::view {

/// Points drawn at most per curve; longer series are thinned (every k-th sample) for the picture only.
inline constexpr std::size_t kMaxPlotPoints = 4000;

/// Fig. 2: raw codes and the smoothed estimate against time; nullopt when the series has no raw values.
std::optional<Plot> raw_vs_smoothed_plot(const fit::DriftAnalysis& a);

/// Fig. 3: data and the fitted curve eq. 1.
Plot drift_fit_plot(const fit::DriftAnalysis& a);

/// Fig. 4: ensemble-averaged normalised autocorrelation of the residual against lag [s], with bounds.
Plot autocorrelation_plot(const fit::DriftAnalysis& a);

}  // namespace driftlab::host::view
