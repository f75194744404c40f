#include "core/number_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

namespace ncsim::core {
namespace {

// Fixed notation of the largest double: 309 digits, sign, point and up to 17 decimals.
constexpr std::size_t kFixedMax = 400;

}  // namespace

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

std::string num(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

std::string json_num(double v) {
  return std::isfinite(v) ? num(v) : std::string("null");
}

std::string json_num(double v, int digits) {
  return std::isfinite(v) ? significant_text(v, digits) : std::string("null");
}

std::string significant_text(double v, int digits) {
  std::array<char, 64> buf{};
  const auto r =
      std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, digits);
  return std::string(buf.data(), r.ptr);
}

std::string human(double v) {
  return significant_text(v, 6);
}

std::string signed_human(double v) {
  return std::signbit(v) ? human(v) : "+" + human(v);
}

std::string seconds(double t) {
  return micro_text(t);
}

std::string fixed_text(double v) {
  std::array<char, kFixedMax> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed);
  return std::string(buf.data(), r.ptr);
}

std::string decimals_text(double v, int decimals) {
  std::array<char, kFixedMax> buf{};
  if (v == 0.0) v = 0.0;  // no "-0.0000"
  const auto r =
      std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, decimals);
  std::string s(buf.data(), r.ptr);
  // A negative value that rounds to zero ("-0.00001" at 4 decimals) is written unsigned.
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("0.", 1) == std::string::npos)
    s.erase(0, 1);
  return s;
}

}  // namespace ncsim::core
