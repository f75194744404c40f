// audit/audit: limits and contour checks on the cycle stream (see the header).

#include "audit/audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "audit/contour.hpp"
#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::audit {

namespace {

constexpr double kStepNoise = 1e-8;       // [1] a joint's velocity step below this x v: rounding
constexpr double kPositionNoise = 1e-10;  // [mm] absolute rounding of a cycle position

}  // namespace

Audit::Audit(std::span<const planner::AxisLimits> axes, double t_cycle,
             const planner::AxisVec& start)
    : limits_(axes.begin(), axes.end()), t_(t_cycle) {
  if (limits_.empty() || limits_.size() > planner::kMaxAxes)
    throw std::invalid_argument("ipo audit: " + std::to_string(limits_.size()) + " axes");
  if (!(t_cycle > 0.0) || !std::isfinite(t_cycle))
    throw std::invalid_argument("ipo audit: cycle must be > 0, got " + core::human(t_cycle));
  verdict_.axes.resize(limits_.size());
  for (std::size_t i = 0; i < limits_.size(); ++i) {
    const planner::AxisLimits& l = limits_[i];
    AxisAudit& a = verdict_.axes[i];
    a.v_limit = std::min(l.v_max, l.v_reference);
    const planner::AxisLimits r = planner::rapid_limits(l);
    a.a_limit = std::max({l.a_max, l.d_max, r.a_max});  // G00 slope P-AXIS-00004 included
    a.j_limit = std::max(l.j_max, r.j_max);
  }
  x_.resize(limits_.size());
  for (std::size_t i = 0; i < limits_.size(); ++i)
    x_[i].fill(start[i]);
  dv_.assign(limits_.size(), {0.0, 0.0, 0.0});
  da_.assign(limits_.size(), {0.0, 0.0, 0.0});
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  b_.assign(limits_.size(), {kNone, kNone, kNone, kNone});
}

void Audit::violate(Quantity q, Method m, std::size_t axis, double t, std::uint32_t line,
                    std::uint16_t file, double value, double limit, bool joint) {
  ++verdict_.violation_count;
  if (verdict_.violations.size() < kMaxListed)
    verdict_.violations.push_back(
        Violation{q, m, static_cast<std::uint8_t>(axis), t, line, value, limit, joint, file});
}

void Audit::check(Quantity q, Method m, std::size_t axis, const ipo::Cycle& c, double value,
                  double limit, bool joint, double path) {
  if (value <= limit * (1.0 + kRelTol)) return;
  violate(q, m, axis, c.t, c.line, c.file, value, limit, joint);
  if (path < 0.0) return;
  if (verdict_.violations.size() == verdict_.violation_count)  // listed: the path share with it
    verdict_.violations.back().path = path;
  if (path <= limit * (1.0 + kRelTol)) ++verdict_.belt_count;  // the belt's own (004 l.454)
}

void Audit::on_joint(const ipo::Joint& jt) {
  joint_rapid_ = joint_rapid_ || jt.rapid_in || jt.rapid_out;
  // Under #TRAFO the steps are Cartesian: the joints' checks take over (on_joints()), with the
  // joints' own steps where the interpolator gave them. The state is the last cycle's: a switch
  // happens with the path standing, and the first cycle after it starts from rest, so it
  // passes no joint unless its segment is shorter than J T^3 / 6.
  if (!transformed_)
    step_formulas(jt);
  else if (jt.joint_steps && !joint_limits_.empty())
    joint_step_formulas(jt);
  else
    joint_seen_ = true;
}

void Audit::formula_step(Quantity q, std::size_t i, const ipo::Joint& jt, double value,
                         double bound, bool joint) {
  note_step(
      Step{q, static_cast<std::uint8_t>(i), jt.t, jt.line, jt.v, value, bound, jt.file, joint});
  if (!(value <= bound * (1.0 + kRelTol)))
    violate(q, Method::formula, i, jt.t, jt.line, jt.file, value, bound, joint);
}

