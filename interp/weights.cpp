// interp/weights: see weights.hpp.

#include "interp/weights.hpp"

#include <algorithm>
#include <cmath>

#include "core/number_text.hpp"

namespace ncsim::interp {
namespace {

constexpr double kLowest = 0.01;  // 1 %
constexpr double kLongestRamp = 100.0;

double limit(double percent, bool ramp, const std::string& what, std::vector<std::string>& notes) {
  if (!std::isfinite(percent)) {
    notes.push_back(what + " is not a finite number: 100 % stays");
    return 1.0;
  }
  const double f = percent / 100.0;
  const double lo = ramp ? 1.0 : kLowest;
  const double hi = ramp ? kLongestRamp : 1.0;
  const double out = std::clamp(f, lo, hi);
  if (out != f) {
    notes.push_back(what + " = " + core::number_text(percent) + " % is limited to " +
                    core::number_text(out * 100.0) + " %" +
                    (ramp && f < 1.0
                         ? " (a shorter ramp would raise the axis's jerk above its list)"
                     : !ramp && f > 1.0 ? " (more would ask the axis beyond its list)"
                                        : ""));
  }
  return out;
}

AxisValues* feed_axes(DynamicsWeights& w, std::uint32_t code) {
  switch (code) {
    case 127:
    case 128:
      return &w.v_feed;
    case 130:
    case 131:
      return &w.a_feed;
    case 230:
    case 231:
      return &w.a_rapid;
    case 132:
    case 133:
      return &w.ramp_feed;
    default:
      return nullptr;
  }
}

}  // namespace

bool is_applied_weighting(std::uint32_t code) noexcept {
  switch (code) {
    case 127:
    case 128:
    case 129:
    case 130:
    case 131:
    case 132:
    case 133:
    case 230:
    case 231:
    case 233:
      return true;
    default:
      return false;
  }
}

bool is_feedhold_weighting(std::uint32_t code) noexcept {
  return code == 333 || code == 334 || code == 338 || code == 339;
}

bool is_axis_weighting(std::uint32_t code) noexcept {
  return code == 127 || code == 130 || code == 132 || code == 230 || code == 333 || code == 338;
}

std::vector<std::string> apply_weighting(DynamicsWeights& w, std::uint32_t code,
                                         std::optional<double> group,
                                         std::span<const std::pair<std::uint8_t, double>> axes,
                                         std::span<const machines::AxisParams> axes_of_machine) {
  std::vector<std::string> notes;
  const bool ramp = code == 132 || code == 133 || code == 233;
  const std::string g = "G" + std::to_string(code);
  if (code == 129 || code == 233) {  // group forms of one value
    const double f = limit(group.value_or(100.0), ramp, g, notes);
    (code == 129 ? w.v_rapid : w.ramp_rapid) = f;
    return notes;
  }
  AxisValues* target = feed_axes(w, code);
  if (target == nullptr) return notes;
  *target = all_ones();  // every selection starts from 100 %
  if (is_axis_weighting(code)) {
    for (const auto& [axis, percent] : axes) {
      const std::string name = axis < axes_of_machine.size() ? axes_of_machine[axis].name : "axis";
      (*target)[axis] = limit(percent, ramp, g + " " + name, notes);
    }
  } else {
    const double f = limit(group.value_or(100.0), ramp, g, notes);
    for (double& x : *target)
      x = f;
  }
  return notes;
}

}  // namespace ncsim::interp
