#include "machines/kinematics.hpp"

#include "machines/arm_kinematics.hpp"
#include "machines/delta_kinematics.hpp"

namespace ncsim::machines {

namespace {

// A 3-axis kinematic on the slots: X, Y, Z through `map`, A, B, C unchanged.
template <class Map>
KinAxesResult on_xyz(const KinAxes& in, Map map) {
  KinAxesResult out;
  out.value = in;
  const KinResult r = map(Eigen::Vector3d(in[0], in[1], in[2]));
  if (!r.ok()) {
    out.error = r.error;
    return out;
  }
  for (std::size_t k = 0; k < 3; ++k)
    out.value[k] = r.value[static_cast<Eigen::Index>(k)];
  return out;
}

}  // namespace

KinAxesResult Kinematics::forward_axes(const KinAxes& acs) const {
  return on_xyz(acs, [this](const Eigen::Vector3d& p) { return forward(p); });
}

KinAxesResult Kinematics::inverse_axes(const KinAxes& mcs) const {
  return on_xyz(mcs, [this](const Eigen::Vector3d& p) { return inverse(p); });
}

KinematicsBuild make_kinematics(int id, std::span<const double> params) {
  KinematicsBuild out;
  switch (id) {
    case 0:
      out.kinematics = std::make_unique<CartesianKinematics>();
      return out;
    case DeltaKinematics::kId: {
      const DeltaGeometry geometry = delta_geometry_from_params(params);
      if (auto e = validate(geometry)) {
        out.error = std::move(e);
        return out;
      }
      out.kinematics = std::make_unique<DeltaKinematics>(geometry);
      return out;
    }
    case ArmKinematics::kId: {
      const ArmGeometry geometry = arm_geometry_from_params(params);
      if (auto e = validate(geometry)) {
        out.error = std::move(e);
        return out;
      }
      out.kinematics = std::make_unique<ArmKinematics>(geometry);
      return out;
    }
    default:
      out.error =
          KinError{"292005", "illegal kinematic id " + std::to_string(id) +
                                 "; ncsim knows 0 (Cartesian), 37 (delta) and 45 (6-axis arm)"};
      return out;
  }
}

}  // namespace ncsim::machines
