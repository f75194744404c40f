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

}  // namespace ncsim::core
