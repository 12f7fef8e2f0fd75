// Plain recordings as logs; see plain_recording.hpp.
#include "host/gap/plain_recording.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "driftlab/proto/messages.hpp"
#include "host/fit/series.hpp"
#include "host/stats/median.hpp"
#include "host/stats/rate_unit.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::gap {

namespace {

constexpr double kMidScale = 512.0;
constexpr double kFullScale = 1023.0;

}  // namespace

ColumnMapping parse_column_mapping(const std::string& text) {
    const auto eq = text.find('=');
    auto colon = text.rfind(':');
    if (eq == std::string::npos || colon == std::string::npos || colon < eq)
        throw UsageError("--as: expected CHANNEL=COLUMN:LSB[:UNIT] (e.g. gyro=col1:0.00875), got '" + text + "'");
    ColumnMapping m;
    const std::string channel = text.substr(0, eq);
    const std::optional<Channel> named = channel_named(channel);
    if (!named) throw UsageError("--as: unknown channel '" + channel + "' (" + channel_name_list() + ")");
    m.channel = *named;
    // The last field is a unit when it does not start like a number (a column name may hold neither ':' nor one).
    const std::string last = text.substr(colon + 1);
    if (!last.empty() && std::isalpha(static_cast<unsigned char>(last.front()))) {
        const bool gyro = m.channel == Channel::gyro;
        const stats::RateQuantity quantity =
            gyro ? stats::RateQuantity::angular_rate : stats::RateQuantity::acceleration;
        const auto unit = stats::rate_unit(last);
        if (!unit || unit->quantity != quantity)
            throw UsageError("--as: unknown unit '" + last + "' for " + channel + " (" +
                             stats::rate_unit_names(quantity) + ") in '" + text + "'");
        // The simulator's unit of the channel: deg/s, g.
        m.to_model_unit = unit->si_per_unit / stats::rate_unit(gyro ? "deg/s" : "g")->si_per_unit;
        const auto previous = text.rfind(':', colon - 1);
        if (previous == std::string::npos || previous < eq)
            throw UsageError("--as: expected CHANNEL=COLUMN:LSB:UNIT, got '" + text + "'");
        colon = previous;
    }
    m.column = text.substr(eq + 1, colon - eq - 1);
    if (m.column.empty()) throw UsageError("--as: no column name in '" + text + "'");
    const std::string lsb = text.substr(colon + 1, text.find(':', colon + 1) - colon - 1);
    char* end = nullptr;
    m.lsb = std::strtod(lsb.c_str(), &end);
    if (lsb.empty() || *end != '\0' || !(m.lsb > 0.0) || !std::isfinite(m.lsb))
        throw UsageError("--as: the LSB must be a positive number, got '" + lsb + "' in '" + text + "'");
    return m;
}

