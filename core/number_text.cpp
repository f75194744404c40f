#include "core/number_text.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace ncsim::core {

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0.0) return "0";  // also for -0.0: a user never writes "-0" for a result
  // Fixed notation where a user writes numbers that way (a 0.1 um parameter of 40000000 is not
  // "4e+07"), the shortest exponent form outside; both read back to the same double.
  char buffer[64];
  const double magnitude = std::fabs(value);
  const auto format =
      magnitude >= 1e-5 && magnitude < 1e16 ? std::chars_format::fixed : std::chars_format::general;
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, format);
  return std::string(buffer, result.ptr);
}

std::string micro_text(double value) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 6);
  if (r.ec != std::errc{} || !std::isfinite(value)) return number_text(value);
  std::string s(buffer, r.ptr);
  while (s.back() == '0')
    s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace ncsim::core
