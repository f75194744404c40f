#pragma once
// cli/number_format: the ways the ncsim command writes numbers (locale-independent).
// num(): the shortest text that reads back to the same double, for machine-readable outputs
// (CSV, --json, --blocks, the totals): exact values, byte-identical reruns. human(): 6
// significant digits for people (3000.0000000000027 -> 3000, 0.14200000000000002 -> 0.142).
// seconds(): a time of the run in a message, to the microsecond (cycles are whole us).

#include <array>
#include <charconv>
#include <string>
#include <system_error>

namespace ncsim::cli {

/// Shortest round-trip text of `v` (std::to_chars).
inline std::string num(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

/// Text of `v` for people: 6 significant digits.
inline std::string human(double v) {
  std::array<char, 32> buf{};
  const auto r =
      std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 6);
  return std::string(buf.data(), r.ptr);
}

/// Text of a run's time `t` [s] in a message: fixed to the microsecond (the cycle is a whole
/// number of us, `--cycle-us`), trailing zeros dropped: 10.338000000000001 -> 10.338, 2 -> 2.
inline std::string seconds(double t) {
  std::array<char, 48> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), t, std::chars_format::fixed, 6);
  if (r.ec != std::errc{}) return num(t);  // beyond 1e40 s: no run gets there
  std::string s(buf.data(), r.ptr);
  while (s.back() == '0')
    s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace ncsim::cli
