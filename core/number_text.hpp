#pragma once
// core/number_text: every number ncsim writes as text, in one place (locale-independent).
//
// - number_text(): numbers in messages as a user would write them: the shortest text that
//   reads back to the same double, in fixed notation from 1e-5 to 1e16 ("10", "-0.5",
//   "40000000", "0.00002") and with an exponent outside ("1e-07", "2.5e+20").
// - num() / json_num(): the shortest round-trip text (std::to_chars) for machine-readable
//   outputs (CSV, --json, --blocks, the totals, the report's times): exact values,
//   byte-identical reruns; json_num() writes `null` where JSON has no number.
// - significant_text() / human(): a number for people, to a number of significant digits
//   (printf's %g: 3000.0000000000027 -> 3000, 0.14200000000000002 -> 0.142); the numbers in
//   run-time and monitor messages (their %.6g); signed_human(): printf's %+g.
// - micro_text() / seconds(): rounded to 1e-6 of the unit (the goldens' values; a run's time).
// - fixed_text(): fixed notation, shortest round-trip (the goldens' tolerances);
//   decimals_text(): a fixed number of decimals, never "-0" (the interpreter's trace).
// Not here: integers in hex (a parameter's bit mask "0x%08X", the byte escapes of JSON and list
// files), written with snprintf where they are used.

#include <string>

namespace ncsim::core {

/// Shortest round-trip decimal text of `value` (see above); "nan", "inf", "-inf" for non-finite
/// values.
std::string number_text(double value);

/// `value` rounded to 1e-6 of its unit in fixed notation, trailing zeros and point dropped,
/// never "-0" ("10.337" for 10.338000000000001 - 0.001, "2", "0.000001"): times of a run whose
/// cycle is a whole number of microseconds, the golden files' values. number_text() where the
/// fixed text would not fit (|value| beyond ~1e40) or the value is not finite.
std::string micro_text(double value);

/// Shortest round-trip text of `v` (std::to_chars, its own choice of fixed or exponent).
std::string num(double v);

/// A number in --json and the report's data: num(), or `null` where `v` is not finite: JSON
/// has no NaN or infinity (issue 34 item 11: a NaN that got through was written as `-nan`).
std::string json_num(double v);

/// A number in JSON to `digits` significant digits (significant_text()), or `null` where `v`
/// is not finite (the report's display values: a pixel is far coarser).
std::string json_num(double v, int digits);

/// `v` to `digits` significant digits, as printf's `%.<digits>g` in the C locale ("nan",
/// "-inf" for non-finite values).
std::string significant_text(double v, int digits);

/// Text of `v` for people: 6 significant digits (printf's %g, iostream's default); the numbers
/// in run-time messages.
std::string human(double v);

/// human() with its sign always written ("+1", "-0.5", "+0"): printf's %+g.
std::string signed_human(double v);

/// Text of a run's time `t` [s] in a message: to the microsecond (the cycle is a whole number of
/// us, `--cycle-us`): 10.338000000000001 -> 10.338 (micro_text()).
std::string seconds(double t);

/// Shortest round-trip text of `v` in fixed notation, never an exponent ("0.0001", "2.5").
std::string fixed_text(double v);

/// `v` in fixed notation with exactly `decimals` decimals (0 .. 17), rounded; a value that
/// rounds to zero is written without a sign ("0.0000", never "-0.0000").
std::string decimals_text(double v, int decimals);

}  // namespace ncsim::core
