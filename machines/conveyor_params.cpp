// machines/conveyor_params: see conveyor_params.hpp.

#include "machines/conveyor_params.hpp"

#include <algorithm>

namespace ncsim::machines {

const ConveyorFilterParam* find_conveyor_filter_param(std::string_view key) noexcept {
  const auto* it = std::find_if(kConveyorFilterParams.begin(), kConveyorFilterParams.end(),
                                [&](const ConveyorFilterParam& f) { return f.key == key; });
  return it != kConveyorFilterParams.end() ? it : nullptr;
}

}  // namespace ncsim::machines
