// Per-channel drift analysis; see drift_analysis.hpp.
#include "host/fit/drift_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "host/stats/lone_values.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::fit {

std::string DriftAnalysis::undetermined_reason() const {
    if (t_beyond_record)
        return "T is beyond the record, which determines only the initial slope C1/T" +
               std::string(fit.status == FitStatus::singular ? " (the fit is singular)" : "");
    if (fit.status == FitStatus::singular) return "the fit is singular (C1, C2 and T are not separately determined)";
    return "";
}

namespace {

// What the fit's time axis and result say about how far to trust C1, C2 and T.
void fit_warnings(DriftAnalysis& out) {
    // A plain table's row index read as seconds had been printed as seconds, unremarked.
    if (out.data.index_period_s > 0.0)
        out.warnings.push_back("no time column: t is the row index x " + format_double(out.data.index_period_s) +
                               " s (--sample-period or --tau0); name the time column with --time-column if the table "
                               "has one");
    // A record that starts 100 spans after power-on (Unix time) holds a transient as short as itself only as
    // exp(-100) of C1: the fit is singular, or reads a slow drift as T far beyond the record.
    const double span_s = out.data.t_s.back() - out.data.t_s.front();
    if (out.data.t_s.front() > 100.0 * span_s)
        out.warnings.push_back("times start at " + significant(out.data.t_s.front(), 3) +
                               " s, over 100x the record's span of " + significant(span_s, 3) +
                               " s: eq. 1 counts from power-on; subtract the power-on time (or the "
                               "first row's) from the time column");
    if (out.fit.status == FitStatus::singular)
        out.warnings.push_back("fit is singular (condition number " + fixed_point(out.fit.condition_number, 0) +
                               "): C1, C2 and T are not separately determined by these data; no intervals");
    if (out.fit.status == FitStatus::iteration_limit)
        out.warnings.push_back("fit stopped at the evaluation limit (" + std::to_string(out.fit.function_evaluations) +
                               "); parameters are the last iterate");
    out.t_beyond_record = out.fit.start.t_at_upper_end || beyond_record(out.fit.parameters.t_s, out.data.t_s.back());
    out.t_below_sampling = out.fit.start.t_at_lower_end || out.fit.parameters.t_s < out.sample_period_s;
    if (out.t_beyond_record)
        out.warnings.push_back("T (" + to_precision_of(out.plain.t_s.value, out.plain.t_s.stderr_) +
                               " s) is beyond the record (ends at t = " + fixed_point(out.data.t_s.back(), 1) +
                               " s): the data show no settling, so only the initial slope C1/T is well determined (" +
                               with_error(out.plain.initial_slope) + " per s)");
    if (out.t_below_sampling)
        out.warnings.push_back("T (" + significant(out.fit.parameters.t_s, 3) +
                               " s) is shorter than the sampling interval: the transient is not resolved");
}

// What the residual's whiteness says about the intervals; `lone`: values that may hold most of its variance.
void whiteness_warnings(DriftAnalysis& out, const stats::LoneValues& lone, std::size_t n) {
    const auto& w = out.whiteness;
    const std::string not_white = "residual is not white (Ljung-Box p = " + significant(w.ljung_box.p_value, 3) + ", " +
                                  fixed_point(100.0 * w.fraction_inside, 1) + " % of ensemble lags inside +-2 sigma)";
    if (!w.white && out.fit.status == FitStatus::singular) {
        // A singular fit's intervals are infinite, widened or not: there is no interval to advise.
        out.warnings.push_back(not_white);
    } else if (!w.white && w.autocorrelation_time.tau <= 1.0) {
        // Rejected, yet no positive correlation to widen by (negative lag-1 correlation, or a structure the window
        // stops before): the widened intervals are the plain ones, which cannot be vouched for.
        out.warnings.push_back(not_white +
                               ", but its integrated autocorrelation time is not above 1 sample: there is "
                               "nothing to widen the intervals by, and they may still be too narrow");
    } else if (!w.white) {
        out.warnings.push_back(
            not_white + ": the plain intervals are too narrow by about x" + fixed_point(out.widened.inflation, 2) +
            " (autocorrelation time " + fixed_point(w.autocorrelation_time.tau, 2) + " samples, effective n " +
            fixed_point(static_cast<double>(n) / w.autocorrelation_time.tau, 0) + "); use the widened intervals" +
            (w.autocorrelation_time.window_found ? ""
                                                 : " (a lower bound: the correlation outlasts the lags examined)"));
    } else if (lone.variance_share > 0.5) {
        // Ljung-Box divides by the residual's variance: values holding most of it set every rho_k near 0, whatever
        // the other rows do. An AR(1) residual with one impulse had been called white.
        const bool several = lone.indices.size() > 1;
        out.warnings.push_back(std::string("the verdict 'white' is that of the lone ") +
                               (several ? "values above, which hold" : "value above, which holds") +
                               " most of the variance the Ljung-Box test divides by (" +
                               fixed_point(100.0 * w.fraction_inside, 1) +
                               " % of ensemble lags inside +-2 sigma): leave " + (several ? "them" : "it") +
                               " out with --exclude to test the other rows");
    }
}

}  // namespace

