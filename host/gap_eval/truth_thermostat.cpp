// Bang-bang thermostat with hysteresis: the room heats at one rate until +h, cools at another until -h; the unit
// sees it through a first-order thermal lag. Rates are drawn so that 3-8 cycles fit in the log. truth.hpp.
#include <algorithm>
#include <cmath>

#include "host/gap_eval/truth.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::host::gap {

std::vector<double> truth_thermostat(const std::vector<double>& t_s, double size_counts, std::uint64_t seed) {
    sim::Rng rng(seed, 0x72);
    const double span_s = t_s.back() - t_s.front();
    const double cycles = 3.0 + 5.0 * rng.uniform();
    const double period_s = span_s / cycles;
    const double heat_share = 0.35 + 0.3 * rng.uniform();  // fraction of the period spent heating
    const double h = 1.0;                                  // hysteresis half-width [K]
    const double heat_rate = 2.0 * h / (heat_share * period_s), cool_rate = 2.0 * h / ((1.0 - heat_share) * period_s);
    const double lag_s = period_s * (0.05 + 0.15 * rng.uniform());
    double room = -h + 2.0 * h * rng.uniform();
    bool heating = rng.uniform() < 0.5;
    double lagged = room;
    // Fine internal step so switching instants are resolved.
    const double dt_fine = std::min(period_s / 400.0, (t_s.size() > 1 ? t_s[1] - t_s[0] : 1.0));
    std::vector<double> raw(t_s.size());
    double t = 0.0;
    for (std::size_t k = 0; k < t_s.size(); ++k) {
        while (t < t_s[k]) {
            const double d = std::min(dt_fine, t_s[k] - t);
            room += (heating ? heat_rate : -cool_rate) * d;
            if (room >= h) heating = false;
            if (room <= -h) heating = true;
            lagged += (room - lagged) * (1.0 - std::exp(-d / lag_s));
            t += d;
        }
        raw[k] = lagged;
    }
    const auto [lo, hi] = std::minmax_element(raw.begin(), raw.end());
    const double half = std::max(1e-12, 0.5 * (*hi - *lo));
    const double mid = 0.5 * (*hi + *lo);
    std::vector<double> out(t_s.size());
    for (std::size_t k = 0; k < t_s.size(); ++k) out[k] = size_counts * (raw[k] - mid) / half;
    return out;
}

}  // namespace driftlab::host::gap
