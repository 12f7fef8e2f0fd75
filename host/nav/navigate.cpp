#include "host/nav/navigate.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "host/nav/input_correction.hpp"
#include "host/nav/stop_detector.hpp"
#include "host/stats/chi_square.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::nav {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
/// A robot on its wheels stands still: the zero velocity is known to 1 mm/s.
constexpr double kStopSpeedSd = 0.001;

struct VariantSpec {
    const char* name;
    bool eq1;
    bool filter;
};
constexpr std::array<VariantSpec, 4> kVariants = {
    {{"raw", false, false}, {"forward", true, false}, {"ekf", false, true}, {"forward+ekf", true, true}}};

// The filter's noise in SI units: the unit's Allan terms where known, else the white noise of the initial rest.
FilterNoise filter_noise(const std::optional<UnitDrift>& drift, const InitialRest& rest, double period_s,
                         const std::array<double, kNavAxes>& cps, bool walks, bool heading_only,
                         const std::array<double, kNavAxes>& effects_psd) {
    FilterNoise n;
    for (std::size_t k = 0; k < (heading_only ? 1 : kNavAxes); ++k) {  // an axis not recorded has no noise
        const double white = drift ? drift->axes[k].white_density : rest.sd[k] * std::sqrt(period_s);
        n.white_density[k] = white / cps[k];
        if (walks && drift) n.bias_walk_psd[k] = drift->axes[k].bias_walk_psd() / (cps[k] * cps[k]);
        if (walks) n.bias_walk_psd[k] += effects_psd[k];
    }
    return n;
}

class TrackRecorder {
public:
    TrackRecorder(Track& t, const std::optional<NavTruth>& truth, bool heading_only)
        : t_(t), truth_(truth), heading_only_(heading_only) {}
    void record(std::size_t i, double t_s, const PlanarEkf& f, bool stopped) {
        const auto& s = f.state();
        const auto& p = f.covariance();
        t_.x_m.push_back(s(PlanarEkf::x));
        t_.y_m.push_back(s(PlanarEkf::y));
        t_.heading_deg.push_back(s(PlanarEkf::heading) * kDegPerRad);
        t_.heading_sd_deg.push_back(std::sqrt(p(PlanarEkf::heading, PlanarEkf::heading)) * kDegPerRad);
        t_.position_sd_m.push_back(std::sqrt(p(PlanarEkf::x, PlanarEkf::x) + p(PlanarEkf::y, PlanarEkf::y)));
        if (truth_)
            t_.nees.push_back(i == 0 ? NAN
                              : heading_only_
                                  ? f.heading_nees(truth_->heading_deg(i) / kDegPerRad)
                                  : f.pose_nees(truth_->x(i), truth_->y(i), truth_->heading_deg(i) / kDegPerRad));
        if (stopped && (t_.stops.empty() || t_.stops.back().to_s != last_t_)) t_.stops.push_back({t_s, t_s});
        if (stopped) t_.stops.back().to_s = t_s;
        last_t_ = t_s;
    }

private:
    Track& t_;
    const std::optional<NavTruth>& truth_;
    bool heading_only_;
    double last_t_ = NAN;
};

struct RunContext {
    const LogData& log;
    const std::optional<NavTruth>& truth;
    const NavOptions& options;
    std::array<double, kNavAxes> cps;
    double period_s;
    bool heading_only;
};

Track run_variant(const RunContext& ctx, const VariantSpec& spec, const InputCorrection& correction,
                  const FilterNoise& noise) {
    Track track;
    track.name = spec.name;
    track.filter = spec.filter;
    std::array<double, 3> bias_sd0{}, reading_sd{};
    for (std::size_t k = 0; k < kNavAxes; ++k) {
        bias_sd0[k] = correction.sd_counts()[k] / ctx.cps[k];
        reading_sd[k] = noise.white_density[k] / std::sqrt(ctx.period_s);
    }
    PlanarEkf f(noise, bias_sd0);
    StopDetector stops(ctx.options.stop_window_s, reading_sd);
    const AidOptions& aid = ctx.options.aid;
    std::mt19937_64 rng(aid.seed);  // the same aid noise for every variant
    std::normal_distribution<double> unit_normal;
    const double gate = stats::chi_square_quantile(0.99, 2.0);
    TrackRecorder rec(track, ctx.truth, ctx.heading_only);

    ImuReading prev = reading(ctx.log, 0, correction, ctx.cps);
    rec.record(0, ctx.log.t_s[0], f, false);
    double last_fix_s = ctx.log.t_s[0];
    for (std::size_t i = 1; i < ctx.log.size(); ++i) {
        const double t = ctx.log.t_s[i], dt = t - ctx.log.t_s[i - 1];
        const ImuReading cur = reading(ctx.log, i, correction, ctx.cps);
        f.predict(dt, prev, cur);
        stops.push(t, cur);
        const auto& s = f.state();
        const auto& p = f.covariance();
        std::array<double, 3> bias{}, bias_sd{};
        for (int k = 0; k < 3; ++k) {
            bias[k] = s(PlanarEkf::bias_gyro + k);
            bias_sd[k] = std::sqrt(p(PlanarEkf::bias_gyro + k, PlanarEkf::bias_gyro + k));
        }
        bool stopped = false;
        if (stops.quiet(bias, bias_sd)) {
            const bool apply = spec.filter && aid.zupt;
            stopped = f.update_zero_velocity(kStopSpeedSd, gate, apply);
            if (stopped && apply) {
                f.update_bias_at_rest(cur, dt);
                ++track.zero_velocity_updates;
            }
        }
        if (spec.filter && aid.odometry) {
            f.update_odometry(ctx.truth->speed(i) + aid.odometry_sd_mps * unit_normal(rng), aid.odometry_sd_mps,
                              aid.odometry_sd_mps);
            ++track.odometry_updates;
        }
        if (spec.filter && aid.fixes && t - last_fix_s >= aid.fix_every_s) {
            f.update_position(ctx.truth->x(i) + aid.fix_sd_m * unit_normal(rng),
                              ctx.truth->y(i) + aid.fix_sd_m * unit_normal(rng), aid.fix_sd_m);
            ++track.position_fixes;
            last_fix_s = t;
        }
        rec.record(i, t, f, stopped);
        prev = cur;
    }
    return track;
}

}  // namespace

