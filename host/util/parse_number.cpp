// Strict number parsing; see parse_number.hpp.
#include "host/util/parse_number.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace driftlab::host {

std::string_view trim_blanks(std::string_view field) {
    const auto is_blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!field.empty() && is_blank(field.front())) field.remove_prefix(1);
    while (!field.empty() && is_blank(field.back())) field.remove_suffix(1);
    return field;
}

ParsedNumber parse_finite_double(std::string_view field) {
    field = trim_blanks(field);
    if (field.empty()) return {0.0, NumberError::empty};
    // from_chars rejects a leading '+', which other tools write; accept it once.
    if (field.front() == '+' && field.size() > 1 && field[1] != '-') field.remove_prefix(1);
    double value = 0.0;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, value);
    if (ec == std::errc::result_out_of_range) return {0.0, NumberError::out_of_range};
    if (ec != std::errc() || ptr != end) return {0.0, NumberError::not_a_number};
    if (!std::isfinite(value)) return {value, NumberError::not_finite};
    return {value, NumberError::ok};
}

std::optional<std::uint64_t> parse_unsigned(std::string_view field) {
    field = trim_blanks(field);
    std::uint64_t value = 0;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, value);
    if (field.empty() || ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

const char* number_error_text(NumberError e) {
    switch (e) {
    case NumberError::ok: return "ok";
    case NumberError::empty: return "empty field";
    case NumberError::not_a_number: return "not a number";
    case NumberError::not_finite: return "not finite (NaN or infinity)";
    case NumberError::out_of_range: return "out of the range of a double";
    }
    return "invalid";
}

}  // namespace driftlab::host
