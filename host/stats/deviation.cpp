// Allan-family deviations: names, properties and normalisation of the raw term sums (docs/allan.md §1).
#include "host/stats/deviation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/stats/allan.hpp"
#include "host/stats/hadamard.hpp"
#include "host/util/parallel_for.hpp"

namespace driftlab::host::stats {

Deviation parse_deviation(std::string_view name) {
    for (Deviation d : {Deviation::adev, Deviation::oadev, Deviation::mdev, Deviation::hdev, Deviation::ohdev}) {
        if (name == deviation_name(d)) return d;
    }
    throw std::invalid_argument("unknown deviation '" + std::string(name) +
                                "' (expected adev, oadev, mdev, hdev, ohdev)");
}

std::string_view deviation_name(Deviation dev) {
    switch (dev) {
    case Deviation::adev: return "adev";
    case Deviation::oadev: return "oadev";
    case Deviation::mdev: return "mdev";
    case Deviation::hdev: return "hdev";
    case Deviation::ohdev: return "ohdev";
    }
    return "?";
}

int difference_order(Deviation dev) { return (dev == Deviation::hdev || dev == Deviation::ohdev) ? 3 : 2; }

bool is_overlapping(Deviation dev) { return dev != Deviation::adev && dev != Deviation::hdev; }

int stable32_factor_divisor(Deviation dev) { return is_overlapping(dev) ? 4 : 5; }

namespace {

// Terms a gap-free record of `samples` phase samples would give; the difference to the actual count is what
// the gaps cost.
std::int64_t terms_without_gaps(Deviation type, std::int64_t samples, std::int64_t m) {
    std::int64_t n = 0;
    switch (type) {
    case Deviation::adev: n = (samples - 1) / m - 1; break;
    case Deviation::oadev: n = samples - 2 * m; break;
    case Deviation::mdev: n = samples - 3 * m + 1; break;
    case Deviation::hdev: n = (samples - 1) / m - 2; break;
    case Deviation::ohdev: n = samples - 3 * m; break;
    }
    return std::max<std::int64_t>(n, 0);
}

TermSum terms(const PhaseRecord& record, Deviation type, std::int64_t m) {
    switch (type) {
    case Deviation::adev:
    case Deviation::oadev: return allan_terms(record, m, is_overlapping(type));
    case Deviation::mdev: return modified_allan_terms(record, m);
    case Deviation::hdev:
    case Deviation::ohdev: return hadamard_terms(record, m, is_overlapping(type));
    }
    return {};
}

}  // namespace

DeviationCurve compute_deviation(const PhaseRecord& record, Deviation type, std::span<const std::int64_t> ms,
                                 int threads) {
    DeviationCurve curve;
    curve.type = type;
    const long double tau0 = record.tau0_s();
    // Each factor is a pass over the whole record (80 MB for ten million samples): one factor to a thread.
    std::vector<TermSum> sums(ms.size());
    parallel_for(ms.size(), threads, [&](std::size_t i) { sums[i] = terms(record, type, ms[i]); });
    for (std::size_t i = 0; i < ms.size(); ++i) {
        const std::int64_t m = ms[i];
        const TermSum& t = sums[i];
        // Denominator of the variance per term, SP 1065: 2 m^2 tau0^2 (Allan), 2 m^4 tau0^2 (modified: the
        // inner sum holds m second differences), 6 m^2 tau0^2 (Hadamard).
        long double scale = 0.0L;
        const long double mm = static_cast<long double>(m);
        switch (type) {
        case Deviation::adev:
        case Deviation::oadev: scale = 2.0L * mm * mm * tau0 * tau0; break;
        case Deviation::mdev: scale = 2.0L * mm * mm * mm * mm * tau0 * tau0; break;
        case Deviation::hdev:
        case Deviation::ohdev: scale = 6.0L * mm * mm * tau0 * tau0; break;
        }
        if (t.n < 1) continue;
        curve.m.push_back(m);
        curve.tau_s.push_back(static_cast<double>(mm * tau0));
        curve.dev.push_back(static_cast<double>(
            std::ldexp(std::sqrt(t.sum_sq / (scale * static_cast<long double>(t.n))), record.scale_exponent())));
        curve.n.push_back(t.n);
        curve.n_skipped.push_back(
            std::max<std::int64_t>(terms_without_gaps(type, static_cast<std::int64_t>(record.size()), m) - t.n, 0));
    }
    return curve;
}

}  // namespace driftlab::host::stats
