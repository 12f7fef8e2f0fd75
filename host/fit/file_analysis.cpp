// Per-file drift analysis; see file_analysis.hpp.
#include "host/fit/file_analysis.hpp"

#include "host/util/error.hpp"

namespace driftlab::host::fit {

std::size_t FileAnalysis::failures() const {
    std::size_t n = 0;
    for (const auto& s : series) n += !s.analysis;
    return n;
}

std::string FileAnalysis::failure_summary() const {
    std::string out;
    for (const auto& s : series) {
        if (s.analysis) continue;
        out += (out.empty() ? "" : "; ") + s.error;
    }
    return out;
}

FileAnalysis analyse_file(const FileAnalysisRequest& request) {
    FileAnalysis out;
    out.path = request.path;
    out.canonical_log = is_canonical_log(request.path);
    const std::vector<Series> all =
        load_series(request.path, request.names, request.time_column, request.sample_period_s);
    for (const Series& s : all) {
        SeriesOutcome o;
        o.name = s.name;
        try {
            o.analysis = analyse_drift(s, request.options);
        } catch (const DataError& e) {
            // The caller reports the file once; keep the series' own message.
            o.error = e.what();
            const std::string prefix = request.path + ": ";
            if (o.error.rfind(prefix, 0) == 0) o.error.erase(0, prefix.size());
        }
        out.series.push_back(std::move(o));
    }
    return out;
}

}  // namespace driftlab::host::fit
