// The gap battery; see statistics.hpp. Cell margins are the practical-relevance floors of docs/gap.md §Located.
#include "host/gap/statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "host/fit/lm_fit.hpp"
#include "host/gap/code_density.hpp"
#include "host/gap/event_statistics.hpp"
#include "host/stats/spectral.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kTimeWindows = 10;  // windowed mean and variance: 10 windows of L/10
// The interleaved design's fitting tenths: both parts hold early and late tenths and five of them each, and the
// pattern is not periodic. Alternate tenths (0, 2, 4, 6, 8) repeat every fifth of the log, so a fit on them cannot
// tell a period P from the alias 1/(1/P + 5/L) (mask sidelobe -3.9 dB); this pattern's largest sidelobe is -9.4 dB.
constexpr std::array<std::size_t, 5> kFittingTenths{0, 4, 5, 7, 9};
constexpr double kMeanMarginCounts = 0.1;   // windowed mean of the residual [counts]
constexpr double kLogRatioMargin = 0.0953;  // ln 1.1: ADEV, variance, frequency-count ratios beyond 10 %
constexpr double kPsdMargin = 0.2303;       // 1 dB in ln power
constexpr double kAcfMargin = 0.1;          // mean autocorrelation in a lag band
constexpr double kCorrMargin = 0.1;         // lag-0 correlation between channels
constexpr double kCoherenceMargin = 0.1;    // band coherence between channels
constexpr int kFracBins = 8;
constexpr double kTailMargin = 0.1906;   // ln 1.21: kurtosis beyond 21 %
constexpr double kJumpMargin = 0.2231;   // ln 1.25: the largest block step beyond 25 % of the usual
constexpr std::size_t kJumpBlocks = 16;  // blocks per part for the step statistic

class Builder {
public:
    Builder(std::vector<double>& values, std::vector<Cell>* layout) : values_(values), layout_(layout) {}
    /// `text`: Cell::text, where the cell's text differs from its key.
    void add(double value, const Cell& cell, std::string text = {}) {
        values_.push_back(value);
        if (!layout_) return;
        layout_->push_back(cell);
        layout_->back().text = std::move(text);
    }
    bool wants_layout() const { return layout_ != nullptr; }

private:
    std::vector<double>& values_;
    std::vector<Cell>* layout_;
};

std::string short_number(double v) { return significant(v, 3); }

std::string seconds_label(double s) { return short_number(s) + "s"; }

// A cell's seconds for people (Cell::text): a window's ends to the digits its length warrants, and at least to the
// second (t=1201s..1350s: a label, where t=1200s..1350s would name other samples); a lag or a tau, a whole multiple of
// the sample period, as it is.
std::string window_seconds_text(double s, double length_s) {
    return to_precision_of(s, std::min(length_s, 10.0)) + "s";
}
std::string multiple_seconds_text(double s) { return significant(s, 6) + "s"; }

double log_floor(double v) { return std::log(std::max(v, 1e-300)); }

// One part's rows as runs [first, last) in time order: found once per battery and copied run by run from each series
// cut into parts (a channel's residual, output and raw codes, both residuals of a channel pair); testing the mask row
// by row for each series had taken 3 % of `gap`'s time.
using Runs = std::vector<std::pair<std::size_t, std::size_t>>;

Runs runs_of(const std::vector<bool>& fitting, bool want_fitting) {
    Runs runs;
    for (std::size_t i = 0; i < fitting.size();) {
        if (fitting[i] != want_fitting) {
            ++i;
            continue;
        }
        const std::size_t first = i;
        while (i < fitting.size() && fitting[i] == want_fitting) ++i;
        runs.emplace_back(first, i);
    }
    return runs;
}

