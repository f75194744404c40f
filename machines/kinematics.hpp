#pragma once
// machines/kinematics: MCS <-> ACS transforms, chosen by kinematic id through one interface.
//
// Inputs: three axis values (ACS: mm for linear axes, degrees for delta drives) or an MCS point
// [mm]. Outputs: the other side, or a KinError as a value (never thrown: forward/inverse run in
// the cycle).
// Ids: 0 = Cartesian identity (no transformation); 37 = 3-arm delta robot (delta_kinematics.hpp,
// parameter mapping is an ncsim decision, docs/machines.md "Kinematic 37"). Any other id gives
// error 292005 (isg-language.md §5.9).
// Invariants: forward(inverse(p)) == p and inverse(forward(q)) == q to kSamePoint wherever both
// succeed (on the configured branch; see the delta header).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace ncsim::machines {

struct KinError {
  std::string id;       ///< "NC3201" workspace, "NC3202" joint limit, "292005" unknown id, ...
  std::string message;  ///< names the point or joint and the limit
};

struct KinResult {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  ///< valid when !error
  std::optional<KinError> error;
  bool ok() const { return !error.has_value(); }
};

class Kinematics {
 public:
  virtual ~Kinematics() = default;
  /// Kinematic id as in #KIN ID[..] / trafo[j].id.
  virtual int id() const = 0;
  /// ACS axis values -> MCS point [mm].
  virtual KinResult forward(const Eigen::Vector3d& acs) const = 0;
  /// MCS point [mm] -> ACS axis values.
  virtual KinResult inverse(const Eigen::Vector3d& mcs) const = 0;
};

struct KinematicsBuild {
  std::unique_ptr<Kinematics> kinematics;  ///< set when !error
  std::optional<KinError> error;
};

/// Builds the kinematic `id` from its trafo parameters, already in internal units (mm, deg):
/// params[k] is trafo[j].param[k] * 1e-4. Unknown id -> error 292005; bad geometry -> NC3203.
KinematicsBuild make_kinematics(int id, std::span<const double> params);

/// The identity transform (id 0).
class CartesianKinematics final : public Kinematics {
 public:
  int id() const override { return 0; }
  KinResult forward(const Eigen::Vector3d& acs) const override { return KinResult{acs, {}}; }
  KinResult inverse(const Eigen::Vector3d& mcs) const override { return KinResult{mcs, {}}; }
};

}  // namespace ncsim::machines
