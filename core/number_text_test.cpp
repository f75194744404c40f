#include "core/number_text.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

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
