#pragma once
// machines/conveyor_params: the conveyor axis's actual-value filter and delay-time parameters
// by their list key (seed 004 §2.1.4, §5.2.1): the one key -> field mapping the loader and a
// program's `#MACHINE DATA` (program/machine_data.hpp; 004 l.391) share.

#include <array>
#include <string_view>

#include "machines/machine.hpp"

namespace ncsim::machines {

/// One conv_sync.* parameter: its list key and how a value in internal units (the delay time
/// in s; orders and flags as numbers, uns32 0..1000 in param_table.cpp) lands in the params.
struct ConveyorFilterParam {
  std::string_view key;
  void (*set)(ConveyorAxisParams& params, double value);
};

/// P-AXIS-00620, NCSIM-AXIS-005, NCSIM-AXIS-006, P-AXIS-00623, 00624, 00625, 00626.
inline constexpr std::array<ConveyorFilterParam, 7> kConveyorFilterParams{{
    {"conv_sync.enable_filter",
     [](ConveyorAxisParams& p, double v) { p.enable_filter = v != 0.0; }},
    {"conv_sync.type_pos_filter",
     [](ConveyorAxisParams& p, double v) { p.type_pos_filter = static_cast<int>(v); }},
    {"conv_sync.order_pos_filter",
     [](ConveyorAxisParams& p, double v) { p.order_pos_filter = static_cast<int>(v); }},
    {"conv_sync.order_v_filter",
     [](ConveyorAxisParams& p, double v) { p.order_v_filter = static_cast<int>(v); }},
    {"conv_sync.order_post_v_filter",
     [](ConveyorAxisParams& p, double v) { p.order_post_v_filter = static_cast<int>(v); }},
    {"conv_sync.order_v_filter_dyn",
     [](ConveyorAxisParams& p, double v) { p.order_v_filter_dyn = static_cast<int>(v); }},
    {"conv_sync.delay_time", [](ConveyorAxisParams& p, double v) { p.delay_time = v; }},
}};

/// The parameter with list key `key`, or null for any other key.
const ConveyorFilterParam* find_conveyor_filter_param(std::string_view key) noexcept;

}  // namespace ncsim::machines