LogData log_from_table(const NumericTable& table, const PlainRecording& how) {
    if (how.columns.empty()) throw UsageError("a plain recording needs at least one --as CHANNEL=COLUMN:LSB");
    if (!(how.sample_period_s > 0.0))
        throw UsageError("a plain recording needs its sample period (--tau0 SECONDS > 0)");
    if (how.block < 1 || how.block > proto::kConversionsPerOutputMax)
        throw UsageError("--block: 1 to " + std::to_string(proto::kConversionsPerOutputMax) +
                         " samples per output (the most conversions per output a log's smoothing can hold)");
    std::vector<std::string> names;
    std::vector<bool> mapped(kChannelCount, false);
    for (const auto& m : how.columns) {
        for (const auto& other : names)
            if (other == m.column) throw UsageError("--as: column '" + m.column + "' mapped twice");
        names.push_back(m.column);
        const std::size_t c = channel_index(m.channel);
        if (mapped[c]) throw UsageError(std::string("--as: channel ") + kChannelNames[c] + " mapped twice");
        mapped[c] = true;
    }
    std::vector<fit::Series> series;
    try {
        series = fit::series_from_table(table, names, "", how.sample_period_s);
    } catch (const UsageError& e) {
        // Every name came from --as (a column the table lacks, or its time column).
        throw UsageError(std::string("--as: ") + e.what());
    }
    const std::vector<double>& t = series.front().t_s;
    if (const auto disagreement = stats::tau0_disagreement(t, how.sample_period_s))
        throw UsageError(*disagreement + "; give the recording's sample period, or a table without a time column");
    if (t.front() < 0.0)
        throw DataError(table.source_name, table.line_of_row(0),
                        "the time column starts at " + format_double(t.front()) +
                            " s: eq. 1 counts time from power-on, so give times since power-on (or a table without a "
                            "time column)");
    const std::size_t outputs = table.rows() / how.block;
    if (outputs < 2)
        throw DataError(
            table.source_name, 0,
            std::to_string(table.rows()) + " rows make fewer than two blocks of " + std::to_string(how.block));
    LogData log;
    log.source_name = table.source_name;
    for (std::size_t b = 0; b < outputs; ++b) {
        log.t_s.push_back(t[(b + 1) * how.block - 1]);  // an output is sent after its last conversion
        log.seq.push_back(b);
    }
    for (std::size_t c = 0; c < kChannelCount; ++c) log.counts[c].assign(outputs, kMidScale);
    log.recorded.fill(false);
    for (const auto& m : how.columns) {
        const std::size_t c = channel_index(m.channel);
        log.recorded[c] = true;
        const fit::Series* s = nullptr;
        for (const auto& candidate : series)
            if (candidate.name == m.column) s = &candidate;
        // Integer codes, as the sensor produced them, offset so the column's median sits at mid-scale (a median:
        // one wild value must not move the others off the scale, so that the error names its own row).
        const double median_code = std::round(stats::median(s->values) / m.lsb);
        const double offset = kMidScale - median_code;
        log.metadata.set(std::string("mid_scale_value_") + kChannelNames[c], median_code * m.lsb);
        for (std::size_t b = 0; b < outputs; ++b) {
            double sum = 0.0;
            for (std::size_t i = b * how.block; i < (b + 1) * how.block; ++i) {
                const double code = std::round(s->values[i] / m.lsb) + offset;
                if (!(code >= 0.0 && code <= kFullScale))
                    throw DataError(
                        table.source_name, table.line_of_row(i),
                        "column '" + m.column + "' row " + std::to_string(i + 1) + " (" + format_double(s->values[i]) +
                            ") lies beyond the 10-bit range around the column's median (" + format_double(kMidScale) +
                            " codes of LSB " + format_double(m.lsb) + "): give a coarser LSB, or check that row");
                sum += code;
            }
            log.counts[c][b] = sum / static_cast<double>(how.block);
        }
    }
    // Another logger's table: its rows came in no frames, so there is no link to diagnose (GapResult::link).
    log.metadata.set("source", std::string(kPlainRecordingSource));
    log.metadata.set("sample_period_s", static_cast<double>(how.block) * how.sample_period_s);
    log.metadata.set("conversions_per_output", static_cast<std::int64_t>(how.block));
    log.metadata.set("window", static_cast<std::int64_t>(how.block));
    log.metadata.set("fit_order", static_cast<std::int64_t>(0));
    return log;
}

sim::SimModel unit_of_recording(sim::SimModel unit, const PlainRecording& how, const LogData& log) {
    unit.adc.bits = 10;  // the codes log_from_table() made
    for (const auto& m : how.columns) {
        const std::size_t c = channel_index(m.channel);
        const auto mid = log.metadata.get_double(std::string("mid_scale_value_") + kChannelNames[c]);
        if (!mid)
            throw std::invalid_argument(
                "unit_of_recording: the log was not made by log_from_table() with this mapping");
        sim::ChannelModel& ch = unit.channels[c];
        ch.front_end.span_unit = kMidScale * m.lsb * m.to_model_unit;  // counts_per_unit = levels / 2 / span = 1 / lsb
        ch.front_end.center_unit = *mid * m.to_model_unit;
        ch.input_unit = *mid * m.to_model_unit;
    }
    return unit;
}

}  // namespace driftlab::host::gap