void Audit::joint_step_formulas(const ipo::Joint& jt) {
  // The axes' formulas on the joints (docs/planner.md "Corners under a transform", where the
  // planner applies them): |dq_i| <= C0_i min(A+_i, |A-_i|) T at C0, |dw_i| <= j_i T at C0
  // and C1 on jerk-limited slopes; the planner's joint caps hold under #TRANSVELMIN too.
  for (std::size_t i = 0; i < joint_limits_.size(); ++i) {
    const planner::AxisLimits& l = joint_limits_[i];
    const double dq = std::abs(jt.dq[i]);
    const double dw = std::abs(jt.dw[i]);
    qdv_[i][0] += dq;
    qda_[i][0] += dw;
    if (dq > kRelRounding * std::max(1.0, jt.v))
      formula_step(Quantity::velojump, i, jt, dq, l.c0 * std::min(l.a_max, l.d_max) * t_, true);
    if (jt.cls != planner::TransitionClass::c2 && jt.jerk_limited && jt.c1_limited &&
        dw > kRelRounding * std::max(1.0, jt.v * jt.v))
      formula_step(Quantity::c1_step, i, jt, dw, l.j_max * t_, true);
  }
}

void Audit::note_step(const Step& s) {
  ++verdict_.step_count;
  if (verdict_.steps.size() < kMaxListed) verdict_.steps.push_back(s);
  StepKind& k = verdict_.step_kinds[step_kind(s.quantity)];
  // value / bound > closest's, without dividing (bounds are > 0 where steps are documented)
  if (k.count == 0 || s.value * k.closest.bound > k.closest.value * s.bound) k.closest = s;
  ++k.count;
}

void Audit::step_formulas(const ipo::Joint& jt) {
  for (std::size_t i = 0; i < limits_.size(); ++i) {
    // At a joint with a G00 block the slope in force in both blocks (P-AXIS-00004).
    const planner::AxisLimits l = planner::joint_slope(limits_[i], jt.rapid_in, jt.rapid_out);
    const double dv = std::abs(jt.dv[i]);
    const double da = std::abs(jt.da[i]);
    dv_[i][0] += dv;
    da_[i][0] += da;
    // VELOJUMP (000 l.108): |dv_i| <= C0_i min(A+_i, |A-_i|) T. #TRANSVELMIN (not under G261)
    // raises the link above it (isg-language.md 5.6: it has priority): the step is v |dx'_i|
    // with |dx'_i| = |dv_i| / v, allowed up to the programmed v_min: |dv_i| <= v_min |dx'_i|.
    const double velojump = l.c0 * std::min(l.a_max, l.d_max) * t_;
    const double raised =
        jt.transvelmin > 0.0 && jt.v > 0.0 && jt.cls == planner::TransitionClass::c0
            ? jt.transvelmin * (dv / jt.v)
            : 0.0;
    // A velocity step below 1e-8 v is the rounding of a C2 joint (a ball's G2 contact leaves
    // about 1e-10 v): not listed (it is far below any bound). Above, listed, also where the
    // planner's tangent tolerance (1e-6, corner.hpp) called the joint tangent (the checker
    // measured 1e-5 mm/s steps there, seed 2967).
    if (dv > kStepNoise * std::max(1.0, jt.v))
      formula_step(raised > velojump ? Quantity::transvelmin : Quantity::velojump, i, jt, dv,
                   std::max(raised, velojump), false);
    // C1 (P-CHAN-00009 semantics, docs/planner.md "Corners"): |da_i| <= j_i T, at C1 joints
    // and, since session 31, at C0 joints too (a knee into a curve: the curvature jump; a knee
    // that carries the acceleration: its own step and the curvature's), #TRANSVELMIN links
    // included (PROG-207486091: the jerk limitation is prioritised). With P-CHAN-00009 = 0 the
    // kernel does not reduce the velocity for it: the step is listed against the acceleration
    // limits alone, A+ + |A-| (the most a step between two cycles within them can be).
    if (jt.cls != planner::TransitionClass::c2 && jt.jerk_limited &&
        da > planner::kCurvatureFloor * std::max(1.0, jt.v * jt.v))
      formula_step(Quantity::c1_step, i, jt, da, jt.c1_limited ? l.j_max * t_ : l.a_max + l.d_max,
                   false);
  }
}

