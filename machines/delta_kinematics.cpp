#include "machines/delta_kinematics.hpp"

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

Eigen::Vector3d arm_direction(int arm) {
  const double azimuth = 2.0 * std::numbers::pi / 3.0 * arm;
  return Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0.0);
}

std::string point_text(const Eigen::Vector3d& p) {
  return "(" + core::number_text(p.x()) + ", " + core::number_text(p.y()) + ", " +
         core::number_text(p.z()) + ")";
}

// Wraps an angle [deg] into (-180, 180].
double wrap_deg(double a) {
  double w = std::remainder(a, 360.0);
  if (w <= -180.0) w += 360.0;
  return w;
}

}  // namespace

std::optional<KinError> validate(const DeltaGeometry& g) {
  auto bad = [](const std::string& what) {
    return KinError{"NC3203", "kinematic 37 (delta): " + what};
  };
  if (!(g.l_upper > 0.0)) return bad("upper arm length trafo[0].param[6] must be positive");
  if (!(g.l_lower > 0.0)) return bad("lower arm length trafo[0].param[5] must be positive");
  if (g.r_base < 0.0) return bad("base radius trafo[0].param[4] must not be negative");
  if (g.r_effector < 0.0) return bad("effector radius trafo[0].param[3] must not be negative");
  if (!(g.joint_min_deg < g.joint_max_deg)) {
    return bad("joint limit trafo[0].param[10] = " + core::number_text(g.joint_min_deg) +
               " deg must be below trafo[0].param[11] = " + core::number_text(g.joint_max_deg) +
               " deg");
  }
  return std::nullopt;
}

DeltaGeometry delta_geometry_from_params(std::span<const double> p) {
  auto at = [&p](std::size_t k) { return k < p.size() ? p[k] : 0.0; };
  DeltaGeometry g;
  g.base_mm = Eigen::Vector3d(at(0), at(1), at(2));
  g.r_effector = at(3);
  g.r_base = at(4);
  g.l_lower = at(5);
  g.l_upper = at(6);
  g.zero_offset_deg = {at(7), at(8), at(9)};
  g.joint_min_deg = at(10);
  g.joint_max_deg = at(11);
  g.tcp_offset = at(12);
  return g;
}

KinResult DeltaKinematics::forward(const Eigen::Vector3d& acs) const {
  KinResult out;
  std::array<Eigen::Vector3d, 3> centre;
  for (int i = 0; i < 3; ++i) {
    if (acs[i] < g_.joint_min_deg || acs[i] > g_.joint_max_deg) {
      out.error =
          KinError{"NC3202", "kinematic 37 (delta): drive " + std::to_string(i + 1) + " = " +
                                 core::number_text(acs[i]) + " deg is outside its limits " +
                                 core::number_text(g_.joint_min_deg) + ".." +
                                 core::number_text(g_.joint_max_deg) + " deg"};
      return out;
    }
    const double theta = rad(acs[i] - g_.zero_offset_deg[static_cast<std::size_t>(i)]);
    // Sphere of the effector centre: elbow shifted inwards by the effector radius.
    centre[static_cast<std::size_t>(i)] =
        (g_.r_base - g_.r_effector + g_.l_upper * std::cos(theta)) * arm_direction(i) -
        g_.l_upper * std::sin(theta) * Eigen::Vector3d::UnitZ();
  }
  // Intersection of three spheres of equal radius l_lower.
  const Eigen::Vector3d d12 = centre[1] - centre[0];
  const Eigen::Vector3d d13 = centre[2] - centre[0];
  const double d = d12.norm();
  const Eigen::Vector3d ex = d12 / d;
  const double i = ex.dot(d13);
  const Eigen::Vector3d ey_raw = d13 - i * ex;
  const double j = ey_raw.norm();
  if (d < kZeroLength || j < kZeroLength) {
    out.error = KinError{"NC3201", "kinematic 37 (delta): drive angles " + point_text(acs) +
                                       " deg give a degenerate arm position"};
    return out;
  }
  const Eigen::Vector3d ey = ey_raw / j;
  const Eigen::Vector3d ez = ex.cross(ey);
  const double x = d / 2.0;
  const double y = (i * i + j * j - 2.0 * i * x) / (2.0 * j);
  const double z2 = g_.l_lower * g_.l_lower - x * x - y * y;
  if (z2 < 0.0) {
    out.error = KinError{"NC3201", "kinematic 37 (delta): drive angles " + point_text(acs) +
                                       " deg cannot be assembled (lower arms too short)"};
    return out;
  }
  const double z = std::sqrt(z2);
  const Eigen::Vector3d base_point = centre[0] + x * ex + y * ey;
  const Eigen::Vector3d p1 = base_point + z * ez;
  const Eigen::Vector3d p2 = base_point - z * ez;
  const Eigen::Vector3d effector = p1.z() < p2.z() ? p1 : p2;
  out.value = g_.base_mm + effector - g_.tcp_offset * Eigen::Vector3d::UnitZ();
  return out;
}

KinResult DeltaKinematics::inverse(const Eigen::Vector3d& mcs) const {
  KinResult out;
  const Eigen::Vector3d p = mcs - g_.base_mm + g_.tcp_offset * Eigen::Vector3d::UnitZ();
  for (int arm = 0; arm < 3; ++arm) {
    const Eigen::Vector3d u = arm_direction(arm);
    const Eigen::Vector3d v = Eigen::Vector3d::UnitZ().cross(u);
    const double wx = p.dot(u) + g_.r_effector - g_.r_base;
    const double wy = p.dot(v);
    const double wz = p.z();
    const double k =
        (wx * wx + wy * wy + wz * wz + g_.l_upper * g_.l_upper - g_.l_lower * g_.l_lower) /
        (2.0 * g_.l_upper);
    const double a = wx;
    const double b = -wz;
    const double r = std::hypot(a, b);
    if (r < kZeroLength || std::abs(k) > r) {
      out.error = KinError{"NC3201", "kinematic 37 (delta): point " + point_text(mcs) +
                                         " mm is outside the workspace (arm " +
                                         std::to_string(arm + 1) + " cannot reach it)"};
      return out;
    }
    const double theta = std::atan2(b, a) - std::acos(k / r);
    const double axis_deg =
        wrap_deg(theta * kDegPerRad) + g_.zero_offset_deg[static_cast<std::size_t>(arm)];
    if (axis_deg < g_.joint_min_deg || axis_deg > g_.joint_max_deg) {
      out.error =
          KinError{"NC3202", "kinematic 37 (delta): point " + point_text(mcs) + " mm needs drive " +
                                 std::to_string(arm + 1) + " = " + core::number_text(axis_deg) +
                                 " deg, outside its limits " + core::number_text(g_.joint_min_deg) +
                                 ".." + core::number_text(g_.joint_max_deg) + " deg"};
      return out;
    }
    out.value[arm] = axis_deg;
  }
  return out;
}

}  // namespace ncsim::machines
