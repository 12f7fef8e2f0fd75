// Number-to-text: round trips, and a value written to the precision of its uncertainty.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "host/util/format_number.hpp"

namespace driftlab::host {
namespace {

TEST(FormatDouble, ParsesBackToTheSameDouble) {
    for (double v : {0.1, -505.0834, 1e-300, 3.0e205, 2.0 / 3.0, std::nextafter(1.0, 2.0), 123456789012345.6,
                     0.000123456789012345678, 5000000.0})
        EXPECT_EQ(std::stod(format_double(v)), v) << format_double(v);
}

// A tick count read "5e+06" beside 5025000 on the next row: integers and ordinary fractions are fixed-point.
TEST(FormatDouble, OrdinaryMagnitudesAreFixedPointAndOthersShortest) {
    EXPECT_EQ(format_double(5000000.0), "5000000");
    EXPECT_EQ(format_double(0.0001), "0.0001");
    EXPECT_EQ(format_double(-120000.5), "-120000.5");
    EXPECT_EQ(format_double(0.0), "0");
    EXPECT_EQ(format_double(1e-5), "1e-05");
    EXPECT_EQ(format_double(1e15), "1e+15");
}

// The last digit sits at the uncertainty's second significant digit, whatever the magnitude: a table in g shows
// its digits where fixed decimals had printed -0.000.
TEST(ToPrecisionOf, TheLastDigitIsTheUncertaintysSecond) {
    EXPECT_EQ(to_precision_of(-0.00021813, 0.0000482), "-0.000218");
    EXPECT_EQ(to_precision_of(0.0000482, 0.0000482), "0.000048");
    EXPECT_EQ(to_precision_of(505.083426, 0.0537), "505.083");
    EXPECT_EQ(to_precision_of(397.7146, 1.43), "397.7");
    EXPECT_EQ(to_precision_of(1052485.26, 23553.79), "1052000");  // a last digit left of the point rounds there
    EXPECT_EQ(to_precision_of(23553.79, 23553.79), "24000");
    EXPECT_EQ(to_precision_of(-30.0514, 0.099), "-30.051");  // 0.099: its second digit is at 1e-3
}

TEST(ToPrecisionOf, VeryLargeOrSmallMagnitudesAreScientificWithTheSameLastDigit) {
    EXPECT_EQ(to_precision_of(-3.0051385e201, 5.03e198), "-3.0051e+201");
    EXPECT_EQ(to_precision_of(5.03e198, 5.03e198), "5.0e+198");
    EXPECT_EQ(to_precision_of(-7.23e-180, 1.2e-182), "-7.230e-180");
    EXPECT_EQ(to_precision_of(0.0, 1.2e-182), "0.0e+00");
}

TEST(ToPrecisionOf, WithoutAFiniteUncertaintySixSignificantDigits) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(to_precision_of(-202.806076, inf), "-202.806");
    EXPECT_EQ(to_precision_of(4.5447311, 0.0), "4.54473");
    EXPECT_EQ(to_precision_of(4.5447311, std::nan("")), "4.54473");
    EXPECT_EQ(to_precision_of(inf, 1.0), "inf");
}

// The report's fit table: a value carries the digits its standard error justifies and no more, the error two.
TEST(ValueWithError, TheValueStopsAtTheErrorsSecondDigit) {
    EXPECT_EQ(value_with_error(12.3417, 0.0512, "+-"), "12.342 +- 0.051");
    EXPECT_EQ(value_with_error(-12.3417, 0.0512, "&plusmn;"), "-12.342 &plusmn; 0.051");  // the sign stays
    EXPECT_EQ(value_with_error(-0.00021813, 0.0000482, "+-"), "-0.000218 +- 0.000048");
    // An error larger than the value: the value keeps no digit below the error's second.
    EXPECT_EQ(value_with_error(0.3, 12.0, "+-"), "0 +- 12");
    EXPECT_EQ(value_with_error(3.0, 120.0, "+-"), "0 +- 120");
    EXPECT_EQ(value_with_error(-1264.7, 123.4, "+-"), "-1260 +- 120");
    EXPECT_EQ(value_with_error(-0.004, 0.35, "+-"), "0.00 +- 0.35");  // rounds to zero: no "-0.00"
}

TEST(ValueWithError, WithoutAUsableErrorTheValueHasSixDigits) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(value_with_error(4.5447311, 0.0, "+-"), "4.54473 +- 0");  // an exact value: said so, not hidden
    EXPECT_EQ(value_with_error(4.5447311, inf, "+-"), "4.54473");
    EXPECT_EQ(value_with_error(4.5447311, std::nan(""), "+-"), "4.54473");
    EXPECT_EQ(value_with_error(4.5447311, -0.1, "+-"), "4.54473");
}

// A small negative value rounded to zero had kept its sign: gap's candidate table read "shrink -0%" and "gain -0.0"
// where nothing changed. A negative value that does not round to zero keeps it.
TEST(FixedPoint, AValueThatRoundsToZeroHasNoSign) {
    EXPECT_EQ(fixed_point(-0.004, 0), "0");
    EXPECT_EQ(fixed_point(-0.04, 1), "0.0");
    EXPECT_EQ(fixed_point(-0.0, 2), "0.00");
    EXPECT_EQ(fixed_point(-0.06, 1), "-0.1");
    EXPECT_EQ(fixed_point(-12.34, 1), "-12.3");
    EXPECT_EQ(to_precision_of(-0.0003, 0.05), "0.000");
    EXPECT_EQ(to_precision_of(-0.0003, 0.005), "-0.0003");
}

// gap's parameters were printed with %.4g: a second time constant read "t2_s 1.191e+04" and a walk's size
// "9.776e-05". The same digits, at most, without the exponent; the digits %e rounds to, not every digit of %f.
TEST(SignificantPlain, AtMostTheDigitsAndNoExponentForOrdinaryMagnitudes) {
    EXPECT_EQ(significant_plain(11912.3, 4), "11910");
    EXPECT_EQ(significant_plain(145812.3, 4), "145800");
    EXPECT_EQ(significant_plain(9.776e-05, 4), "0.00009776");
    EXPECT_EQ(significant_plain(-0.34061, 4), "-0.3406");
    EXPECT_EQ(significant_plain(507.44, 4), "507.4");
    EXPECT_EQ(significant_plain(30.0, 4), "30");  // no trailing zeros, as %g
    EXPECT_EQ(significant_plain(0.0250, 3), "0.025");
    EXPECT_EQ(significant_plain(9.99996, 4), "10");  // rounding carries into a new leading digit
    EXPECT_EQ(significant_plain(-1.0e-5, 2), "-0.00001");
    EXPECT_EQ(significant_plain(-0.0, 4), "0");
}

TEST(SignificantPlain, BeyondToPrecisionOfsPlainRangeItIsPercentG) {
    EXPECT_EQ(significant_plain(3.1e205, 4), "3.1e+205");
    EXPECT_EQ(significant_plain(2.5e9, 3), "2.5e+09");
    EXPECT_EQ(significant_plain(1.234e-11, 4), "1.234e-11");  // its last digit at 1e-14
    EXPECT_EQ(significant_plain(1.2e-11, 2), "0.000000000012");
    EXPECT_EQ(significant_plain(std::nan(""), 4), "nan");
}

}  // namespace
}  // namespace driftlab::host