void Audit::check_motion(std::size_t i, bool joint, const Stencil& st, AxisAudit& aa,
                         std::array<double, 4>& x, const ipo::Cycle& c, double pos, double v_signed,
                         double a_signed, double j_signed) {
  const double t2 = t_ * t_;
  const double t3 = t2 * t_;
  // G00 is planned with its own slope (P-AXIS-00004 / 00200; planner::rapid_limits).
  const planner::AxisLimits fast = planner::rapid_limits(st.feed);
  const planner::AxisLimits& l = st.rapid ? fast : st.feed;
  // A finite-difference stencil that holds a G00 cycle is checked against the larger slope.
  const double a_fd = st.any_rapid ? std::max({st.feed.a_max, st.feed.d_max, fast.a_max})
                                   : std::max(st.feed.a_max, st.feed.d_max);
  const double j_fd = st.any_rapid ? std::max(st.feed.j_max, fast.j_max) : st.feed.j_max;
  // Closed form.
  const double v = std::abs(v_signed);
  const double a = std::abs(a_signed);
  const double j = std::abs(j_signed);
  aa.v_closed = std::max(aa.v_closed, v);
  aa.a_closed = std::max(aa.a_closed, a);
  check(Quantity::velocity, Method::closed_form, i, c, v, aa.v_limit, joint);
  const bool speeding_up = a_signed * v_signed >= 0.0;
  // The path's share of the acceleration (the setpoint's less the belt's).
  const bool belt_now = st.belt != nullptr && std::isfinite((*st.belt)[0]);
  check(Quantity::acceleration, Method::closed_form, i, c, a, speeding_up ? l.a_max : l.d_max,
        joint, belt_now ? std::abs(a_signed - st.a_belt) : -1.0);
  if (st.jerk_closed) {
    ++aa.jerk_cycles;
    aa.j_closed = std::max(aa.j_closed, j);
    check(Quantity::jerk, Method::closed_form, i, c, j, l.j_max, joint);
  }
  // Finite differences of the positions.
  x = {pos, x[0], x[1], x[2]};
  const double mag = std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2]), std::abs(x[3])});
  const double noise = kPositionNoise + 4.0 * kMachineEpsilon * mag;
  const double vd = std::abs(x[0] - x[1]) / t_;
  const double ad = std::abs(x[0] - 2.0 * x[1] + x[2]) / t2;
  const double jd = std::abs(x[0] - 3.0 * x[1] + 3.0 * x[2] - x[3]) / t3;
  aa.v_diff = std::max(aa.v_diff, vd);
  check(Quantity::velocity, Method::finite_difference, i, c, vd, aa.v_limit + 2.0 * noise / t_,
        joint);
  if (st.velocity_only) return;
  // The same differences of the positions less the belt's share, where the axis
  // moved with the belt at every position of the stencil (else -1: not split).
  std::array<double, 4> p{-1.0, -1.0, -1.0, -1.0};
  if (st.belt != nullptr) {
    const std::array<double, 4>& b = *st.belt;
    for (std::size_t k = 0; k < 4; ++k)
      p[k] = x[k] - b[k];  // NaN where the axis did not move with the belt
  }
  const auto split = [](double d) { return std::isfinite(d) ? std::abs(d) : -1.0; };
  const double ap = st.belt ? split((p[0] - 2.0 * p[1] + p[2]) / t2) : -1.0;
  const double jp = st.belt ? split((p[0] - 3.0 * p[1] + 3.0 * p[2] - p[3]) / t3) : -1.0;
  if (st.dv2 == 0.0) aa.a_diff = std::max(aa.a_diff, ad);
  check(Quantity::acceleration, Method::finite_difference, i, c, ad,
        a_fd + st.dv2 / t_ + 4.0 * noise / t2, joint, ap);
  if (st.jerk_fd) {
    if (st.dv3 == 0.0 && st.da3 == 0.0) aa.j_diff = std::max(aa.j_diff, jd);
    check(Quantity::jerk, Method::finite_difference, i, c, jd,
          j_fd + st.da3 / t_ + st.dv3 / t2 + 8.0 * noise / t3, joint, jp);
  }
}