DriftAnalysis analyse_drift(const Series& series, const AnalysisOptions& options) {
    DriftAnalysis out;
    out.data = rows_kept(series, options.t_min_s, options.t_max_s, options.excluded);
    const std::string where = "series '" + series.name + "'";
    const std::size_t n = out.data.t_s.size();
    if (n < kMinAnalysisSamples)
        throw DataError(series.source, 0, too_few_kept(series, n, "the fit", kMinAnalysisSamples));
    // Eq. 1's t counts from power-on: before it the exponential grows without bound, and the fit had ended in NaN
    // residuals reported as "every sequence of the residual is constant".
    if (out.data.t_s.front() < 0.0)
        throw DataError(series.source, 0,
                        where + ": its time starts at " + format_double(out.data.t_s.front()) +
                            " s, but eq. 1 counts from power-on: give times since power-on (or --from 0)");
    const auto [lo, hi] = std::minmax_element(out.data.values.begin(), out.data.values.end());
    if (*lo == *hi)
        throw DataError(series.source, 0, where + " is constant (" + format_double(*lo) + "): nothing to fit");

    out.sample_period_s = stats::median_spacing_s(out.data.t_s);
    double longest_spacing_s = 0.0;
    for (std::size_t k = 1; k < n; ++k) {
        const double dt = out.data.t_s[k] - out.data.t_s[k - 1];
        out.time_gaps += dt > 1.5 * out.sample_period_s;
        longest_spacing_s = std::max(longest_spacing_s, dt);
    }
    // Rows in bursts (an MPU6050 read 100 times a second in bursts 2 ms apart) come far less often than their median
    // spacing says: 50 s at the median had made sequences of 247 s. L seconds hold L / mean samples.
    const double mean_spacing_s = stats::mean_spacing_s(out.data.t_s);
    const bool median_is_rate = stats::spacing_agrees(out.sample_period_s, mean_spacing_s);

    out.fit = fit_drift(out.data.t_s, out.data.values, options.fit);
    try {
        out.whiteness = stats::test_whiteness(out.fit.residual, median_is_rate ? out.sample_period_s : mean_spacing_s,
                                              options.whiteness);
    } catch (const UsageError& e) {
        // A residual the test cannot take (constant in every sequence) is this series' data, not the command line.
        throw DataError(series.source, 0, where + ": " + e.what());
    }
    out.plain = parameter_intervals(out.fit, 1.0);
    out.widened =
        out.whiteness.white ? out.plain : parameter_intervals(out.fit, out.whiteness.autocorrelation_time.tau);

    // First: a corrupt row is in every figure below.
    const stats::LoneValues lone = stats::lone_values(out.data.values, code_of(out.data));
    if (auto warning = stats::lone_values_warning(out.data.t_s, out.data.values, lone))
        out.warnings.push_back(std::move(*warning));
    fit_warnings(out);
    whiteness_warnings(out, lone, n);
    // In rows that come in bursts every burst's end counts (17270 on the MPU6050 file): the longest says whether a
    // real gap is among them.
    if (out.time_gaps > 0)
        out.warnings.push_back(std::to_string(out.time_gaps) + " gaps in time (spacing > 1.5x the median " +
                               significant(out.sample_period_s, 3) + " s; the longest " +
                               significant(longest_spacing_s, 3) + " s" +
                               (median_is_rate ? "" : ", most of them the ends of the bursts the rows come in") +
                               "): the fit uses the true times, the autocorrelation counts lags in samples");
    if (!median_is_rate)
        out.warnings.push_back("rows are " + stats::spacing_text(out.data.t_s) +
                               ": the whiteness sequences and lags count samples at the mean spacing");
    if (!out.whiteness.adaptation.empty()) out.warnings.push_back("whiteness: " + out.whiteness.adaptation);
    return out;
}

}  // namespace driftlab::host::fit
