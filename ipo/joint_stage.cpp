// ipo/joint_stage: Cartesian cycle state -> joint setpoints (method in joint_stage.hpp).

#include "ipo/joint_stage.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace ncsim::ipo {

JointStage::JointStage(planner::JointMap inverse, std::size_t joint_count)
    : inverse_(std::move(inverse)), n_(joint_count) {
  if (!inverse_) throw std::invalid_argument("ipo joint stage: no inverse transform");
  if (joint_count == 0 || joint_count > planner::kMaxAxes)
    throw std::invalid_argument("ipo joint stage: joint count " + std::to_string(joint_count) +
                                " outside 1.." + std::to_string(planner::kMaxAxes));
}

bool JointStage::step(const AxisVec& x, const AxisVec& v, const AxisVec& a, const AxisVec& j,
                      JointSetpoint& out) const noexcept {
  constexpr double h = kJointStageStep;
  constexpr std::array<double, 5> taus{0.0, h, -h, 2.0 * h, -2.0 * h};
  std::array<AxisVec, 5> q{};
  bool moving = false;
  for (std::size_t i = 0; i < planner::kMaxAxes; ++i)
    moving = moving || v[i] != 0.0 || a[i] != 0.0 || j[i] != 0.0;
  const std::size_t points = moving ? taus.size() : 1;
  for (std::size_t k = 0; k < points; ++k) {
    const double t = taus[k];
    AxisVec p = x;
    for (std::size_t i = 0; i < planner::kMaxAxes; ++i)
      p[i] += t * (v[i] + t * (a[i] / 2.0 + t * j[i] / 6.0));
    try {
      if (!inverse_(p, q[k])) {
        failed_ = p;
        return false;
      }
    } catch (...) {  // a throwing map is a failing map: the per-cycle path never throws
      failed_ = p;
      return false;
    }
  }
  JointSetpoint s;
  s.q = q[0];
  if (moving) {
    for (std::size_t i = 0; i < n_; ++i) {
      s.v[i] = (q[1][i] - q[2][i]) / (2.0 * h);
      s.a[i] = (q[1][i] - 2.0 * q[0][i] + q[2][i]) / (h * h);
      s.j[i] = (q[3][i] - 2.0 * q[1][i] + 2.0 * q[2][i] - q[4][i]) / (2.0 * h * h * h);
    }
  }
  out = s;
  return true;
}

}  // namespace ncsim::ipo
