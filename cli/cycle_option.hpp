#pragma once
// cli/cycle_option: the checks of `--cycle-us` (time, run, report, sweep, tune-delay) and of
// `run --every N`. --cycle-us is the interpolation cycle in whole microseconds; it overrides the
// channel list's NCSIM-CHAN-610 ncsim.cycle_time, whose bounds are the same (docs/ipo.md "The
// cycle time"). Whole microseconds keep every t of the CSV and the golden files a whole number
// of us; 1 us .. 1 s bounds it.

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>

namespace ncsim::cli {

inline constexpr std::uint64_t kMinCycleUs = 1;        ///< smallest --cycle-us [us]
inline constexpr std::uint64_t kMaxCycleUs = 1000000;  ///< largest --cycle-us [us] (1 s)

/// Why `text` is not a valid --cycle-us value, "" when it is: a whole number of microseconds
/// written in digits, 1 .. 1000000.
inline std::string cycle_us_error(std::string_view text) {
  const std::string range = "1 to 1000000 us; 1000 us = 1 ms";
  if (text.empty())
    return "needs a value: the interpolation cycle in whole microseconds (" + range + ")";
  const bool negative = text.front() == '-';
  const std::string_view digits = negative ? text.substr(1) : text;
  const bool all_digits =
      !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
  if (!all_digits) {
    return "'" + std::string(text) + "' is not a whole number of microseconds in digits (" + range +
           ")";
  }
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  (void)end;
  if (negative || (ec == std::errc{} && value < kMinCycleUs)) {
    return std::string(text) + " us is below the smallest cycle, 1 us";
  }
  if (ec == std::errc::result_out_of_range || value > kMaxCycleUs) {
    return std::string(text) + " us is above the largest cycle, 1000000 us (1 s)";
  }
  return "";
}

inline constexpr std::uint64_t kMaxEvery = std::uint64_t{1} << 40;  ///< largest --every N

/// Why `text` is not a valid `run --every N` value, "" when it is: a whole number of cycles
/// written in digits, 1 .. 2^40 (docs/ipo.md "The commands").
inline std::string every_error(std::string_view text) {
  const std::string range = "1 to 1099511627776 cycles; 1 writes every cycle";
  if (text.empty()) return "needs a value: one row every N cycles (" + range + ")";
  const bool negative = text.front() == '-';
  const std::string_view digits = negative ? text.substr(1) : text;
  const bool all_digits =
      !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
  if (!all_digits)
    return "'" + std::string(text) + "' is not a whole number of cycles in digits (" + range + ")";
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  (void)end;
  if (negative || (ec == std::errc{} && value < 1))
    return std::string(text) + " is below the smallest, 1 (a row every cycle)";
  if (ec == std::errc::result_out_of_range || value > kMaxEvery)
    return std::string(text) + " is above the largest, 1099511627776 (2^40) cycles";
  return "";
}

}  // namespace ncsim::cli
