// machines/arm_kinematics: the 6-axis articulated robot of #KIN ID[45] (see the header).
//
// Names in this file: q1..q6 joint angles; the arm plane is spanned by e_r (joint 1's
// direction) and +Z; in it (r, z) are the wrist centre's coordinates from the shoulder, phi the
// forearm's angle from the vertical (q2 + q3 + 90 deg), L = |(a3, d4)| the elbow-to-wrist
// distance and delta = atan2(a3, d4) its angle off the forearm's axis.
#include "machines/arm_kinematics.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::machines {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

double rad(double deg) {
  return deg / kDegPerRad;
}

// Wraps an angle [deg] into (-180, 180].
double wrap_deg(double a) {
  double w = std::remainder(a, 360.0);
  if (w <= -180.0) w += 360.0;
  return w;
}

Eigen::Matrix3d rot_x(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d rot_y(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d rot_z(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// The tool-down reference: A = B = C = 0 turns the flange's axis onto -Z.
Eigen::Matrix3d tool_down() {
  return rot_y(std::numbers::pi);
}

// Tool orientation from A, B, C [deg] (header).
Eigen::Matrix3d orientation(double a_deg, double b_deg, double c_deg) {
  return rot_z(rad(c_deg)) * rot_y(rad(b_deg)) * rot_x(rad(a_deg)) * tool_down();
}

// A, B, C [deg] of a tool orientation; at B = +-90 deg (tool horizontal) A is 0.
std::array<double, 3> abc_of(const Eigen::Matrix3d& r) {
  const Eigen::Matrix3d n = r * tool_down().transpose();
  const double cb = std::hypot(n(0, 0), n(1, 0));
  const double b = std::atan2(-n(2, 0), cb);
  if (cb < kTiny) return {0.0, b * kDegPerRad, std::atan2(-n(0, 1), n(1, 1)) * kDegPerRad};
  return {std::atan2(n(2, 1), n(2, 2)) * kDegPerRad, b * kDegPerRad,
          std::atan2(n(1, 0), n(0, 0)) * kDegPerRad};
}

// The forearm frame: joint 1 turned, +Z onto the forearm's axis (angle phi from the vertical).
Eigen::Matrix3d forearm_frame(double q1_rad, double phi_rad) {
  return rot_z(q1_rad) * rot_y(phi_rad);
}

std::string pose_text(const KinAxes& p) {
  return "X" + core::number_text(p[0]) + " Y" + core::number_text(p[1]) + " Z" +
         core::number_text(p[2]) + " A" + core::number_text(p[3]) + " B" + core::number_text(p[4]) +
         " C" + core::number_text(p[5]);
}

KinError error(const char* id, const std::string& what) {
  return KinError{id, "kinematic 45 (6-axis arm): " + what};
}

// Joint `i` (0-based) of `q` outside its limits: NC3202.
std::optional<KinError> limit_error(const ArmGeometry& g, const KinAxes& q, const std::string& at) {
  for (std::size_t i = 0; i < 6; ++i) {
    if (q[i] >= g.joint_min_deg[i] && q[i] <= g.joint_max_deg[i]) continue;
    return error("NC3202", at + "joint " + std::to_string(i + 1) + " = " + core::number_text(q[i]) +
                               " deg, outside its limits " + core::number_text(g.joint_min_deg[i]) +
                               ".." + core::number_text(g.joint_max_deg[i]) + " deg");
  }
  return std::nullopt;
}

}  // namespace

std::optional<KinError> validate(const ArmGeometry& g) {
  if (!(g.a2 > 0.0)) return error("NC3203", "upper arm trafo[0].param[5] must be positive");
  if (!(std::hypot(g.a3, g.d4) > 0.0))
    return error("NC3203", "forearm trafo[0].param[6] / param[7] must not both be 0");
  if (g.d6 < 0.0 || g.tool < 0.0)
    return error("NC3203", "wrist-to-flange param[8] and tool param[9] must not be negative");
  const double code = g.solution_raw * 1e4;
  if (!(code >= 0.0 && code <= 7.0) || std::abs(code - std::round(code)) > 1e-6)
    return error("NC3203", "solution code trafo[0].param[10] = " + core::number_text(code) +
                               " must be an integer 0..7");
  if (!(g.wrist_band_deg > 0.0 && g.wrist_band_deg < 45.0))
    return error("NC3203", "wrist singular band trafo[0].param[23] = " +
                               core::number_text(g.wrist_band_deg) + " deg must lie in 0..45");
  for (std::size_t i = 0; i < 6; ++i) {
    const std::string lo = "trafo[0].param[" + std::to_string(11 + 2 * i) + "]";
    const std::string hi = "trafo[0].param[" + std::to_string(12 + 2 * i) + "]";
    if (!(g.joint_min_deg[i] < g.joint_max_deg[i]))
      return error("NC3203", "joint " + std::to_string(i + 1) + " limit " + lo + " = " +
                                 core::number_text(g.joint_min_deg[i]) + " deg must be below " +
                                 hi + " = " + core::number_text(g.joint_max_deg[i]) + " deg");
    // The inverse gives every joint in (-180, 180]: a range beyond it is a second solution.
    if (g.joint_min_deg[i] < -180.0 || g.joint_max_deg[i] > 180.0)
      return error("NC3203", "joint " + std::to_string(i + 1) + " limits " + lo + " / " + hi +
                                 " must lie within -180..180 deg (one solution per pose)");
  }
  return std::nullopt;
}

ArmGeometry arm_geometry_from_params(std::span<const double> p) {
  auto at = [&p](std::size_t k) { return k < p.size() ? p[k] : 0.0; };
  ArmGeometry g;
  g.base_mm = Eigen::Vector3d(at(0), at(1), at(2));
  g.d1 = at(3);
  g.a1 = at(4);
  g.a2 = at(5);
  g.a3 = at(6);
  g.d4 = at(7);
  g.d6 = at(8);
  g.tool = at(9);
  g.solution_raw = at(10);
  const long code = std::lround(at(10) * 1e4);
  g.solution = ArmSolution{(code & 1) != 0, (code & 2) != 0, (code & 4) != 0};
  for (std::size_t i = 0; i < 6; ++i) {
    g.joint_min_deg[i] = at(11 + 2 * i);
    g.joint_max_deg[i] = at(12 + 2 * i);
  }
  if (at(23) != 0.0) g.wrist_band_deg = at(23);
  return g;
}

KinResult ArmKinematics::forward(const Eigen::Vector3d&) const {
  return KinResult{Eigen::Vector3d::Zero(),
                   error("NC3203", "maps six axes X, Y, Z, A, B, C, not three (forward_axes)")};
}

KinResult ArmKinematics::inverse(const Eigen::Vector3d&) const {
  return KinResult{Eigen::Vector3d::Zero(),
                   error("NC3203", "maps six axes X, Y, Z, A, B, C, not three (inverse_axes)")};
}

KinAxesResult ArmKinematics::forward_axes(const KinAxes& q) const {
  KinAxesResult out;
  if (auto e = limit_error(g_, q, "joints " + pose_text(q) + ": ")) {
    out.error = std::move(e);
    return out;
  }
  const double q1 = rad(q[0]), q2 = rad(q[1]), phi = rad(q[1] + q[2] + 90.0);
  const double delta = std::atan2(g_.a3, g_.d4), l = std::hypot(g_.a3, g_.d4);
  // The wrist centre in the arm plane, then in MCS.
  const double r = g_.a1 + g_.a2 * std::sin(q2) + l * std::sin(phi - delta);
  const double z = g_.d1 + g_.a2 * std::cos(q2) + l * std::cos(phi - delta);
  const Eigen::Vector3d wrist = g_.base_mm + Eigen::Vector3d(r * std::cos(q1), r * std::sin(q1), z);
  const Eigen::Matrix3d flange =
      forearm_frame(q1, phi) * rot_z(rad(q[3])) * rot_y(rad(q[4])) * rot_z(rad(q[5]));
  const Eigen::Vector3d tcp = wrist + (g_.d6 + g_.tool) * flange.col(2);
  const std::array<double, 3> abc = abc_of(flange);
  out.value = {tcp.x(), tcp.y(), tcp.z(), abc[0], abc[1], abc[2]};
  return out;
}

KinAxesResult ArmKinematics::inverse_axes(const KinAxes& mcs) const {
  return inverse_on(mcs, g_.solution);
}

KinAxesResult ArmKinematics::inverse_on(const KinAxes& mcs, const ArmSolution& s) const {
  KinAxesResult out;
  const Eigen::Matrix3d target = orientation(mcs[3], mcs[4], mcs[5]);
  const Eigen::Vector3d wrist =
      Eigen::Vector3d(mcs[0], mcs[1], mcs[2]) - g_.base_mm - (g_.d6 + g_.tool) * target.col(2);
  const double rho = std::hypot(wrist.x(), wrist.y());
  if (rho < kShoulderSingular) {
    out.error =
        error("NC3204", "pose " + pose_text(mcs) + " puts the wrist centre " +
                            core::number_text(rho) + " mm from joint 1's axis (below " +
                            core::number_text(kShoulderSingular) + " mm: shoulder singularity)");
    return out;
  }
  const double azimuth = std::atan2(wrist.y(), wrist.x());
  const double q1 = s.shoulder_back ? rad(wrap_deg(azimuth * kDegPerRad + 180.0)) : azimuth;
  const double r = (s.shoulder_back ? -rho : rho) - g_.a1;
  const double z = wrist.z() - g_.d1;
  const double dist = std::hypot(r, z);
  const double l = std::hypot(g_.a3, g_.d4), delta = std::atan2(g_.a3, g_.d4);
  const double c = (g_.a2 * g_.a2 + dist * dist - l * l) / (2.0 * g_.a2 * std::max(dist, kTiny));
  if (dist < kZeroLength || std::abs(c) > 1.0) {
    out.error = error("NC3201", "pose " + pose_text(mcs) + " is out of reach (wrist centre " +
                                    core::number_text(dist) + " mm from the shoulder, reach " +
                                    core::number_text(std::abs(g_.a2 - l)) + ".." +
                                    core::number_text(g_.a2 + l) + " mm)");
    return out;
  }
  const double beta = std::atan2(r, z), alpha = std::acos(c);
  const double q2 = s.elbow_down ? beta + alpha : beta - alpha;
  const double psi = std::atan2(r - g_.a2 * std::sin(q2), z - g_.a2 * std::cos(q2));
  const double q3 = psi + delta - q2 - std::numbers::pi / 2.0;
  const double phi = q2 + q3 + std::numbers::pi / 2.0;
  // The wrist: M = R_F^T R = Rz(q4) Ry(q5) Rz(q6).
  const Eigen::Matrix3d m = forearm_frame(q1, phi).transpose() * target;
  const double s5 = std::hypot(m(0, 2), m(1, 2));
  const double q5 = std::atan2(s5, m(2, 2));
  if (s5 < std::sin(rad(g_.wrist_band_deg))) {
    out.error = error("NC3204", "pose " + pose_text(mcs) +
                                    " needs joint 5 = " + core::number_text(q5 * kDegPerRad) +
                                    " deg, within the wrist singular band " +
                                    core::number_text(g_.wrist_band_deg) + " deg of 0 / 180 deg");
    return out;
  }
  const double sign = s.wrist_flip ? -1.0 : 1.0;
  const double q4 = std::atan2(sign * m(1, 2), sign * m(0, 2));
  const double q6 = std::atan2(sign * m(2, 1), -sign * m(2, 0));
  out.value = {q1 * kDegPerRad, wrap_deg(q2 * kDegPerRad), wrap_deg(q3 * kDegPerRad),
               q4 * kDegPerRad, sign * q5 * kDegPerRad,    q6 * kDegPerRad};
  if (auto e = limit_error(g_, out.value, "pose " + pose_text(mcs) + " needs ")) {
    out.error = std::move(e);
    return out;
  }
  return out;
}

ArmSolution ArmKinematics::solution_of(const KinAxes& q) const {
  const double q2 = rad(q[1]), phi = rad(q[1] + q[2] + 90.0);
  const double delta = std::atan2(g_.a3, g_.d4), l = std::hypot(g_.a3, g_.d4);
  // The wrist centre in joint 1's frame: r from the shoulder along e_r, z above it.
  const double r = g_.a2 * std::sin(q2) + l * std::sin(phi - delta);
  const double z = g_.a2 * std::cos(q2) + l * std::cos(phi - delta);
  ArmSolution s;
  s.shoulder_back = r + g_.a1 < 0.0;
  s.elbow_down = wrap_deg((std::atan2(r, z) - q2) * kDegPerRad) < 0.0;
  s.wrist_flip = q[4] < 0.0;
  return s;
}

}  // namespace ncsim::machines
