#include "axes/modulo.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::axes {

std::string_view diagnostic_id(ModuloStatus status) noexcept {
  switch (status) {
    case ModuloStatus::ok:
      return {};
    case ModuloStatus::invalid_target_position:
      return "NC5510";
    case ModuloStatus::invalid_additional_turn_count:
      return "NC5511";
  }
  return {};
}

std::string_view describe(ModuloStatus status) noexcept {
  switch (status) {
    case ModuloStatus::ok:
      return "ok";
    case ModuloStatus::invalid_target_position:
      return "invalid target position: a modulo target must lie in [0, modulo factor)";
    case ModuloStatus::invalid_additional_turn_count:
      return "invalid additional turn count: turns must be >= 0 and 0 with the shortest way";
  }
  return {};
}

double modulo_position(double absolute, double factor) noexcept {
  double m = std::fmod(absolute, factor);
  if (m < 0.0) m += factor;
  if (m >= factor) m -= factor;  // -1e-17 + factor rounds to factor
  return m;
}

ModuloMove plan_modulo(const ModuloParams& params, const ModuloRequest& request) {
  const double factor = params.factor;
  if (!std::isfinite(factor) || factor <= 0.0) {
    throw std::invalid_argument("Modulo Factor = " + core::number_text(factor) +
                                ": must be finite and > 0");
  }
  if (!std::isfinite(params.tolerance) || params.tolerance < 0.0) {
    throw std::invalid_argument("Tolerance Window for Modulo Start = " +
                                core::number_text(params.tolerance) + ": must be finite and >= 0");
  }
  ModuloMove move;
  move.end_position = request.start;
  move.end_modulo = request.target;
  if (!std::isfinite(request.target) || request.target < 0.0 || request.target >= factor ||
      !std::isfinite(request.start)) {
    move.status = ModuloStatus::invalid_target_position;
    return move;
  }
  if (request.additional_turns < 0 ||
      (request.direction == ModuloDirection::shortest_way && request.additional_turns != 0)) {
    move.status = ModuloStatus::invalid_additional_turn_count;
    return move;
  }

  // Distance to the next occurrence of the target in positive direction, in [0, factor).
  double forward = request.target - modulo_position(request.start, factor);
  if (forward < 0.0) forward += factor;
  if (forward >= factor) forward -= factor;
  // The nearer occurrence; half a turn counts as positive (ncsim decision).
  const double shortest = forward > 0.5 * factor ? forward - factor : forward;

  double base = 0.0;
  if (std::fabs(shortest) <= params.tolerance ||
      request.direction == ModuloDirection::shortest_way) {
    base = shortest;
  } else if (request.direction == ModuloDirection::positive) {
    base = forward;
  } else {
    base = forward == 0.0 ? 0.0 : forward - factor;
  }
  const double turns = static_cast<double>(request.additional_turns) * factor;
  move.distance = request.direction == ModuloDirection::negative ? base - turns : base + turns;
  move.end_position = request.start + move.distance;
  return move;
}

ModuloRequest from_signed_modulo_position(double start, double signed_position,
                                          double factor) noexcept {
  ModuloRequest request;
  request.start = start;
  // 002_* 2.1: 0.0 cannot carry a direction and counts as positive.
  request.direction = signed_position < 0.0 ? ModuloDirection::negative : ModuloDirection::positive;
  const double magnitude = std::fabs(signed_position);
  if (!std::isfinite(magnitude) || !(factor > 0.0)) {
    request.target = std::numeric_limits<double>::quiet_NaN();  // plan: invalid target
    return request;
  }
  const double turns = std::floor(magnitude / factor);
  if (turns > static_cast<double>(std::numeric_limits<int>::max())) {
    request.additional_turns = -1;  // plan: invalid additional turn count
    return request;
  }
  request.additional_turns = static_cast<int>(turns);
  request.target = magnitude - turns * factor;
  return request;
}

}  // namespace ncsim::axes
