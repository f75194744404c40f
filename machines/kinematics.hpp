#pragma once
// machines/kinematics: MCS <-> ACS transforms, chosen by kinematic id through one interface.
//
// Inputs: three axis values (ACS: mm for linear axes, degrees for delta drives) or an MCS point
// [mm]; or, through forward_axes / inverse_axes, the values of the kinematic's machine axes in
// the order X, Y, Z, A, B, C (KinAxes; a 3-axis kinematic uses X, Y, Z and passes A, B, C).
// Outputs: the other side, or a KinError as a value (never thrown: forward/inverse run in the
// cycle).
// Ids: 0 = Cartesian identity (no transformation); 37 = 3-arm delta robot (delta_kinematics.hpp,
// parameter mapping is an ncsim decision, docs/machines.md "Kinematic 37"); 45 = 6-axis
// articulated robot (arm_kinematics.hpp, docs/machines.md "Kinematic 45"). Any other id gives
// error 292005 (isg-language.md §5.9).
// Invariants: forward(inverse(p)) == p and inverse(forward(q)) == q to kSamePoint wherever both
// succeed (on the configured branch; see the delta and arm headers).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
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

/// Most machine axes one kinematic maps: X, Y, Z, A, B, C.
inline constexpr std::size_t kKinAxes = 6;
/// Axis names of a kinematic's slots, in slot order.
inline constexpr std::array<const char*, kKinAxes> kKinAxisNames{"X", "Y", "Z", "A", "B", "C"};
/// Values of the slots X, Y, Z, A, B, C: ACS [mm | deg] or MCS (TCP [mm], orientation [deg]).
using KinAxes = std::array<double, kKinAxes>;

struct KinAxesResult {
  KinAxes value{};  ///< valid when !error
  std::optional<KinError> error;
  bool ok() const { return !error.has_value(); }
};

class Kinematics {
 public:
  virtual ~Kinematics() = default;
  /// Kinematic id as in #KIN ID[..] / trafo[j].id.
  virtual int id() const = 0;
  /// How many of the slots X, Y, Z, A, B, C the kinematic maps: 3 (X, Y, Z) or 6.
  virtual std::size_t axis_count() const { return 3; }
  /// ACS axis values -> MCS point [mm] (a 3-axis kinematic).
  virtual KinResult forward(const Eigen::Vector3d& acs) const = 0;
  /// MCS point [mm] -> ACS axis values (a 3-axis kinematic).
  virtual KinResult inverse(const Eigen::Vector3d& mcs) const = 0;
  /// ACS slots -> MCS slots; the slots beyond axis_count() pass unchanged.
  virtual KinAxesResult forward_axes(const KinAxes& acs) const;
  /// MCS slots -> ACS slots; the slots beyond axis_count() pass unchanged.
  virtual KinAxesResult inverse_axes(const KinAxes& mcs) const;
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
