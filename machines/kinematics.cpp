#include "machines/kinematics.hpp"

#include "machines/delta_kinematics.hpp"

namespace ncsim::machines {

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
    default:
      out.error = KinError{"292005", "illegal kinematic id " + std::to_string(id) +
                                         "; ncsim knows 0 (Cartesian) and 37 (delta)"};
      return out;
  }
}

}  // namespace ncsim::machines
