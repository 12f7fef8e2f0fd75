// Replicates in parallel (parallel_for); see replicates.hpp.
#include "host/gap/replicates.hpp"

#include <algorithm>

#include "host/util/parallel_for.hpp"

namespace driftlab::host::gap {

std::uint64_t replicate_seed(std::uint64_t seed, int r) {
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(r) + 1;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

Eigen::MatrixXd simulate_replicates(const GapModel& model, const std::vector<double>& t_s,
                                    const std::array<bool, kChannelCount>& channels, int replicates, std::uint64_t seed,
                                    int threads, const ReplicateSummary& summary, const ReplicateExtra& extra,
                                    bool raw_codes) {
    std::vector<std::vector<double>> rows(static_cast<std::size_t>(replicates));
    const std::optional<sim::DriftAtConversions> drift = sim::drift_at_conversions(model, t_s, channels);
    parallel_for(rows.size(), threads, [&](std::size_t r) {
        sim::OutputRequest request;
        request.t_s = &t_s;
        request.channels = channels;
        if (drift) request.drift = &*drift;
        const std::uint64_t rs = replicate_seed(seed, static_cast<int>(r));
        if (extra) extra(rs, request);
        sim::Outputs raw;
        if (raw_codes) request.raw_codes = &raw;
        const sim::Outputs y = sim::simulate_outputs(model, request, rs);
        rows[r] = summary(y, raw);
    });
    Eigen::MatrixXd out(replicates, static_cast<Eigen::Index>(rows.front().size()));
    for (int r = 0; r < replicates; ++r)
        out.row(r) =
            Eigen::Map<const Eigen::RowVectorXd>(rows[static_cast<std::size_t>(r)].data(),
                                                 static_cast<Eigen::Index>(rows[static_cast<std::size_t>(r)].size()));
    return out;
}

fit::FitOptions start_at_model(const GapModel& model, Channel c) {
    const sim::DriftParams& d = model.base[channel_index(c)].drift;
    fit::FitOptions fo;
    fo.start = fit::DriftParameters{d.c1_counts, d.c2_counts, d.tau_s};
    return fo;
}

Eigen::MatrixXd run_replicates(const GapModel& model, const std::vector<double>& t_s, const BatteryOptions& options,
                               int replicates, std::uint64_t seed, int threads, const ReplicateExtra& extra) {
    BatteryOptions warm = options;
    for (std::size_t c = 0; c < kChannelCount; ++c)
        warm.fit_start[c] = start_at_model(model, static_cast<Channel>(c)).start;
    return simulate_replicates(
        model, t_s, options.channels, replicates, seed, threads,
        [&](const sim::Outputs& sim, const sim::Outputs& raw_codes) {
            std::array<const std::vector<double>*, kChannelCount> y{};
            RawCodes raw{};
            for (std::size_t c = 0; c < kChannelCount; ++c) {
                y[c] = &sim[c];
                if (options.raw_codes[c]) raw[c] = &raw_codes[c];
            }
            return compute_battery(t_s, y, warm, nullptr, raw).values;
        },
        extra, std::any_of(options.raw_codes.begin(), options.raw_codes.end(), [](bool b) { return b; }));
}

}  // namespace driftlab::host::gap
