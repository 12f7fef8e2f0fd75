// Nelder-Mead through NLopt; see nelder_mead.hpp.
#include "host/stats/nelder_mead.hpp"

#include <nlopt.h>

#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace driftlab::host::stats {

namespace {

struct Search {
    const std::function<double(const std::vector<double>&)>* f;
    nlopt_opt opt;
    std::vector<double> x;
    int evaluations = 0;
    std::exception_ptr failure;
};

double objective(unsigned n, const double* x, double* /*gradient: derivative-free*/, void* data) {
    auto& s = *static_cast<Search*>(data);
    ++s.evaluations;
    s.x.assign(x, x + n);
    try {
        const double v = (*s.f)(s.x);
        return std::isfinite(v) ? v
                                : std::numeric_limits<double>::infinity();  // -inf too: NLopt would keep it as the best
    } catch (...) {
        // An exception must not cross NLopt's C frames: keep it, stop, and rethrow once NLopt has returned.
        s.failure = std::current_exception();
        nlopt_force_stop(s.opt);
        return std::numeric_limits<double>::infinity();
    }
}

}  // namespace

NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f,
                             const std::vector<double>& start, const std::vector<double>& step, int max_evaluations) {
    const auto n = static_cast<unsigned>(start.size());
    const std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(nlopt_create(NLOPT_LN_NELDERMEAD, n),
                                                                     nlopt_destroy);
    if (!opt || step.size() != start.size()) throw std::invalid_argument("nelder_mead: one step per coordinate");
    Search search{&f, opt.get(), {}, 0, nullptr};
    nlopt_set_min_objective(opt.get(), objective, &search);
    nlopt_set_maxeval(opt.get(), max_evaluations);
    nlopt_set_initial_step(opt.get(), step.data());
    NelderMeadResult result{start, std::numeric_limits<double>::infinity(), 0};
    const nlopt_result status = nlopt_optimize(opt.get(), result.x.data(), &result.value);
    if (search.failure) std::rethrow_exception(search.failure);
    if (status == NLOPT_INVALID_ARGS || status == NLOPT_OUT_OF_MEMORY)
        throw std::runtime_error("nelder_mead: NLopt refused the search (" +
                                 std::string(nlopt_result_to_string(status)) + ")");
    result.evaluations = search.evaluations;
    return result;
}

}  // namespace driftlab::host::stats
