// ipo/path_override: the run-time override settings (see the header).

#include "ipo/path_override.hpp"

#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::ipo {

void PathOverride::set_override(double factor) {
  const double hi = max_override(type_);
  if (!(factor >= 0.0) || !(factor <= hi))
    throw std::invalid_argument("ipo: override " + core::human(factor) + " outside [0, " +
                                core::human(hi) + "] for override type " +
                                override_type_name(type_) + " (NCSIM-CHAN-630)");
  override_ = factor;
}

}  // namespace ncsim::ipo