// The samples of `v` in one part, in time order (interleaved blocks are joined: the same joins happen in the real
// log and every replicate, so the comparison stays like with like).
std::vector<double> part_of(const std::vector<double>& v, const Runs& part) {
    std::size_t size = 0;
    for (const auto& [first, last] : part) size += last - first;
    std::vector<double> out;
    out.reserve(size);
    for (const auto& [first, last] : part)
        out.insert(out.end(), v.begin() + static_cast<std::ptrdiff_t>(first),
                   v.begin() + static_cast<std::ptrdiff_t>(last));
    return out;
}

// Dispersion of the fractional part of the smoothed output over kFracBins bins: the code/quantiser signature.
double frac_dispersion(const std::vector<double>& y) {
    std::array<double, kFracBins> n{};
    for (double v : y) {
        const double f = v - std::floor(v);
        n[std::min(kFracBins - 1, static_cast<int>(f * kFracBins))] += 1.0;
    }
    const double expected = static_cast<double>(y.size()) / kFracBins;
    double chi2 = 0.0;
    for (double c : n) chi2 += (c - expected) * (c - expected) / expected;
    return std::log1p(chi2);
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= static_cast<double>(a.size());
    mb /= static_cast<double>(b.size());
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace

const char* segment_name(Segment s) { return s == Segment::fit ? "fit" : "heldout"; }

std::optional<Holdout> holdout_from_name(const std::string& name) {
    if (name == "forecast") return Holdout::forecast;
    if (name == "interleaved") return Holdout::interleaved;
    return std::nullopt;
}

std::string holdout_description(Holdout holdout, double fit_fraction) {
    if (holdout == Holdout::forecast)
        return "candidates fitted on the first " + short_number(100.0 * fit_fraction) +
               " % of the log (by time), judged on the rest";
    std::string fit, held;
    for (std::size_t w = 0; w < static_cast<std::size_t>(kTimeWindows); ++w) {
        const bool in = std::find(kFittingTenths.begin(), kFittingTenths.end(), w) != kFittingTenths.end();
        std::string& list = in ? fit : held;
        list += (list.empty() ? "" : ", ") + std::to_string(w);
    }
    return "candidates fitted on tenths " + fit + " of the log, judged on tenths " + held;
}

std::vector<bool> fitting_mask(const std::vector<double>& t_s, const BatteryOptions& options) {
    const std::size_t n = t_s.size();
    std::vector<bool> mask(n);
    if (options.holdout == Holdout::interleaved) {
        for (std::size_t w : kFittingTenths)
            for (std::size_t i = n * w / kTimeWindows; i < n * (w + 1) / kTimeWindows; ++i) mask[i] = true;
    } else {
        const double t_split = t_s.front() + options.fit_fraction * (t_s.back() - t_s.front());
        for (std::size_t i = 0; i < n; ++i) mask[i] = t_s[i] <= t_split;
    }
    return mask;
}

// The label of octave band j of a spectrum sampled at tau0: "f=LO..HIHz".
std::string band_label(double tau0, std::size_t j) {
    const double f_hi = 0.5 / tau0 / std::ldexp(1.0, static_cast<int>(j));
    return "f=" + short_number(f_hi / 2) + ".." + short_number(f_hi) + "Hz";
}

// The residual `e`'s mean and variance over each tenth of the log.
void add_window_cells(Builder& out, const std::vector<double>& t_s, const std::vector<double>& e,
                      const std::vector<bool>& fitting, const std::string& name, int ci) {
    const std::size_t n = t_s.size();
    for (int w = 0; w < kTimeWindows; ++w) {
        const std::size_t a = n * static_cast<std::size_t>(w) / kTimeWindows;
        const std::size_t b = n * static_cast<std::size_t>(w + 1) / kTimeWindows;
        double mean = 0.0, var = 0.0;
        for (std::size_t i = a; i < b; ++i) mean += e[i];
        mean /= static_cast<double>(b - a);
        for (std::size_t i = a; i < b; ++i) var += (e[i] - mean) * (e[i] - mean);
        var /= static_cast<double>(std::max<std::size_t>(1, b - a - 1));
        const Segment seg = fitting[(a + b) / 2] ? Segment::fit : Segment::heldout;
        std::string label, text;
        if (out.wants_layout()) {
            label = "t=" + seconds_label(t_s[a]) + ".." + seconds_label(t_s[b - 1]);
            const double length = t_s[b - 1] - t_s[a];
            text = "t=" + window_seconds_text(t_s[a], length) + ".." + window_seconds_text(t_s[b - 1], length);
        }
        out.add(mean, {"mean", name, ci, label, seg, false, kMeanMarginCounts}, text);
        out.add(log_floor(var), {"var", name, ci, label, seg, true, 2.0 * kLogRatioMargin}, text);
    }
}

// One part's (fitting or held-out) cells of a channel: Allan deviation, band power and autocorrelation by octave,
// fraction-of-count occupancy (with `frac`), raw-code histogram (with `raw`), kurtosis and the largest block step.
// Returns the part's transform, which the coherences share.
// A channel's series the part cells are cut from: the eq. 1 residual, the output, and for the code histogram the
// codes and the level each row's code is compared with (the smoothed output, or for outputs that are themselves
// codes the neighbours' mean).
struct ChannelSeries {
    const std::vector<double>& e;
    const std::vector<double>& y;
    const std::vector<double>* codes = nullptr;
    const std::vector<double>* level = nullptr;
};

stats::BandSpectrum add_part_cells(Builder& out, const ChannelSeries& series, const Runs& rows, Segment seg,
                                   double tau0, const std::string& name, int ci, bool frac) {
    const std::vector<double> part = part_of(series.e, rows);
    const std::vector<double> part_y = part_of(series.y, rows);
    const std::size_t len = part.size();
    const auto adev = stats::octave_oadev(part, std::max<std::size_t>(1, len / 8));
    for (std::size_t j = 0; j < adev.size(); ++j) {
        const double tau = tau0 * std::ldexp(1.0, static_cast<int>(j));
        out.add(log_floor(adev[j]),
                {"adev", name, ci, out.wants_layout() ? "tau=" + seconds_label(tau) : "", seg, true, kLogRatioMargin},
                out.wants_layout() ? "tau=" + multiple_seconds_text(tau) : "");
    }
    stats::BandSpectrum spectrum = stats::band_spectrum(part);
    const auto psd = stats::octave_band_power(spectrum);
    for (std::size_t j = 0; j < psd.size(); ++j)
        out.add(log_floor(psd[j]),
                {"psd", name, ci, out.wants_layout() ? band_label(tau0, j) : "", seg, true, kPsdMargin});
    const auto acf = stats::octave_lag_acf(part, std::max<std::size_t>(1, len / 8));
    for (std::size_t j = 0; j < acf.size(); ++j) {
        std::string label, text;
        if (out.wants_layout()) {
            const double lo = std::ldexp(1.0, static_cast<int>(j));
            label = "lag=" + seconds_label(lo * tau0) + ".." + seconds_label((2 * lo - 1) * tau0);
            text = "lag=" + multiple_seconds_text(lo * tau0) +
                   (lo > 1 ? ".." + multiple_seconds_text((2 * lo - 1) * tau0) : "");
        }
        out.add(acf[j], {"acf", name, ci, label, seg, false, kAcfMargin}, text);
    }
    if (frac)
        out.add(frac_dispersion(part_y), {"frac", name, ci, "fraction-of-count occupancy", seg, true, kLogRatioMargin});
    if (series.codes)
        out.add(code_density_excess(part_of(*series.codes, rows), part_of(*series.level, rows)),
                {"codes", name, ci, "raw-code histogram", seg, true, kLogRatioMargin});
    out.add(log_kurtosis(part), {"tail", name, ci, "kurtosis", seg, true, kTailMargin});
    if (len >= kJumpBlocks)
        out.add(
            log_jump_ratio(part, kJumpBlocks),
            {"jump", name, ci, out.wants_layout() ? "largest of " + std::to_string(kJumpBlocks) + " block steps" : "",
             seg, true, kJumpMargin});
    return spectrum;
}

// The cells of each pair of analysed channels: correlation at lag 0 and coherence by octave band, per part.
void add_pair_cells(Builder& out, const BatteryOptions& options, const BatteryResult& result,
                    const std::array<Runs, 2>& parts,
                    const std::array<std::array<stats::BandSpectrum, 2>, kChannelCount>& spectra) {
    const double tau0 = options.sample_period_s;
    for (std::size_t a = 0; a < kChannelCount; ++a) {
        for (std::size_t b = a + 1; b < kChannelCount; ++b) {
            if (!options.channels[a] || !options.channels[b]) continue;
            const std::string pair = std::string(kChannelNames[a]) + "~" + kChannelNames[b];
            for (int s = 0; s < 2; ++s) {
                const Segment seg = s == 0 ? Segment::fit : Segment::heldout;
                const Runs& rows = parts[static_cast<std::size_t>(s)];
                const double r = correlation(part_of(result.residual[a], rows), part_of(result.residual[b], rows));
                out.add(r, {"corr", pair, -1, "lag 0", seg, false, kCorrMargin});
                // Shared content in one band (a common disturbance), or at a short lag, which lag 0 dilutes or misses.
                const auto coh = stats::octave_band_coherence(spectra[a][static_cast<std::size_t>(s)],
                                                              spectra[b][static_cast<std::size_t>(s)]);
                // atanh(sqrt(coherence)) is near Gaussian with a variance set by the band's bins alone (Enochson and
                // Goodman's transform): raw coherence in a band of few bins is skewed, and its z would inflate the
                // family-wise threshold of every cell.
                for (std::size_t j = 0; j < coh.size(); ++j)
                    out.add(
                        std::atanh(std::sqrt(std::min(coh[j], 0.999999))),
                        {"coh", pair, -1, out.wants_layout() ? band_label(tau0, j) : "", seg, false, kCoherenceMargin});
            }
        }
    }
}

BatteryResult compute_battery(const std::vector<double>& t_s,
                              const std::array<const std::vector<double>*, kChannelCount>& y,
                              const BatteryOptions& options, std::vector<Cell>* layout, const RawCodes& raw) {
    BatteryResult result;
    Builder out(result.values, layout);
    const std::vector<bool> fitting = fitting_mask(t_s, options);
    const std::array<Runs, 2> parts{runs_of(fitting, true), runs_of(fitting, false)};  // fitting, held-out
    // Each analysed channel's transform per part (fitting, held-out), shared by its band power and the coherences.
    std::array<std::array<stats::BandSpectrum, 2>, kChannelCount> spectra;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!options.channels[c]) continue;
        fit::FitOptions fo;
        fo.start = options.fit_start[c];
        const fit::FitResult f = fit::fit_drift(t_s, *y[c], fo);
        result.drift[c] = f.parameters;
        result.residual[c] = f.residual;
        const std::string name = kChannelNames[c];
        const int ci = static_cast<int>(c);
        if (options.raw_codes[c] && (!raw[c] || raw[c]->size() != t_s.size()))
            throw std::invalid_argument(std::string("compute_battery: no raw codes for ") + name);
        add_window_cells(out, t_s, result.residual[c], fitting, name, ci);
        std::vector<double> neighbours;
        ChannelSeries series{result.residual[c], *y[c]};
        if (options.output_codes[c]) {
            neighbours = neighbour_level(*y[c]);
            series.codes = y[c];
            series.level = &neighbours;
        } else if (options.raw_codes[c]) {
            series.codes = raw[c];
            series.level = y[c];
        }
        for (std::size_t s = 0; s < 2; ++s)
            spectra[c][s] = add_part_cells(out, series, parts[s], s == 0 ? Segment::fit : Segment::heldout,
                                           options.sample_period_s, name, ci, options.frac_cells);
    }
    add_pair_cells(out, options, result, parts, spectra);
    return result;
}

}  // namespace driftlab::host::gap
