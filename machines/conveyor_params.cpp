// machines/conveyor_params: see conveyor_params.hpp.

#include "machines/conveyor_params.hpp"

namespace ncsim::machines {

bool set_conveyor_filter_param(ConveyorAxisParams& params, std::string_view key, double value) {
  const int order = static_cast<int>(value);  // uns32 0..1000 (param_table.cpp)
  if (key == "conv_sync.enable_filter") {
    params.enable_filter = value != 0.0;
  } else if (key == "conv_sync.type_pos_filter") {
    params.type_pos_filter = order;
  } else if (key == "conv_sync.order_pos_filter") {
    params.order_pos_filter = order;
  } else if (key == "conv_sync.order_v_filter") {
    params.order_v_filter = order;
  } else if (key == "conv_sync.order_post_v_filter") {
    params.order_post_v_filter = order;
  } else if (key == "conv_sync.order_v_filter_dyn") {
    params.order_v_filter_dyn = order;
  } else if (key == "conv_sync.delay_time") {
    params.delay_time = value;
  } else {
    return false;
  }
  return true;
}

}  // namespace ncsim::machines
