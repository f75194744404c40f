// cli/cycle_option: which --cycle-us texts are refused, and what the message says.

#include "cli/cycle_option.hpp"

#include <doctest/doctest.h>

#include <string>

using ncsim::cli::cycle_us_error;
using ncsim::cli::every_error;

TEST_CASE("--cycle-us: whole microseconds 1 .. 1000000 pass") {
  for (const char* ok : {"1", "250", "1000", "2000", "1000000", "0001"}) {
    CAPTURE(ok);
    CHECK(cycle_us_error(ok).empty());
  }
}

TEST_CASE("--cycle-us: 0 and negatives are below 1 us, beyond 1 s above it, each named") {
  CHECK(cycle_us_error("0") == "0 us is below the smallest cycle, 1 us");
  CHECK(cycle_us_error("-5") == "-5 us is below the smallest cycle, 1 us");
  CHECK(cycle_us_error("-0") == "-0 us is below the smallest cycle, 1 us");
  CHECK(cycle_us_error("1000001") == "1000001 us is above the largest cycle, 1000000 us (1 s)");
  CHECK(cycle_us_error("99999999999999999999999") ==
        "99999999999999999999999 us is above the largest cycle, 1000000 us (1 s)");
}

TEST_CASE("--cycle-us: anything but digits is not a whole number of microseconds") {
  for (const char* bad : {"abc", "1e12", "1.5", "+5", " 5", "5 ", "0x10", "1000us", "-"}) {
    CAPTURE(bad);
    CHECK(cycle_us_error(bad) == "'" + std::string(bad) +
                                     "' is not a whole number of microseconds in digits (1 to "
                                     "1000000 us; 1000 us = 1 ms)");
  }
  CHECK(cycle_us_error("").find("needs a value") == 0);
}

TEST_CASE("--every: whole numbers 1 .. 2^40 pass; 0, negatives and beyond are named") {
  for (const char* ok : {"1", "10", "7035", "1099511627776", "01"}) {
    CAPTURE(ok);
    CHECK(every_error(ok).empty());
  }
  CHECK(every_error("0") == "0 is below the smallest, 1 (a row every cycle)");
  CHECK(every_error("-3") == "-3 is below the smallest, 1 (a row every cycle)");
  CHECK(every_error("1099511627777") ==
        "1099511627777 is above the largest, 1099511627776 (2^40) cycles");
  CHECK(every_error("99999999999999999999999") ==
        "99999999999999999999999 is above the largest, 1099511627776 (2^40) cycles");
}

TEST_CASE("--every: anything but digits is not a whole number of cycles") {
  for (const char* bad : {"abc", "1.5", "1e3", "+5", " 5", "10x", "-"}) {
    CAPTURE(bad);
    CHECK(every_error(bad) == "'" + std::string(bad) +
                                  "' is not a whole number of cycles in digits (1 to "
                                  "1099511627776 cycles; 1 writes every cycle)");
  }
  CHECK(every_error("").find("needs a value") == 0);
}
