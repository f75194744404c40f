#pragma once
// audit/audit: checks the cycle stream against the axis limits and the programmed contour.
//
// Purpose: prove on every run that no limit is broken (`--audit`, exit 3 on a violation).
// Inputs: the cycle stream of a PathInterpolator (as its Sink, Detail::axes), the axis limits,
// the cycle T, the start position.
// Outputs: a Verdict: per axis the largest |v|, |a|, |j| from the closed-form values and from
// finite differences of the cycle positions, against the limits; the largest distance from the
// programmed contour; the documented VELOJUMP / #TRANSVELMIN / C1 steps, listed apart and
// checked against their formulas; every violation with time and line (docs/ipo.md "The audit").
// Method:
//  - closed form: v_i, a_i, j_i of each cycle sample (chain rule on the path state) against
//    v_max (and the reference velocity), A+ when the axis speeds up / A- when it slows down,
//    and J (jerk-limited slopes only: STEP is acceleration-limited by definition); in G00
//    cycles the G00 slope (planner::rapid_limits: P-AXIS-00004, P-AXIS-00200);
//  - finite differences of the positions: v = dx / T, a = d2x / T^2, j = d3x / T^3 are
//    weighted means of the continuous v, a, j over their stencil, so they are bounded by the
//    same limits wherever v and a are continuous. A joint with a velocity step dv (C0,
//    VELOJUMP) adds at most |dv| / T to a and |dv| / T^2 to j in the cycles whose stencil holds
//    it; an acceleration step da (C1, or C0 on curves) adds at most |da| / T to j. Those cycles
//    are checked against limit + that allowance; the steps themselves against their formulas:
//    |dv_i| <= C0_i min(A+_i, |A-_i|) T (000 l.108), or at a link #TRANSVELMIN raised above
//    that (Joint::rule) |dv_i| <= v_min |dx'_i| (isg-language.md 5.6, "#TRANSVELMIN takes
//    priority"), |da_i| <= j_i T at C1 (P-CHAN-00009);
//  - contour: each motion sample's distance from its programmed block (contour.hpp), within
//    PATH_DEV where the block ends in a tolerance ball (a blend point is within r of the
//    corner, which lies on the block), else within rounding.
// Rounding: values within limit (1 + 1e-9) pass; finite differences also get the effect of a
// position noise of 1e-10 mm + 4 eps |x| (2 / T, 4 / T^2, 8 / T^3).
//  - joints (under a kinematic transform, on_joints()): each joint's v, a, j from the joint
//    stage against its own limits (A+ / A- by the sign of v a, J on jerk-limited slopes), and
//    finite differences of its positions, by the same checks as an axis (check_motion); a joint
//    has no step formula, so a stencil that holds a documented path step (VELOJUMP, C1) is
//    checked for velocity only.
//  - transformed cycles (#TRAFO ON, ipo::transformed()): the cycle's x is the TCP, which has no
//    limits of its own; the axis checks and the path joints' step formulas (Cartesian steps)
//    are left to the joints (on_joints()), the contour is checked on the TCP. When the joints
//    are the machine axes (set_joint_limits(..., true): the channel), the two share one position
//    history at a switch, so the finite differences run on across #TRAFO ON / OFF.
//  - conveyor (set_belt()): while an axis moves with the belt (catch-up, PCS1, after #SYNC OUT)
//    its setpoint is the path's share plus the belt's (share x master travel). Neither the
//    manual nor ncsim reserves acceleration or jerk for the belt's own changes (004 l.454:
//    "dynamic overshoots ... caused by fluctuations in conveyor belt velocity"); an axis's
//    acceleration or jerk beyond its limit stays a violation, and where the axis followed the
//    belt over the whole stencil the violation also carries the value less the belt's share
//    (Violation::path): within the limit, the excess is the belt's own (Verdict::belt_count).
//    Velocity is not split: the planner reserves the belt's velocity (1.10 CONV_VEL, 50653).
// Memory: the lists keep the first kMaxListed entries; counts and maxima cover everything.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "axes/control.hpp"
#include "ipo/interpolator.hpp"
#include "ipo/joint_stage.hpp"
#include "tracking/belt_offset.hpp"  // BeltOffset

