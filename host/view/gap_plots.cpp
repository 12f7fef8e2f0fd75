// The plots of a gap result's report; see gap_plots.hpp.
#include "host/view/gap_plots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "host/fit/lm_fit.hpp"
#include "host/gap/replicates.hpp"
#include "host/stats/spectral.hpp"
#include "host/util/format_number.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gnuplot.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::view {

using gap::GapModel;
using gap::GapOptions;
using gap::GapResult;

namespace {

constexpr int kBandReplicates = 12;

// The report's plots: gap_<kind>_<channel>, as PNG (gap.md links them); plot_bands() draws them, report_files() lists
// them all.
const std::vector<ImageFormat> kPlotFormats{ImageFormat::png};
constexpr std::array<const char*, 3> kPlotKinds{"adev", "mean", "codes"};

std::string plot_name(const char* kind, const std::string& channel) {
    return std::string("gap_") + kind + "_" + channel;
}

struct Band {
    std::vector<double> low, high;

    void widen(const std::vector<double>& v) {
        if (low.empty()) low = high = v;
        for (std::size_t j = 0; j < v.size(); ++j) {
            low[j] = std::min(low[j], v[j]);
            high[j] = std::max(high[j], v[j]);
        }
    }
};

// Sample-index edges of the time bins of the mean-over-time plot: about 30 outputs each, 10 to 60 bins.
std::vector<std::size_t> time_bins(std::size_t n) {
    const std::size_t bins = std::clamp<std::size_t>(n / 30, 10, 60);
    std::vector<std::size_t> edges(bins + 1);
    for (std::size_t b = 0; b <= bins; ++b) edges[b] = b * n / bins;
    return edges;
}

std::vector<double> binned_mean(const std::vector<double>& v, const std::vector<std::size_t>& edges) {
    std::vector<double> out(edges.size() - 1);
    for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
        double sum = 0.0;
        for (std::size_t k = edges[b]; k < edges[b + 1]; ++k) sum += v[k];
        out[b] = sum / static_cast<double>(std::max<std::size_t>(1, edges[b + 1] - edges[b]));
    }
    return out;
}

// The share of rows on each code from `lowest` to `highest` (codes outside count in neither).
std::vector<double> code_shares(const std::vector<double>& codes, int lowest, int highest) {
    std::vector<double> out(static_cast<std::size_t>(highest - lowest + 1), 0.0);
    for (double v : codes) {
        const long code = std::lround(v);
        if (code >= lowest && code <= highest)
            out[static_cast<std::size_t>(code - lowest)] += 1.0 / static_cast<double>(codes.size());
    }
    return out;
}

// The codes a raw-mode log's channel holds, lowest to highest; empty for a channel without raw codes.
struct CodeRange {
    const std::vector<double>* real = nullptr;
    int lowest = 0, highest = -1;
};

// What the real log's eq. 1 residual should fall in under `model`: pointwise min/max over a few replicates, each
// refitted as the log is, of the residual's octave ADEV and of its mean per time bin; and, for a raw-mode channel,
// of the share of rows on each code (where a code of the wrong width shows).
struct ReplicateBands {
    Band adev, mean, codes;
};

ReplicateBands replicate_bands(const GapModel& model, const LogData& log, std::size_t c, std::size_t max_m,
                               const std::vector<std::size_t>& edges, const CodeRange& range, std::uint64_t seed) {
    ReplicateBands bands;
    for (int r = 0; r < kBandReplicates; ++r) {
        sim::OutputRequest req;
        req.t_s = &log.t_s;
        req.channels = {};
        req.channels[c] = true;
        sim::Outputs raw;
        if (range.real) req.raw_codes = &raw;
        const sim::Outputs sim = sim::simulate_outputs(model, req, gap::replicate_seed(seed, r));
        const auto residual = fit::fit_drift(log.t_s, sim[c], start_at_model(model, static_cast<Channel>(c))).residual;
        bands.adev.widen(stats::octave_oadev(residual, max_m));
        bands.mean.widen(binned_mean(residual, edges));
        if (range.real) bands.codes.widen(code_shares(raw[c], range.lowest, range.highest));
    }
    return bands;
}

// The unit plots and step sizes are shown in: the diagnosis's physical one (deg/s; g as mg, so an accelerometer's
// noise does not read in thousandths), through the model's converter, so a plain table's are in its own unit. The
// bands are drawn from counts and scaled after: a constant factor moves no line against another.
std::vector<double> scaled(std::vector<double> v, double k) {
    for (double& x : v) x *= k;
    return v;
}

Band scaled(const Band& b, double k) { return {scaled(b.low, k), scaled(b.high, k)}; }

// A channel's real residual against the replicate bands of the base and of the final model, as DIR/<plot_name()>;
// returns gap.md's link to its image.
std::string plot_bands(const std::string& title, const std::string& x_label, const std::string& y_label, bool log_axes,
                       const std::vector<double>& x, const std::vector<double>& real, const Band& base,
                       const Band* after, const std::string& dir, const std::string& name) {
    Plot p;
    p.title = title;
    p.x_label = x_label;
    p.y_label = y_label;
    p.log_x = p.log_y = log_axes;
    p.series.push_back({"base simulator (" + std::to_string(kBandReplicates) + " replicates)", x, base.low, base.low,
                        base.high, SeriesStyle::band, false, "red", 1.0});
    if (after)
        p.series.push_back(
            {"with the added effects", x, after->low, after->low, after->high, SeriesStyle::band, false, "blue", 1.0});
    p.series.push_back({"real", x, real, {}, {}, SeriesStyle::lines, false, "black", 2.0});
    const std::string image =
        std::filesystem::path(render_plot(p, dir, name, kPlotFormats).front()).filename().string();
    return "![" + name + "](" + image + ")\n\n";
}

