#include "core/number_text.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

using ncsim::core::micro_text;
using ncsim::core::number_text;

TEST_CASE("numbers print as a user writes them, without trailing zeros") {
  CHECK(number_text(10.0) == "10");
  CHECK(number_text(-300.0) == "-300");
  CHECK(number_text(0.1) == "0.1");
  CHECK(number_text(-0.0) == "0");
  CHECK(number_text(65.0000001) == "65.0000001");
  CHECK(number_text(40000000.0) == "40000000");  // a 0.1 um list value, not "4e+07"
  CHECK(number_text(0.00002) == "0.00002");
}

TEST_CASE("very small and very large numbers keep an exponent") {
  CHECK(number_text(1e-7) == "1e-07");
  CHECK(number_text(2.5e20) == "2.5e+20");
}

TEST_CASE("the text reads back to the same number") {
  for (const double v : {1.0 / 3.0, 2.0 / 7.0 * 1e-12, 123456.789e10, -4e-300}) {
    CHECK(std::stod(number_text(v)) == v);
  }
}

TEST_CASE("non-finite values have names") {
  CHECK(number_text(std::numeric_limits<double>::quiet_NaN()) == "nan");
  CHECK(number_text(-std::numeric_limits<double>::infinity()) == "-inf");
}

TEST_CASE("micro_text: to the microsecond, no trailing zeros, never -0") {
  CHECK(micro_text(10338 * 0.001) == "10.338");
  CHECK(micro_text(2.0) == "2");
  CHECK(micro_text(1e-6) == "0.000001");
  CHECK(micro_text(-4e-7) == "0");
  CHECK(micro_text(-1.25) == "-1.25");
  CHECK(micro_text(1e300) == number_text(1e300));
}

TEST_CASE("human and significant_text are printf's %g, locale-independent") {
  using ncsim::core::human;
  using ncsim::core::significant_text;
  CHECK(human(3000.0000000000027) == "3000");
  CHECK(human(0.14200000000000002) == "0.142");
  CHECK(human(1e-5) == "1e-05");
  CHECK(significant_text(2.0 / 3.0, 7) == "0.6666667");
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-12, 12);
  for (int i = 0; i < 1000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    CHECK(human(v) == buf);
    std::snprintf(buf, sizeof buf, "%.7g", v);
    CHECK(significant_text(v, 7) == buf);
  }
}

TEST_CASE("signed_human is printf's %+g") {
  using ncsim::core::signed_human;
  CHECK(signed_human(1.0) == "+1");
  CHECK(signed_human(-1.0) == "-1");
  CHECK(signed_human(0.0) == "+0");
  CHECK(signed_human(-0.0) == "-0");
  CHECK(signed_human(2.5e-7) == "+2.5e-07");
  CHECK(signed_human(-1234567.0) == "-1.23457e+06");
}

TEST_CASE("json_num writes null where JSON has no number") {
  using ncsim::core::json_num;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(json_num(0.1) == "0.1");
  CHECK(json_num(nan) == "null");
  CHECK(json_num(-inf) == "null");
  CHECK(json_num(2.0 / 3.0, 7) == "0.6666667");
  CHECK(json_num(inf, 7) == "null");
}

TEST_CASE("fixed_text is exact in fixed notation; decimals_text rounds and has no -0") {
  using ncsim::core::decimals_text;
  using ncsim::core::fixed_text;
  CHECK(fixed_text(0.0001) == "0.0001");
  CHECK(fixed_text(2.5) == "2.5");
  CHECK(fixed_text(1e20) == "100000000000000000000");
  CHECK(decimals_text(1.23456, 4) == "1.2346");
  CHECK(decimals_text(-2.0, 4) == "-2.0000");
  CHECK(decimals_text(-0.0, 4) == "0.0000");
  CHECK(decimals_text(-0.00001, 4) == "0.0000");
  CHECK(decimals_text(-0.00005, 4) == "-0.0001");
  CHECK(decimals_text(std::numeric_limits<double>::max(), 4).size() == 309 + 5);
}