namespace ncsim::audit {

enum class Quantity : std::uint8_t {
  velocity,
  acceleration,
  jerk,
  contour,
  velojump,     ///< a C0 velocity step (000 l.108)
  transvelmin,  ///< a C0 velocity step at a link #TRANSVELMIN raised (isg-language.md 5.6)
  c1_step,      ///< a C1 acceleration step (P-CHAN-00009)
};
enum class Method : std::uint8_t {
  closed_form,        ///< the interpolator's v, a, j at the cycle instant
  finite_difference,  ///< differences of the cycle positions
  geometry,           ///< distance from the programmed block
  formula,            ///< a documented step against its formula
};

/// One axis's extremes.
struct AxisAudit {
  double v_closed = 0.0, a_closed = 0.0, j_closed = 0.0;  ///< max |v|, |a|, |j| closed form
  double v_diff = 0.0, a_diff = 0.0, j_diff = 0.0;        ///< max |v|, |a|, |j| finite differences
  double v_limit = 0.0;                                   ///< min(v_max, v_reference) [mm/s]
  double a_limit = 0.0;           ///< max(A+, |A-|, G00 acceleration P-AXIS-00004) [mm/s^2]
  double j_limit = 0.0;           ///< max(J, G00 jerk) [mm/s^3]
  std::uint64_t jerk_cycles = 0;  ///< cycles whose jerk was checked (a jerk-limited slope)
};

struct Violation {
  Quantity quantity = Quantity::velocity;
  Method method = Method::closed_form;
  std::uint8_t axis = 0;
  double t = 0.0;  ///< [s]
  std::uint32_t line = 0;
  double value = 0.0;      ///< |value| measured
  double limit = 0.0;      ///< what was allowed
  bool joint = false;      ///< `axis` is a joint of the kinematic transform (on_joints())
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main program)
  /// The same quantity less the belt's share (set_belt()), where the axis moved
  /// with the belt over the whole stencil; -1: not split.
  double path = -1.0;
};

/// A documented step at a joint (the largest over the axes relative to its bound).
struct Step {
  Quantity quantity = Quantity::velojump;  ///< velojump / transvelmin (dv) or c1_step (da)
  std::uint8_t axis = 0;
  double t = 0.0;  ///< [s]
  std::uint32_t line = 0;
  double v_link = 0.0;     ///< path velocity at the joint [mm/s]
  double value = 0.0;      ///< |dv_i| [mm/s] or |da_i| [mm/s^2]
  double bound = 0.0;      ///< C0_i min(A+_i, |A-_i|) T, v_min |dx'_i| (#TRANSVELMIN), or j_i T
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main)
  bool joint = false;      ///< `axis` is a joint of the kinematic transform (--- trafo)
};

/// The documented steps of one kind: how many, and the one closest to its formula's bound.
struct StepKind {
  std::uint64_t count = 0;
  Step closest;  ///< largest value / bound (valid when count > 0)
};

struct Verdict {
  std::vector<AxisAudit> axes;
  std::vector<AxisAudit> joints;   ///< under a transform: one per joint (set_joint_limits())
  double contour_max = 0.0;        ///< largest distance from the programmed contour [mm]
  double contour_tolerance = 0.0;  ///< tolerance where the largest ratio to it was seen [mm]
  std::uint64_t cycles = 0;        ///< cycles audited
  std::uint64_t step_count = 0;    ///< documented steps seen
  std::vector<Step> steps;         ///< the first kMaxListed
  /// Per kind (velojump, transvelmin, c1_step; step_kind()): count and closest to its bound.
  std::array<StepKind, 3> step_kinds{};
  std::uint64_t violation_count = 0;
  std::vector<Violation> violations;  ///< the first kMaxListed
  /// Violations whose path share (Violation::path) was within the limit: the
  /// belt's own acceleration or jerk on top (004 l.454)
  std::uint64_t belt_count = 0;
  bool ok() const noexcept { return violation_count == 0; }
};