bool enable_aid(AidOptions& aid, const std::string& name) {
    if (name == "none") return true;
    bool* flag = name == "zupt"       ? &aid.zupt
                 : name == "odometry" ? &aid.odometry
                 : name == "fixes"    ? &aid.fixes
                                      : nullptr;
    if (flag) *flag = true;
    return flag != nullptr;
}

NavTruth::NavTruth(const TruthFile& file, std::vector<std::size_t> rows) : file_(&file), rows_(std::move(rows)) {
    if (rows_.empty()) return;
    x0_ = file.x_m[rows_[0]];
    y0_ = file.y_m[rows_[0]];
    heading0_deg_ = file.heading_deg[rows_[0]];
    cos0_ = std::cos(heading0_deg_ / kDegPerRad);
    sin0_ = std::sin(heading0_deg_ / kDegPerRad);
}

double NavTruth::x(std::size_t i) const {
    if (!file_) return 0.0;
    const double dx = file_->x_m[rows_[i]] - x0_, dy = file_->y_m[rows_[i]] - y0_;
    return cos0_ * dx + sin0_ * dy;
}

double NavTruth::y(std::size_t i) const {
    if (!file_) return 0.0;
    const double dx = file_->x_m[rows_[i]] - x0_, dy = file_->y_m[rows_[i]] - y0_;
    return -sin0_ * dx + cos0_ * dy;
}

double NavTruth::heading_deg(std::size_t i) const { return file_ ? file_->heading_deg[rows_[i]] - heading0_deg_ : 0.0; }

NavRun navigate(const LogData& log, const sim::SimModel& unit, const std::optional<UnitDrift>& drift,
                const std::optional<NavTruth>& truth, const NavOptions& options) {
    if (log.size() < 3) throw DataError(log.source_name, 0, "fewer than 3 rows: nothing to navigate");
    if (!log.recorded[channel_index(Channel::gyro)])
        throw DataError(log.source_name, 0, "no gyro channel: planar navigation needs at least the heading's rate");
    const bool ax = log.recorded[channel_index(Channel::accel_x)], ay = log.recorded[channel_index(Channel::accel_y)];
    if (ax != ay)
        throw DataError(log.source_name, 0,
                        "one horizontal accelerometer without the other: give accel_x and accel_y, or neither "
                        "(heading only)");
    if (drift && ax && !(drift->axes[1].present && drift->axes[2].present))
        throw DataError(log.source_name, 0,
                        "the drift model has no accelerometers (" + drift->source +
                            "), the log has: give a model of "
                            "the same channels");
    if ((options.aid.odometry || options.aid.fixes) && !truth)
        throw UsageError("--aid odometry and fixes are drawn from the ground truth: give --truth (or --at-rest)");
    const InitialRest rest = initial_rest(log, options.rest_s);
    const RunContext ctx{log, truth, options, counts_per_si(unit), stats::median_spacing_s(log.t_s), !ax};
    NavRun run;
    run.t_s = log.t_s;
    run.heading_only = !ax;
    for (const VariantSpec& v : kVariants) {
        if (v.eq1 && !drift) continue;
        const InputCorrection correction = v.eq1 ? InputCorrection::eq1(*drift) : InputCorrection::constant(rest);
        run.tracks.push_back(run_variant(
            ctx, v, correction,
            filter_noise(drift, rest, ctx.period_s, ctx.cps, v.filter, ctx.heading_only, options.effects_bias_psd)));
    }
    if (!drift)
        run.notes.push_back(
            "no drift model (--drift or --fit-from): forward and forward+ekf not run, and the filter's "
            "noise is the initial rest's spread with biases that do not walk");
    else
        run.notes.insert(run.notes.end(), drift->notes.begin(), drift->notes.end());
    if (!options.effects_used.empty())
        run.notes.push_back("the filters' bias walks add the bias processes of the effects given: " +
                            options.effects_used);
    if (run.heading_only)
        run.notes.push_back("no accelerometers: the heading alone is navigated, and its NEES has 1 degree of freedom");
    return run;
}

}  // namespace driftlab::host::nav
