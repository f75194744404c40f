#pragma once
// core/number_text: numbers in messages as a user would write them.
//
// The shortest text that reads back to the same double ("10", "-0.5", "1e-07"), independent
// of the locale. For diagnostics; traces and trajectory files use their own fixed formats.

#include <string>

namespace ncsim::core {

/// Shortest round-trip decimal text of `value`; "nan", "inf", "-inf" for non-finite values.
std::string number_text(double value);

}  // namespace ncsim::core