void Audit::switch_transform(bool on) {
  transformed_ = on;
  if (!joints_are_axes_) return;  // joints apart from the axes (a bare interpolator)
  if (on)
    q_ = x_;
  else
    x_ = q_;
}

void Audit::on_cycle(const ipo::Cycle& c) {
  ++verdict_.cycles;
  const bool trafo = ipo::transformed(c, transformed_);
  if (trafo != transformed_) switch_transform(trafo);
  jerk_limited_[0] = c.interval_jerk_limited;
  rapid_[0] = c.rapid || last_rapid_ || joint_rapid_;
  last_rapid_ = c.rapid;
  joint_rapid_ = false;
  const bool any_rapid = rapid_[0] || rapid_[1] || rapid_[2];
  for (std::size_t i = 0; i < limits_.size() && !trafo; ++i) {
    // An INDP motion (Cycle::independent) keeps the axis's G01 limits, jerk-limited.
    const bool indp = ((c.independent >> i) & 1u) != 0;
    // The belt's share of this axis (NaN when it does not move with the belt).
    const bool belt = belt_ != nullptr && belt_->following && !indp;
    b_[i] = {belt ? belt_->share[i] * belt_->travel : std::numeric_limits<double>::quiet_NaN(),
             b_[i][0], b_[i][1], b_[i][2]};
    Stencil st;
    st.feed = limits_[i];
    st.rapid = c.rapid && !indp;
    st.any_rapid = any_rapid;
    st.jerk_closed = c.jerk_limited || indp;
    st.jerk_fd = jerk_limited_[0] && jerk_limited_[1] && jerk_limited_[2];
    st.dv2 = dv_[i][0] + dv_[i][1];
    st.dv3 = st.dv2 + dv_[i][2];
    st.da3 = da_[i][0] + da_[i][1] + da_[i][2];
    if (belt_ != nullptr) {
      st.belt = &b_[i];
      st.a_belt = belt ? belt_->share[i] * belt_->acceleration : 0.0;
    }
    if (set_ != nullptr) {
      const axes::Setpoint& sp = (*set_)[i];
      check_motion(i, false, st, verdict_.axes[i], x_[i], c, sp.p, sp.v, sp.a, sp.j);
    } else {
      check_motion(i, false, st, verdict_.axes[i], x_[i], c, c.x[i], c.v[i], c.a[i], c.j[i]);
    }
  }
  if (trafo)  // the belt's share of the axes starts afresh after #TRAFO OFF
    for (auto& b : b_)
      b.fill(std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < limits_.size(); ++i) {
    dv_[i] = {0.0, dv_[i][0], dv_[i][1]};
    da_[i] = {0.0, da_[i][0], da_[i][1]};
  }
  jerk_limited_ = {true, jerk_limited_[0], jerk_limited_[1]};
  rapid_ = {false, rapid_[0], rapid_[1]};
  // Contour (under #TRAFO the TCP against the Cartesian block).
  if (c.activity == ipo::Activity::motion && c.programmed) {
    const planner::Move& m = *c.programmed;
    double mag = 1.0;
    for (std::size_t i = 0; i < limits_.size(); ++i)
      mag = std::max(mag, std::abs(c.x[i]));
    // DEV: PATH_DEV; DIST: max(PRE_DIST, POST_DIST), the ball its curve provably stays in
    // (planner::contour_bound, docs/planner.md "DIST").
    const double tol = planner::contour_bound(m);
    const double allowed = tol + kRelTol * mag;
    planner::AxisVec x = c.x;  // INDP axes are not part of the block's contour
    for (std::size_t i = 0; i < limits_.size(); ++i)
      if (((c.independent >> i) & 1u) != 0) x[i] = m.start[i];
    const double d = contour_distance(m, x);
    verdict_.contour_max = std::max(verdict_.contour_max, d);
    if (d / allowed > contour_ratio_) {
      contour_ratio_ = d / allowed;
      verdict_.contour_tolerance = tol;
    }
    if (!(d <= allowed))
      violate(Quantity::contour, Method::geometry, 0, c.t, c.line, c.file, d, allowed);
  }
}

