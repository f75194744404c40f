#pragma once
// interp/weights: the dynamics weightings G127..G133, G230, G231, G233 (docs/interp.md "Dynamics
// weighting").
//
// Inputs: one weighting G code of a block, its group value [%] (G128=50) or the block's axis
// words [%] (G130 X70 Y50), the weights in force. Outputs: the new weights and the notes on
// values ncsim limits. Method (TF5200): every selection starts again from 100 % ("50 %
// programmed twice is 50 %, not 25 %"); an axis-specific form sets the axes it names and puts
// every other axis back to 100 %. ncsim lowers limits only: a velocity or acceleration weight
// above 100 % and a ramp-time weight below 100 % would ask more of an axis than its list
// allows, which the audit proves against, so they are limited to 100 % with warning NC4314; a
// weight below 1 % is limited to 1 % (decision: the manual's 0 % creeps at 1 um/s), a ramp
// time above 10000 % to 10000 %.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "interp/command.hpp"

namespace ncsim::interp {

/// True for the weighting codes ncsim applies (G127..G133, G230, G231, G233).
bool is_applied_weighting(std::uint32_t code) noexcept;
/// True for the feed-hold weightings G333, G334 (acceleration), G338, G339 (ramp time): no
/// effect with P-CHAN-00097 = 0, ncsim's only feed hold (PROG-206590731, PROG-206596619).
bool is_feedhold_weighting(std::uint32_t code) noexcept;
/// True for the axis-specific forms (G127, G130, G132, G230, G333, G338): axis words are weights.
bool is_axis_weighting(std::uint32_t code) noexcept;

/// Applies `code` to `w`. `group`: the group form's value [%]; `axes`: machine index and value
/// [%] of the axis-specific form; `axes_of_machine` name them in the notes. Returns the notes
/// (one per limited value) for NC4314.
std::vector<std::string> apply_weighting(DynamicsWeights& w, std::uint32_t code,
                                         std::optional<double> group,
                                         std::span<const std::pair<std::uint8_t, double>> axes,
                                         std::span<const machines::AxisParams> axes_of_machine);

}  // namespace ncsim::interp
