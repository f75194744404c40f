// cli/number_format: num() is the text of every number in the CSV, --json and --blocks; it must
// read back (strtod) to the very double that produced it, and be the shortest such text.

#include "cli/number_format.hpp"

#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using ncsim::cli::num;

// Significant digits of a decimal text ("-1.25e-07" -> 3, "1200" -> 2, "0.0005" -> 1).
int significant_digits(const std::string& s) {
  std::string digits;
  for (const char c : s) {
    if (c == 'e' || c == 'E') break;
    if (c >= '0' && c <= '9') digits += c;
  }
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  const auto last = digits.find_last_not_of('0');
  return static_cast<int>(last - first + 1);
}

// The scientific text of `v` with the fewest significant digits that reads back to `v`.
std::string shortest_scientific(double v) {
  std::array<char, 64> buf{};
  for (int p = 0; p < 17; ++p) {
    std::snprintf(buf.data(), buf.size(), "%.*e", p, v);
    if (std::strtod(buf.data(), nullptr) == v) break;
  }
  return buf.data();
}

// num(v) reads back to v bit for bit and is the shortest such text (std::to_chars): no longer
// than the shortest scientific text, and, when scientific itself, with its fewest digits. (An
// integer-valued double may be written in full in fixed notation when that is not longer:
// 1311014653902757888 for 1.311014653902758e+18.)
void check_round_trip(double v) {
  const std::string text = num(v);
  CAPTURE(text);
  char* end = nullptr;
  const double back = std::strtod(text.c_str(), &end);
  CHECK(*end == '\0');
  CHECK(std::bit_cast<std::uint64_t>(back) == std::bit_cast<std::uint64_t>(v));
  const std::string sci = shortest_scientific(v);
  CAPTURE(sci);
  CHECK(text.size() <= sci.size());
  if (text.find('e') != std::string::npos)
    CHECK(significant_digits(text) == significant_digits(sci));
}

}  // namespace

TEST_CASE("num: edge values read back to the same double") {
  constexpr double kMin = std::numeric_limits<double>::min();
  constexpr double kDenorm = std::numeric_limits<double>::denorm_min();
  constexpr double kMax = std::numeric_limits<double>::max();
  for (const double v : {0.0,
                         -0.0,
                         1.0,
                         -1.0,
                         0.1,
                         0.2,
                         0.1 + 0.2,
                         1.0 / 3.0,
                         1e-300,
                         1e300,
                         -1e300,
                         kMin,
                         -kMin,
                         kDenorm,
                         -kDenorm,
                         kDenorm * 3.0,
                         kMin / 2.0,
                         kMax,
                         -kMax,
                         std::nextafter(1.0, 2.0),
                         std::nextafter(1.0, 0.0),
                         9007199254740993.0,
                         4503599627370496.5,
                         5e-324,
                         2.2250738585072011e-308,
                         0.0005,
                         7.035,
                         10338 * 0.001})
    check_round_trip(v);
  CHECK(num(-0.0) == "-0");
  CHECK(num(0.1 + 0.2) == "0.30000000000000004");
  CHECK(num(1000.0) == "1000");
  CHECK(num(0.0005) == "5e-04");  // shorter than 0.0005
  CHECK(num(0.001) == "0.001");   // as long as 1e-03: fixed
}

TEST_CASE("num: seeded random doubles of every kind read back bit for bit, shortest") {
  std::mt19937_64 rng(20261125);
  std::uniform_int_distribution<std::uint64_t> bits;
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<std::int64_t> integer(-(std::int64_t{1} << 53),
                                                      std::int64_t{1} << 53);
  std::uniform_int_distribution<std::uint64_t> mantissa(1, (std::uint64_t{1} << 52) - 1);
  int subnormals = 0;
  int negatives = 0;
  for (int k = 0; k < 20000; ++k) {
    // Any bit pattern (every exponent and sign; NaN and inf skipped: the CSV has none).
    const double any = std::bit_cast<double>(bits(rng));
    if (std::isfinite(any)) check_round_trip(any);
    // Log-uniform magnitude 1e-300 .. 1e300, either sign.
    const double wide = (unit(rng) < 0 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    check_round_trip(wide);
    negatives += wide < 0 ? 1 : 0;
    // Integers up to 2^53, printed without an exponent or a fraction where exact.
    check_round_trip(static_cast<double>(integer(rng)));
    // Subnormals: exponent field 0, random mantissa and sign.
    const double sub =
        std::bit_cast<double>(mantissa(rng) | (k % 2 == 0 ? 0 : std::uint64_t{1} << 63));
    subnormals += std::fpclassify(sub) == FP_SUBNORMAL ? 1 : 0;
    check_round_trip(sub);
    // Values of the size the CSV carries: positions in mm, times in s.
    check_round_trip(unit(rng) * 4000.0);
    check_round_trip(static_cast<double>(k) * 0.001);
  }
  CHECK(subnormals == 20000);
  CHECK(negatives > 9000);
}

TEST_CASE("json_num: a number that is not finite is null, never nan or inf") {
  // issue 34 item 11: `time --json` wrote -nan
  CHECK(ncsim::cli::json_num(std::nan("")) == "null");
  CHECK(ncsim::cli::json_num(-std::nan("")) == "null");
  CHECK(ncsim::cli::json_num(HUGE_VAL) == "null");
  CHECK(ncsim::cli::json_num(-HUGE_VAL) == "null");
  CHECK(ncsim::cli::json_num(0.1) == "0.1");
  CHECK(ncsim::cli::json_num(-2.5e-300) == ncsim::cli::num(-2.5e-300));
}