class Audit final : public ipo::Sink {
 public:
  static constexpr std::size_t kMaxListed = 1000;

  /// Throws std::invalid_argument when `axes` is empty or larger than kMaxAxes, or t_cycle <= 0.
  Audit(std::span<const planner::AxisLimits> axes, double t_cycle, const planner::AxisVec& start);

  void on_joint(const ipo::Joint& joint) override;
  void on_cycle(const ipo::Cycle& cycle) override;
  /// The setpoints the machine axes received (the channel's Channel::setpoints(), read at each
  /// on_cycle): the axis limits are checked on them, the contour on the cycle's path point.
  /// They differ from the path point while a conveyor moves PCS1 or a catch-up drives the
  /// axes (docs/conveyor.md). Null (default): the cycle's own values.
  void set_setpoints(const std::array<axes::Setpoint, planner::kMaxAxes>* set) noexcept {
    set_ = set;
  }
  /// The belt's share of the setpoints (read at each on_cycle with them); the
  /// violations of an axis that moved with the belt then carry their path share. Null: none.
  void set_belt(const tracking::BeltOffset* belt) noexcept { belt_ = belt; }
  /// Under a kinematic transform: the joints' limits (one per joint, 1..kMaxAxes; throws
  /// std::invalid_argument otherwise) and their positions before the first cycle.
  /// `joints_are_axes`: the joints are the machine axes the cycles hold outside #TRAFO (the
  /// channel; as many joints as axes): one position history runs on across a switch.
  void set_joint_limits(std::span<const planner::AxisLimits> joints, const planner::AxisVec& start,
                        bool joints_are_axes = false);
  /// The joint setpoints of the cycle on_cycle() just saw (ipo::JointStage): each joint's
  /// |v|, |a|, |j| against its own limits, from the stage's values and from finite differences
  /// of the joint positions ("per axis, joints included"; docs/ipo.md "The audit").
  void on_joints(const ipo::Cycle& cycle, const ipo::JointSetpoint& joints);
  const Verdict& verdict() const noexcept { return verdict_; }

 private:
  /// What one axis or joint is checked against in a cycle (check_motion).
  struct Stencil {
    planner::AxisLimits feed;     ///< its limits (feed slope)
    bool rapid = false;           ///< this cycle is G00: closed form against the G00 slope
    bool any_rapid = false;       ///< the stencil holds a G00 cycle: the larger slope
    bool jerk_closed = true;      ///< closed-form jerk is checked (jerk-limited slope)
    bool jerk_fd = true;          ///< the jerk stencil holds jerk-limited cycles only
    double dv2 = 0.0, dv3 = 0.0;  ///< velocity steps in the a / j stencils [mm/s]
    double da3 = 0.0;             ///< acceleration steps in the j stencil [mm/s^2]
    bool velocity_only = false;   ///< a step without a formula is inside: v only
    /// The belt's share of the last four positions (NaN: not moving with it)
    /// and its acceleration in the closed form; null: no belt
    const std::array<double, 4>* belt = nullptr;
    double a_belt = 0.0;
  };
  void violate(Quantity q, Method m, std::size_t axis, double t, std::uint32_t line,
               std::uint16_t file, double value, double limit, bool joint = false);
  void check(Quantity q, Method m, std::size_t axis, const ipo::Cycle& c, double value,
             double limit, bool joint = false, double path = -1.0);
  /// The closed-form and finite-difference checks of one axis or joint (one helper for both).
  void check_motion(std::size_t i, bool joint, const Stencil& st, AxisAudit& aa,
                    std::array<double, 4>& history, const ipo::Cycle& c, double x, double v,
                    double a, double j);
  /// Counts and lists a documented step (Verdict::steps, step_kinds).
  void note_step(const Step& s);
  /// A path joint's documented steps against their formulas (axis cycles only).
  void step_formulas(const ipo::Joint& joint);
  /// One documented step of axis or joint i: listed, and a violation beyond `bound`.
  void formula_step(Quantity q, std::size_t i, const ipo::Joint& joint, double value, double bound,
                    bool is_joint);
  /// The same formulas on the joints' own steps (Joint::dq, dw).
  void joint_step_formulas(const ipo::Joint& joint);
  /// A switch of #TRAFO: the history of the side taken over continues the other's.
  void switch_transform(bool on);

