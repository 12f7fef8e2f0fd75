// The gap report; see gap_report.hpp.
#include "host/gap/gap_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/fit/lm_fit.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/sim_chain.hpp"
#include "host/gap/spectral.hpp"
#include "host/report/gnuplot.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kBandReplicates = 12;

struct Band {
    std::vector<double> low, high;
};

// Pointwise min/max of the residual ADEV over a few replicates: the band the real curve should fall in.
Band adev_band(const GapModel& model, const LogData& log, std::size_t c, std::size_t max_m, std::uint64_t seed) {
    Band band;
    for (int r = 0; r < kBandReplicates; ++r) {
        SimRequest req;
        req.t_s = &log.t_s;
        req.channels = {};
        req.channels[c] = true;
        const SimOutput sim = simulate(model, req, replicate_seed(seed, r));
        const auto dev = octave_oadev(fit::fit_drift(log.t_s, sim[c], start_at_model(model, static_cast<Channel>(c))).residual, max_m);
        if (band.low.empty()) band.low = band.high = dev;
        for (std::size_t j = 0; j < dev.size(); ++j) {
            band.low[j] = std::min(band.low[j], dev[j]);
            band.high[j] = std::max(band.high[j], dev[j]);
        }
    }
    return band;
}

std::string fixed(double v, int digits = 2) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}

}  // namespace

