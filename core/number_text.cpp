#include "core/number_text.hpp"

#include <charconv>
#include <cmath>

namespace ncsim::core {

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0.0) return "0";  // also for -0.0: a user never writes "-0" for a result
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace ncsim::core