  std::vector<planner::AxisLimits> limits_;
  double t_ = 0.001;
  Verdict verdict_;
  std::vector<std::array<double, 4>> x_;  ///< last positions per axis, x_[i][0] newest
  /// Step allowances of the last three cycles per axis: sum |dv|, sum |da|; [0] is this cycle.
  std::vector<std::array<double, 3>> dv_;
  std::vector<std::array<double, 3>> da_;
  std::array<bool, 3> jerk_limited_{true, true, true};
  /// A G00 block in each of the last three cycles: at the cycle's end, at the end of the cycle
  /// before (its block runs on into this one) or at a joint passed in it (item 6 of issue 36:
  /// the G00 before a stop ends inside the first cycle named after the G01).
  std::array<bool, 3> rapid_{false, false, false};
  bool last_rapid_ = false;   ///< the last cycle ended in a G00 block
  bool joint_rapid_ = false;  ///< a joint with a G00 block was passed since the last cycle
  double contour_ratio_ = 0.0;
  // Joints (set_joint_limits()): limits, last positions, the joints' step allowances of the
  // last three cycles (Joint::dq, dw; as dv_, da_), and whether they held a path step whose
  // joint steps are not known (a sync entry, or the inverse failed there: those stencils are
  // checked for velocity only).
  std::vector<planner::AxisLimits> joint_limits_;
  std::vector<std::array<double, 4>> q_;
  std::vector<std::array<double, 3>> qdv_;
  std::vector<std::array<double, 3>> qda_;
  std::array<bool, 3> stepped_{false, false, false};
  std::array<bool, 3> joint_jerk_limited_{true, true, true};
  bool joint_seen_ = false;       ///< an on_joint() without joint steps since on_joints()
  bool transformed_ = false;      ///< the last cycle ran under #TRAFO ON
  bool joints_are_axes_ = false;  ///< set_joint_limits(..., true)
  const std::array<axes::Setpoint, planner::kMaxAxes>* set_ = nullptr;  ///< set_setpoints()
  const tracking::BeltOffset* belt_ = nullptr;                          ///< set_belt()
  std::vector<std::array<double, 4>> b_;  ///< the belt's share per axis, b_[i][0] newest
};

/// Index of a documented step's quantity in Verdict::step_kinds (velojump 0, transvelmin 1,
/// c1_step 2).
inline std::size_t step_kind(Quantity q) noexcept {
  return q == Quantity::velojump ? 0 : q == Quantity::transvelmin ? 1 : 2;
}
/// Names and formulas of the documented step kinds, in Verdict::step_kinds order (reports).
inline constexpr std::array<const char*, 3> kStepKindNames = {"VELOJUMP", "#TRANSVELMIN", "C1"};
inline constexpr std::array<const char*, 3> kStepKindFormulas = {"C0 min(A+, |A-|) T",
                                                                 "v_min |dx'|", "j T"};

/// The name of a quantity in reports ("velocity", "c1-step", ...).
const char* quantity_name(Quantity q) noexcept;
/// The name of a checking method in reports ("closed form", "finite differences", ...).
const char* method_name(Method m) noexcept;

}  // namespace ncsim::audit
