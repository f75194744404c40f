#pragma once
// machines/conveyor_params: the conveyor axis's actual-value filter and delay-time parameters
// by their list key (seed 004 §2.1.4, §5.2.1): the one key -> field mapping the loader and a
// program's `#MACHINE DATA` (ipo/machine_data.hpp; 004 l.391) share.

#include <array>
#include <string_view>

#include "machines/machine.hpp"

namespace ncsim::machines {

/// conv_sync.* keys of P-AXIS-00620, NCSIM-AXIS-005, NCSIM-AXIS-006, P-AXIS-00623, 00624,
/// 00625, 00626 (param_table.cpp).
inline constexpr std::array<std::string_view, 7> kConveyorFilterKeys{
    "conv_sync.enable_filter",  "conv_sync.type_pos_filter",     "conv_sync.order_pos_filter",
    "conv_sync.order_v_filter", "conv_sync.order_post_v_filter", "conv_sync.order_v_filter_dyn",
    "conv_sync.delay_time"};

/// Sets the parameter with list key `key` (one of kConveyorFilterKeys) to `value` in internal
/// units (the delay time in s; orders and flags as numbers). False, nothing changed, for any
/// other key.
bool set_conveyor_filter_param(ConveyorAxisParams& params, std::string_view key, double value);

}  // namespace ncsim::machines
