// Number-to-text: the shortest text that parses to the same double, for files that are read back; and a value
// written to the precision of its uncertainty, for people.
#pragma once

#include <cstddef>
#include <string>

namespace driftlab::host {

/// Shortest decimal text that round-trips to exactly `value` (std::to_chars): fixed-point for magnitudes from 1e-4
/// to below 1e15 (5000000, 0.0001), else the shortest of either form (1e-05, 3e+205); "nan"/"inf" for non-finite.
std::string format_double(double value);

/// Appends format_double(value) to `out` without a temporary string.
void append_double(std::string& out, double value);

/// `value` with its last digit where `uncertainty`'s second significant digit is (so that to_precision_of(u, u) is
/// u to two digits): fixed-point for magnitudes below 1e9 down to a last digit of 1e-12, rounded to that digit left of
/// the point too, else scientific (-0.00021, 505.08, 1052000 of 1052485 ± 23554, 3.1e+205). Six significant digits
/// where the uncertainty is zero, infinite or NaN. A negative value that rounds to zero is written unsigned ("0.00",
/// not "-0.00"), here and in fixed_point().
std::string to_precision_of(double value, double uncertainty);

/// "value ± error" for people: the value to_precision_of() its error, the error to two significant digits
/// (12.3417 and 0.0512 -> "12.342 ± 0.051"), `plus_minus` between them ("+-" for a terminal, "&plusmn;" for HTML).
/// A zero error reads "± 0" after the value to six digits; a negative or non-finite one (no error known) leaves
/// the value alone, to six digits, for the caller to say why.
std::string value_with_error(double value, double error, const std::string& plus_minus);

/// `value` to `digits` significant digits (printf %g): a spacing or a p-value in a sentence, not a number to read back.
std::string significant(double value, int digits);

/// `value` to at most `digits` significant digits, trailing zeros dropped as %g drops them, but without %g's exponent
/// where to_precision_of() writes none: a value without an uncertainty to round to, for people (at 4 digits
/// 11912.3 -> 11910, 0.00017351 -> 0.0001735, 30.0 -> 30; 3.1e+205 as %g writes it).
std::string significant_plain(double value, int digits);

/// `value` with `decimals` digits after the point (printf %f), for tables and sentences.
std::string fixed_point(double value, int decimals);

/// "1 cell", "2 cells": a count and its noun, plural by "s".
std::string counted(std::size_t n, const std::string& noun);

}  // namespace driftlab::host
