// Automatic start by variable projection; see start_values.hpp.
#include "host/fit/start_values.hpp"

#include <algorithm>
#include <cmath>

namespace driftlab::host::fit {
namespace {

constexpr std::size_t kMaxBlocks = 200;
constexpr std::size_t kGridPoints = 64;
constexpr double kUpperSpanFactor = 100.0;

struct Blocks {
    std::vector<double> t_s, y, weight;
};

/// Equal-count block means: the profile keeps its shape (T is much longer than a block by construction).
Blocks block_means(const std::vector<double>& t_s, const std::vector<double>& y) {
    const std::size_t n = t_s.size();
    const std::size_t blocks = std::min(n, kMaxBlocks);
    Blocks b;
    b.t_s.reserve(blocks);
    b.y.reserve(blocks);
    b.weight.reserve(blocks);
    for (std::size_t i = 0; i < blocks; ++i) {
        const std::size_t lo = i * n / blocks;
        const std::size_t hi = (i + 1) * n / blocks;
        double st = 0.0, sy = 0.0;
        for (std::size_t k = lo; k < hi; ++k) {
            st += t_s[k];
            sy += y[k];
        }
        const double w = static_cast<double>(hi - lo);
        b.t_s.push_back(st / w);
        b.y.push_back(sy / w);
        b.weight.push_back(w);
    }
    return b;
}

/// Best C1, C2 for a fixed T and the weighted RSS (the variable-projection profile).
struct Profile {
    double c1 = 0.0, c2 = 0.0, rss = 0.0;
};

Profile profile(const Blocks& b, double t_const_s) {
    // Weighted normal equations of y = C1 x + C2 with x = 1 - exp(-t/T), centred for accuracy.
    double sw = 0.0, sx = 0.0, sy = 0.0;
    const std::size_t n = b.t_s.size();
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = -std::expm1(-b.t_s[i] / t_const_s);
        sw += b.weight[i];
        sx += b.weight[i] * x[i];
        sy += b.weight[i] * b.y[i];
    }
    const double mx = sx / sw, my = sy / sw;
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sxx += b.weight[i] * (x[i] - mx) * (x[i] - mx);
        sxy += b.weight[i] * (x[i] - mx) * (b.y[i] - my);
    }
    Profile p;
    p.c1 = sxx > 0.0 ? sxy / sxx : 0.0;
    p.c2 = my - p.c1 * mx;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = b.y[i] - p.c1 * x[i] - p.c2;
        p.rss += b.weight[i] * r * r;
    }
    return p;
}

}  // namespace

DriftParameters amplitudes_at(const std::vector<double>& t_s, const std::vector<double>& y, double t_const_s) {
    const Profile p = profile(Blocks{t_s, y, std::vector<double>(t_s.size(), 1.0)}, t_const_s);
    return {p.c1, p.c2, t_const_s};
}

StartValues automatic_start(const std::vector<double>& t_s, const std::vector<double>& y) {
    const Blocks b = block_means(t_s, y);
    const double span_s = t_s.back() - t_s.front();
    const double block_s = span_s / static_cast<double>(b.t_s.size());
    const double lo = std::log(std::max(block_s / 4.0, 1e-9 * std::max(1.0, t_s.back())));
    const double hi = std::log(kUpperSpanFactor * std::max(span_s, t_s.back()));

    std::vector<double> log_t(kGridPoints), rss(kGridPoints);
    std::size_t best = 0;
    for (std::size_t i = 0; i < kGridPoints; ++i) {
        log_t[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(kGridPoints - 1);
        rss[i] = profile(b, std::exp(log_t[i])).rss;
        if (rss[i] < rss[best]) best = i;
    }
    // Golden-section search on log T between the neighbours of the best grid point.
    double a = log_t[best == 0 ? 0 : best - 1];
    double d = log_t[std::min(best + 1, kGridPoints - 1)];
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c1 = d - g * (d - a), c2 = a + g * (d - a);
    double f1 = profile(b, std::exp(c1)).rss, f2 = profile(b, std::exp(c2)).rss;
    for (int it = 0; it < 40 && d - a > 1e-6; ++it) {
        if (f1 < f2) {
            d = c2;
            c2 = c1;
            f2 = f1;
            c1 = d - g * (d - a);
            f1 = profile(b, std::exp(c1)).rss;
        } else {
            a = c1;
            c1 = c2;
            f1 = f2;
            c2 = a + g * (d - a);
            f2 = profile(b, std::exp(c2)).rss;
        }
    }
    const double t_best_s = std::exp(0.5 * (a + d));
    const Profile p = profile(b, t_best_s);
    StartValues out;
    out.parameters = {p.c1, p.c2, t_best_s};
    out.block_rss = p.rss;
    out.t_at_upper_end = best == kGridPoints - 1;
    out.t_at_lower_end = best == 0;
    return out;
}

}  // namespace driftlab::host::fit
