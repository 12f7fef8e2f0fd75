// Lone values; see lone_values.hpp.
#include "host/stats/lone_values.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "host/stats/median.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::stats {

namespace {
// Rows named in a warning; the count says how many more there are.
constexpr std::size_t kNamedRows = 5;
// 1 / Phi^-1(3/4): a zero-mean normal variable's standard deviation over its median absolute value.
constexpr double kMadToSigma = 1.482602218505602;

// `value` (in (a, b)) rounded to the fewest significant digits, from `least` on, that keep it strictly between a and
// b: a time that names its row, a window's end to type.
std::string shortest_between(double a, double b, double value, int least) {
    for (int digits = least; digits < 17; ++digits) {
        const std::string text = significant_plain(value, digits);
        const double v = std::stod(text);
        if (v > a && v < b) return text;
    }
    return format_double(value);
}

std::string midway(double a, double b) { return shortest_between(a, b, a / 2.0 + b / 2.0, 1); }
}  // namespace

LoneValues lone_values(const std::vector<double>& x, double code) {
    LoneValues out;
    if (x.size() < 3) return out;
    // Halved differences cannot overflow, whatever finite values x holds; the tests below compare them only with
    // each other. Computed where used, not held: ten million rows are 80 MB a vector.
    const std::size_t differences = x.size() - 1;
    const auto half = [&](std::size_t i) { return x[i + 1] / 2.0 - x[i] / 2.0; };
    const auto magnitude = [&](std::size_t i) { return std::fabs(half(i)); };
    std::vector<double> magnitudes(differences);
    for (std::size_t i = 0; i < differences; ++i) magnitudes[i] = magnitude(i);
    const double mad_scale = kMadToSigma * median(std::move(magnitudes));
    // A series that mostly repeats one code: its step is the scale, the smallest nonzero difference other than the
    // two beside the row judged, so among the three smallest. Where the row's own were taken, a series constant but
    // for one corrupt row had measured the row by itself and never found it. A known code bounds the step: two corrupt
    // rows on a stuck channel had measured each other, and a lone flip of one code had had no step to be measured by.
    std::vector<std::size_t> smallest;  // indices of the smallest nonzero magnitudes, in increasing order
    if (mad_scale == 0.0) {
        for (std::size_t i = 0; i < differences; ++i) {
            if (magnitude(i) == 0.0) continue;
            const auto at = std::find_if(smallest.begin(), smallest.end(),
                                         [&](std::size_t j) { return magnitude(i) < magnitude(j); });
            smallest.insert(at, i);
            if (smallest.size() > 3) smallest.pop_back();
        }
        if (smallest.empty()) return out;  // a constant series
    }
    const double half_code = code / 2.0;  // the differences are halved
    const auto scale_beside = [&](std::size_t k) {
        if (mad_scale > 0.0) return mad_scale;
        for (std::size_t i : smallest)
            if (i != k - 1 && i != k) return half_code > 0.0 ? std::min(magnitude(i), half_code) : magnitude(i);
        return half_code;
    };
    double largest = magnitude(0);
    for (std::size_t i = 1; i < differences; ++i) largest = std::max(largest, magnitude(i));
    double total = 0.0, lone = 0.0;
    for (std::size_t i = 0; i < differences; ++i) total += (magnitude(i) / largest) * (magnitude(i) / largest);
    for (std::size_t k = 1; k + 1 < x.size(); ++k) {
        const double before = magnitude(k - 1), after = magnitude(k);
        const double smaller = std::min(before, after);
        if (smaller > kLoneFactor * scale_beside(k) && std::fabs(half(k - 1) + half(k)) < smaller / 2.0) {
            out.indices.push_back(k);
            lone += (before / largest) * (before / largest) + (after / largest) * (after / largest);
        }
    }
    out.variance_share = total > 0.0 ? lone / total : 0.0;
    return out;
}

std::optional<std::string> lone_values_warning(const std::vector<double>& t_s, const std::vector<double>& x,
                                               double code) {
    return lone_values_warning(t_s, x, lone_values(x, code));
}

std::optional<std::string> lone_values_warning(const std::vector<double>& t_s, const std::vector<double>& x,
                                               const LoneValues& found) {
    if (found.indices.empty() || found.variance_share < kLoneShare) return std::nullopt;
    const std::size_t n = found.indices.size();
    std::string text = std::to_string(n) + (n == 1 ? " lone value (" : " lone values (");
    for (std::size_t i = 0; i < std::min(n, kNamedRows); ++i) {
        const std::size_t k = found.indices[i];
        // Seven significant digits where they tell the row from its neighbours; a time since the epoch (1.7e9 s) takes
        // more, so that it still names one row.
        const std::string t =
            shortest_between(t_s[k - 1] / 2.0 + t_s[k] / 2.0, t_s[k] / 2.0 + t_s[k + 1] / 2.0, t_s[k], 7);
        text += (i ? ", t = " : "t = ") + t + " s: " + significant(x[k], 6);
    }
    if (n > kNamedRows) text += " and " + std::to_string(n - kNamedRows) + " more";
    const bool one = n == 1;
    text += ") " + std::string(one ? "carries " : "carry ") + significant(100.0 * found.variance_share, 3) +
            " % of the sample-to-sample variance: " + (one ? "it lies" : "each lies") + " over " +
            significant(kLoneFactor, 3) +
            " robust standard deviations from both neighbours, which agree with each other: a corrupt row, or an "
            "impulse from the sensor (`driftlab gap` tests its effect `spikes`). " +
            (one ? "It inflates" : "They inflate") +
            " the noise level, the short-tau Allan deviation and the fit's rms: if corrupt, correct " +
            (one ? "that row, or leave it out with" : "those rows, or leave them out with");
    for (std::size_t i = 0; i < std::min(n, kNamedRows); ++i) {
        const std::size_t k = found.indices[i];
        text += " --exclude " + midway(t_s[k - 1], t_s[k]) + ":" + midway(t_s[k], t_s[k + 1]);
    }
    if (n > kNamedRows) text += " and so on";
    return text;
}

}  // namespace driftlab::host::stats
