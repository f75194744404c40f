#pragma once
// core/number_format: the ways ncsim writes numbers in its outputs (locale-independent).
// num(): the shortest text that reads back to the same double, for machine-readable outputs
// (CSV, --json, --blocks, the totals): exact values, byte-identical reruns. human(): 6
// significant digits for people (3000.0000000000027 -> 3000, 0.14200000000000002 -> 0.142).
// seconds(): a time of the run in a message, to the microsecond (cycles are whole us).

#include <array>
#include <charconv>
#include <cmath>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::core {

/// Shortest round-trip text of `v` (std::to_chars).
inline std::string num(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

/// A number in --json: num(), or `null` where `v` is not finite: JSON has no NaN or infinity
/// (issue 34 item 11: a NaN that got through was written as `-nan`, invalid JSON).
inline std::string json_num(double v) {
  return std::isfinite(v) ? num(v) : std::string("null");
}

/// Text of `v` for people: 6 significant digits.
inline std::string human(double v) {
  std::array<char, 32> buf{};
  const auto r =
      std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 6);
  return std::string(buf.data(), r.ptr);
}

/// Text of a run's time `t` [s] in a message: to the microsecond (the cycle is a whole number of
/// us, `--cycle-us`): 10.338000000000001 -> 10.338 (core::micro_text).
inline std::string seconds(double t) {
  return micro_text(t);
}

}  // namespace ncsim::core