void Audit::set_joint_limits(std::span<const planner::AxisLimits> joints,
                             const planner::AxisVec& start, bool joints_are_axes) {
  if (joints.empty() || joints.size() > planner::kMaxAxes)
    throw std::invalid_argument("ipo audit: " + std::to_string(joints.size()) + " joints");
  if (joints_are_axes && joints.size() != limits_.size())
    throw std::invalid_argument("ipo audit: " + std::to_string(joints.size()) +
                                " joints are not the " + std::to_string(limits_.size()) + " axes");
  joints_are_axes_ = joints_are_axes;
  planner::validate(joints);
  joint_limits_.assign(joints.begin(), joints.end());
  verdict_.joints.assign(joints.size(), AxisAudit{});
  q_.resize(joints.size());
  qdv_.assign(joints.size(), {0.0, 0.0, 0.0});
  qda_.assign(joints.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const planner::AxisLimits& l = joints[i];
    verdict_.joints[i].v_limit = std::min(l.v_max, l.v_reference);
    verdict_.joints[i].a_limit = std::max(l.a_max, l.d_max);
    verdict_.joints[i].j_limit = l.j_max;
    q_[i].fill(start[i]);
  }
}

void Audit::on_joints(const ipo::Cycle& c, const ipo::JointSetpoint& s) {
  if (joint_limits_.empty()) return;
  stepped_[0] = joint_seen_;
  joint_seen_ = false;
  joint_jerk_limited_[0] = c.interval_jerk_limited;
  const bool clean = !stepped_[0] && !stepped_[1] && !stepped_[2];
  for (std::size_t i = 0; i < joint_limits_.size(); ++i) {
    // The joints are planned with their feed slope, G00 included (docs/planner.md
    // "Kinematics"), and a joint has no step formula: a stencil with a path step is v only.
    Stencil st;
    st.feed = joint_limits_[i];
    st.jerk_closed = c.jerk_limited;
    st.jerk_fd = joint_jerk_limited_[0] && joint_jerk_limited_[1] && joint_jerk_limited_[2];
    st.velocity_only = !clean;
    st.dv2 = qdv_[i][0] + qdv_[i][1];
    st.dv3 = st.dv2 + qdv_[i][2];
    st.da3 = qda_[i][0] + qda_[i][1] + qda_[i][2];
    check_motion(i, true, st, verdict_.joints[i], q_[i], c, s.q[i], s.v[i], s.a[i], s.j[i]);
    qdv_[i] = {0.0, qdv_[i][0], qdv_[i][1]};
    qda_[i] = {0.0, qda_[i][0], qda_[i][1]};
  }
  stepped_ = {false, stepped_[0], stepped_[1]};
  joint_jerk_limited_ = {true, joint_jerk_limited_[0], joint_jerk_limited_[1]};
}

const char* quantity_name(Quantity q) noexcept {
  switch (q) {
    case Quantity::velocity:
      return "velocity";
    case Quantity::acceleration:
      return "acceleration";
    case Quantity::jerk:
      return "jerk";
    case Quantity::contour:
      return "contour";
    case Quantity::velojump:
      return "velojump";
    case Quantity::transvelmin:
      return "transvelmin";
    case Quantity::c1_step:
      return "c1-step";
  }
  return "?";
}

const char* method_name(Method m) noexcept {
  switch (m) {
    case Method::closed_form:
      return "closed form";
    case Method::finite_difference:
      return "finite differences";
    case Method::geometry:
      return "geometry";
    case Method::formula:
      return "formula";
  }
  return "?";
}

}  // namespace ncsim::audit
