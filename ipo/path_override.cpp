// ipo/path_override: the run-time override settings (see the header).

#include "ipo/path_override.hpp"

#include <stdexcept>
#include <string>

namespace ncsim::ipo {

void PathOverride::set_override(double factor) {
  const double hi = max_override(type_);
  if (!(factor >= 0.0) || !(factor <= hi))
    throw std::invalid_argument("ipo: override " + std::to_string(factor) + " outside [0, " +
                                std::to_string(hi) + "] for override type " +
                                override_type_name(type_) + " (NCSIM-CHAN-630)");
  override_ = factor;
}

}  // namespace ncsim::ipo
