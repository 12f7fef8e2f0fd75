// Nelder-Mead; see nelder_mead.hpp.
#include "host/gap/nelder_mead.hpp"

#include <algorithm>
#include <numeric>

namespace driftlab::host::gap {

NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& start,
                             const std::vector<double>& step, int max_evaluations) {
    const std::size_t n = start.size();
    std::vector<std::vector<double>> simplex(n + 1, start);
    std::vector<double> values(n + 1);
    int evaluations = 0;
    auto eval = [&](const std::vector<double>& x) {
        ++evaluations;
        return f(x);
    };
    for (std::size_t i = 0; i < n; ++i) simplex[i + 1][i] += step[i];
    for (std::size_t i = 0; i <= n; ++i) values[i] = eval(simplex[i]);
    std::vector<std::size_t> order(n + 1);
    while (evaluations < max_evaluations) {
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
        const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
        std::vector<double> centroid(n, 0.0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k <= n; ++k)
                if (k != worst) centroid[i] += simplex[k][i] / static_cast<double>(n);
        auto along = [&](double t) {
            std::vector<double> x(n);
            for (std::size_t i = 0; i < n; ++i) x[i] = centroid[i] + t * (simplex[worst][i] - centroid[i]);
            return x;
        };
        const auto xr = along(-1.0);
        const double fr = eval(xr);
        if (fr < values[best]) {
            const auto xe = along(-2.0);
            const double fe = eval(xe);
            if (fe < fr) simplex[worst] = xe, values[worst] = fe;
            else simplex[worst] = xr, values[worst] = fr;
        } else if (fr < values[second]) {
            simplex[worst] = xr, values[worst] = fr;
        } else {
            const bool outside = fr < values[worst];
            const auto xc = along(outside ? -0.5 : 0.5);
            const double fc = eval(xc);
            if (fc < (outside ? fr : values[worst])) {
                simplex[worst] = xc, values[worst] = fc;
            } else {
                for (std::size_t k = 0; k <= n; ++k) {
                    if (k == best) continue;
                    for (std::size_t i = 0; i < n; ++i) simplex[k][i] = simplex[best][i] + 0.5 * (simplex[k][i] - simplex[best][i]);
                    values[k] = eval(simplex[k]);
                }
            }
        }
    }
    const auto it = std::min_element(values.begin(), values.end());
    return {simplex[static_cast<std::size_t>(it - values.begin())], *it, evaluations};
}

}  // namespace driftlab::host::gap
