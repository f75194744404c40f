#pragma once
// core/number_text: numbers in messages as a user would write them.
//
// The shortest text that reads back to the same double, in fixed notation from 1e-5 to 1e16
// ("10", "-0.5", "40000000", "0.00002") and with an exponent outside ("1e-07", "2.5e+20");
// independent of the locale. For diagnostics; traces and trajectory files use their own fixed
// formats.

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

}  // namespace ncsim::core
