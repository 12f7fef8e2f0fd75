// A canonical log read for a diagnosis; see canonical_log.hpp.
#include "host/gap/canonical_log.hpp"

#include "host/util/error.hpp"

namespace driftlab::host::gap {

// A window of 1 assumed for a missing one would make every averaged log look broken: the metadata must say it.
LogData read_canonical_log(std::istream& in, const std::string& path, ReadOptions options, const sim::SimModel& unit,
                           bool with_truth) {
    options.assumed_adc_bits = unit.adc.bits;
    LogData log = parse_log(in, path, options);
    if (const auto bits = log.metadata.get_int("adc_bits"); bits && *bits != unit.adc.bits)
        throw DataError(path, log.metadata.line_of("adc_bits"),
                        "adc_bits is " + std::to_string(*bits) + ", but the simulator's converter has " +
                            std::to_string(unit.adc.bits) + " bits");
    std::string missing;
    for (const char* key : {"window", "fit_order", "conversions_per_output"})
        if (!log.metadata.has(key)) missing += std::string(missing.empty() ? "" : ", ") + "'" + key + "'";
    if (!missing.empty())
        throw DataError(
            path, 0,
            "the metadata lacks " + missing +
                ": gap repeats the firmware's smoothing in every replicate and "
                "needs all of 'window', 'fit_order' and 'conversions_per_output' (record, decode and hil write them)");
    // The replicates are a unit at rest: a log in motion would read as one huge gap, every cell located.
    if (const auto trajectory = log.metadata.get("trajectory"); trajectory && *trajectory != "rest" && !with_truth)
        throw DataError(path, log.metadata.line_of("trajectory"),
                        "recorded in motion (trajectory " + *trajectory +
                            "): gap compares the log with a unit at rest, and would read the motion as a gap; give "
                            "its ground truth with --truth (hil writes it beside the log as LOG.truth.csv)");
    return log;
}

}  // namespace driftlab::host::gap
