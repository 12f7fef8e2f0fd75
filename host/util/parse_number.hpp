// Strict text-to-number conversion for the log and table readers: the whole field must be one finite number.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace driftlab::host {

/// Why a field is not a usable number.
enum class NumberError { ok, empty, not_a_number, not_finite, out_of_range };

/// Outcome of a strict parse: `error == ok` means `value` holds the number.
struct ParsedNumber {
    double value = 0.0;
    NumberError error = NumberError::ok;
};

/// Parses the whole of `field` (surrounding blanks allowed) as a finite double; "nan", "inf" and
/// trailing garbage are errors, not values.
ParsedNumber parse_finite_double(std::string_view field);

/// Parses the whole of `field` as a non-negative decimal integer.
std::optional<std::uint64_t> parse_unsigned(std::string_view field);

/// Words for an error, for messages ("not a number", "not finite").
const char* number_error_text(NumberError e);

/// `field` without leading and trailing spaces, tabs and carriage returns.
std::string_view trim_blanks(std::string_view field);

}  // namespace driftlab::host