// One channel's plots, as gap.md's links to them.
void plot_channel(std::ostream& md, const GapResult& r, const LogData& log, std::size_t c, const std::string& dir,
                  const GapOptions& options, const std::vector<std::size_t>& edges, const std::vector<double>& bin_t) {
    const std::size_t max_m = std::max<std::size_t>(1, log.size() / 8);
    const auto residual = fit::fit_drift(log.t_s, log.counts[c]).residual;
    const auto real = stats::octave_oadev(residual, max_m);
    CodeRange range;
    if (const std::vector<double>* codes = code_column(log, r, c)) {
        range.real = codes;
        const auto [lo, hi] = std::minmax_element(range.real->begin(), range.real->end());
        range.lowest = static_cast<int>(std::lround(*lo));
        range.highest = static_cast<int>(std::lround(*hi));
    }
    const ReplicateBands base = replicate_bands(r.base, log, c, max_m, edges, range, options.seed);
    const ReplicateBands after = replicate_bands(r.final_model, log, c, max_m, edges, range, options.seed);
    const ReplicateBands* added = r.accepted.empty() ? nullptr : &after;
    std::vector<double> tau(real.size());
    for (std::size_t j = 0; j < tau.size(); ++j)
        tau[j] = r.base.smoothing.sample_period_s * std::ldexp(1.0, static_cast<int>(j));
    const std::string channel = kChannelNames[c];
    const PhysicalUnit unit = display_unit(r.base, static_cast<Channel>(c));
    const auto band_in_unit = [&](const Band& b) { return scaled(b, unit.per_count); };
    const Band base_adev = band_in_unit(base.adev), base_mean = band_in_unit(base.mean);
    const Band after_adev = band_in_unit(after.adev), after_mean = band_in_unit(after.mean);
    md << plot_bands(
        "Residual ADEV, " + channel, "tau [s]", std::string("ADEV of the eq. 1 residual [") + unit.name + "]", true,
        tau, scaled(real, unit.per_count), base_adev, added ? &after_adev : nullptr, dir, plot_name("adev", channel));
    md << plot_bands("Residual mean over time, " + channel, "t [s]",
                     std::string("mean of the eq. 1 residual per bin [") + unit.name + "]", false, bin_t,
                     scaled(binned_mean(residual, edges), unit.per_count), base_mean, added ? &after_mean : nullptr,
                     dir, plot_name("mean", channel));
    if (range.real) {
        std::vector<double> code(static_cast<std::size_t>(range.highest - range.lowest + 1));
        for (std::size_t j = 0; j < code.size(); ++j) code[j] = range.lowest + static_cast<double>(j);
        md << plot_bands("Raw codes, " + channel, "code", "share of rows on the code", false, code,
                         code_shares(*range.real, range.lowest, range.highest), base.codes,
                         added ? &added->codes : nullptr, dir, plot_name("codes", channel));
    }
}

}  // namespace

void write_residual_plots(std::ostream& md, const GapResult& r, const LogData& log, const std::string& dir,
                          const GapOptions& options) {
    md << "\n## The residual against the simulator's replicates\n\nThe eq. 1 residual of the real log (black) against "
          "the min-max band of "
       << kBandReplicates
       << " replicates of the base simulator (red) and of the simulator with "
          "the added effects (blue), each replicate refitted as the log is: its Allan deviation by octave, and its "
          "mean "
          "over time (where a mean shape or a step shows); for a raw-mode log also the share of rows on each raw code "
          "(where a code of the wrong width shows).\n\n";
    std::string scales;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!r.channels[c]) continue;
        const PhysicalUnit unit = display_unit(r.base, static_cast<Channel>(c));
        scales += std::string(scales.empty() ? "" : ", ") + significant_plain(unit.per_count, 3) + " " + unit.name +
                  " on " + kChannelNames[c];
    }
    if (!scales.empty()) md << "The plots are in physical units; one count is " << scales << ".\n\n";
    const bool plots = gnuplot_available();
    if (!plots) md << "(gnuplot not found: plots skipped)\n";
    const std::vector<std::size_t> edges = time_bins(log.size());
    std::vector<double> bin_t(edges.size() - 1);
    for (std::size_t b = 0; b + 1 < edges.size(); ++b) bin_t[b] = 0.5 * (log.t_s[edges[b]] + log.t_s[edges[b + 1] - 1]);
    for (std::size_t c = 0; c < kChannelCount && plots; ++c)
        if (r.channels[c]) plot_channel(md, r, log, c, dir, options, edges, bin_t);
}

std::vector<std::string> residual_plot_files(const std::string& dir) {
    std::vector<std::string> out;
    for (const char* channel : kChannelNames)
        for (const char* kind : kPlotKinds) {
            const auto files = plot_files(dir, plot_name(kind, channel), kPlotFormats);
            out.insert(out.end(), files.begin(), files.end());
        }
    return out;
}

}  // namespace driftlab::host::view