void write_gap_report(const GapResult& r, const LogData& log, const std::string& dir, const GapOptions& options) {
    std::filesystem::create_directories(dir);
    std::ostringstream md;
    md << "# Sim-to-real gap: " << log.source_name << "\n\n";
    md << "**Verdict: " << r.verdict << "**\n\n";
    md << "Gap score (mean z^2 of the battery over its replicate null; about 1 when the simulator explains the log), "
       << options.replicates << " replicates; " << holdout_description(options.holdout, options.fit_fraction)
       << ". A held-out score within its bound (level " << options.alpha << ") is a closed gap."
       << "\n\n| | fitting part | held-out part | held-out bound |\n|---|---|---|---|\n";
    md << "| base simulator | " << fixed(r.gap_before_fit) << " | " << fixed(r.gap_before_heldout) << " | "
       << fixed(r.gap_bound_before) << " |\n";
    md << "| with accepted effects | " << fixed(r.gap_after_fit) << " | " << fixed(r.gap_after_heldout) << " | "
       << fixed(r.gap_bound_after) << " |\n\n";
    md << "## Where: located cells (|z| > " << fixed(r.before.threshold) << ", beyond the practical margin)\n\n";
    md << "| statistic | channel | cell | part | z | ratio or difference [95 % interval] |\n|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < r.located.size() && i < 30; ++i) {
        const auto& l = r.located[i];
        const auto& c = r.layout[l.index];
        md << "| " << c.statistic << " | " << c.channel << " | " << c.cell << " | " << segment_name(c.segment) << " | "
           << fixed(l.z, 1) << " | " << (std::isnan(l.ratio) ? "diff " + fixed(l.difference, 3) : "ratio " + fixed(l.ratio, 3))
           << " [" << fixed(l.interval_low, 3) << ", " << fixed(l.interval_high, 3) << "] |\n";
    }
    md << "\n" << r.located.size() << " cells located before, " << r.located_after.size() << " after.\n\n";
    if (r.diffuse_gap)
        md << "Diffuse gap: the held-out score exceeds its bound with no cell located (many cells a little off, none "
              "alone beyond the threshold). "
           << (options.search_diffuse ? "The candidates were searched on it (--search-diffuse).\n\n"
                                      : "The candidates were not searched (--search-diffuse searches them).\n\n");
    md << "## Which: candidate effects\n\nFitted on the fitting part, judged on the held-out part; among accepted "
          "Gaussian candidates the full-log spectral information criterion ("
       << criterion_name(options.explain_options.information_criterion)
       << ") chooses.\n\n"
          "| step | effect | channel | parameters | held-out gap | shrink | gain / penalty | delta IC | decision |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& e : r.tried) {
        std::string params;
        for (const auto& [k, v] : e.params) params += k + "=" + fixed(v, 4) + " ";
        md << "| " << e.step << " | " << e.effect << " | " << e.channel << " | " << params << " | " << fixed(e.heldout_before)
           << " -> " << fixed(e.heldout_after) << " | " << fixed(100 * e.heldout_shrink, 0) << " % | " << fixed(e.loss_gain, 1)
           << " / " << fixed(e.penalty, 1) << " | " << (has_delta_ic(e) ? fixed(delta_ic(e, options.explain_options.information_criterion), 1) : std::string("-")) << " | "
           << (e.accepted ? "accepted" : "rejected")
           << (e.residual_step.significant ? ", leaves a level step" : "")
           << (e.ambiguous_with.empty() ? "" : ", ambiguous with " + e.ambiguous_with + " (" + e.settle + ")") << " |\n";
    }
    for (const auto& s : r.level_steps) {
        md << "\nLevel-step test, " << kChannelNames[channel_index(s.channel)] << ": two steps of "
           << fixed(s.steps[0].size_counts, 3) << " counts at t = " << fixed(s.steps[0].t_s, 1) << " s and "
           << fixed(s.steps[1].size_counts, 3) << " counts at t = " << fixed(s.steps[1].t_s, 1)
           << " s: likelihood over the explanation " << fixed(s.statistic, 1) << " (price " << fixed(s.margin, 1)
           << ", p " << fixed(s.rival_p, 3) << "); largest whitened impulse " << fixed(s.impulse, 2) << " (p "
           << fixed(s.impulse_p, 3) << "); combined p = " << fixed(s.p_value, 3)
           << (s.significant ? " (significant: a step no library effect makes; the log is unexplained)" : " (none beyond the model's own)")
           << "\n";
    }
    md << "\nNot identifiable from a static log:\n\n";
    for (const auto& n : not_identifiable_list()) md << "- " << n.effect << ": " << n.reason << "\n";
    md << "\n## Residual Allan deviation: real vs simulator bands\n\n";
    const bool plots = report::gnuplot_available();
    if (!plots) md << "(gnuplot not found: plots skipped)\n";
    for (std::size_t c = 0; c < kChannelCount && plots; ++c) {
        if (!r.channels[c]) continue;
        const std::size_t max_m = std::max<std::size_t>(1, log.size() / 8);
        const auto real = octave_oadev(fit::fit_drift(log.t_s, log.counts[c]).residual, max_m);
        const Band base = adev_band(r.base, log, c, max_m, options.seed);
        const Band after = adev_band(r.final_model, log, c, max_m, options.seed);
        std::vector<double> tau(real.size());
        for (std::size_t j = 0; j < tau.size(); ++j) tau[j] = r.base.smoothing.sample_period_s * std::ldexp(1.0, static_cast<int>(j));
        report::Plot p;
        p.title = std::string("Residual ADEV, ") + kChannelNames[c];
        p.x_label = "tau [s]";
        p.y_label = "ADEV of the eq. 1 residual [counts]";
        p.log_x = p.log_y = true;
        p.series.push_back({"real", tau, real, {}, {}, report::SeriesStyle::lines, false, "black", 2.5});
        p.series.push_back({"base sim min", tau, base.low, {}, {}, report::SeriesStyle::lines, true, "red", 1.2});
        p.series.push_back({"base sim max", tau, base.high, {}, {}, report::SeriesStyle::lines, true, "red", 1.2});
        if (!r.accepted.empty()) {
            p.series.push_back({"with effects min", tau, after.low, {}, {}, report::SeriesStyle::lines, false, "blue", 1.2});
            p.series.push_back({"with effects max", tau, after.high, {}, {}, report::SeriesStyle::lines, false, "blue", 1.2});
        }
        const std::string name = std::string("gap_adev_") + kChannelNames[c];
        report::render_plot(p, dir, name, {report::ImageFormat::png});
        md << "![" << name << "](" << name << ".png)\n\n";
    }
    std::ofstream out(dir + "/gap.md");
    out << md.str();
    if (!out) throw DeviceError(dir + "/gap.md", "cannot write the report");
}

}  // namespace driftlab::host::gap
