// Audit: it finds what is wrong (velocity, acceleration, jerk from the closed form and from
// finite differences, a VELOJUMP step above its formula, a point off the contour), with time
// and line; and passes a clean corner with its documented step listed apart.

#include "audit/audit.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "ipo/test_support.hpp"

namespace {

using namespace ncsim::audit;
using namespace ncsim::ipo;
using namespace ncsim::tracking;
using namespace ncsim::ipo::test;
namespace planner = ncsim::planner;

bool has(const Verdict& v, Quantity q, Method m) {
  for (const Violation& x : v.violations)
    if (x.quantity == q && x.method == m) return true;
  return false;
}

Cycle motion(std::uint64_t k, double t, const planner::Move* prog) {
  Cycle c;
  c.index = k;
  c.t = static_cast<double>(k) * t;
  c.line = prog ? prog->line : 0;
  c.programmed = prog;
  return c;
}

TEST_CASE("the audit reports a position stream that moves too fast, with time and line") {
  const std::vector<planner::AxisLimits> axes = {axis(10.0, 100.0, 1e4)};
  Audit audit(axes, 0.001, AxisVec{});
  planner::Move m = line(AxisVec{}, vec(1.0, 0.0), 10.0, 7);
  m.axis_count = 1;
  for (int k = 1; k <= 5; ++k) {
    Cycle c = motion(static_cast<std::uint64_t>(k), 0.001, &m);
    c.x[0] = 0.02 * k;  // 20 mm/s
    audit.on_cycle(c);
  }
  const Verdict& v = audit.verdict();
  CHECK_FALSE(v.ok());
  CHECK(has(v, Quantity::velocity, Method::finite_difference));
  CHECK(has(v, Quantity::acceleration, Method::finite_difference));  // the start from rest
  CHECK(v.violations.front().line == 7);
  CHECK(v.violations.front().t == doctest::Approx(0.001));
  CHECK(v.axes[0].v_diff == doctest::Approx(20.0));
}

TEST_CASE("the audit checks the closed-form values: A+ speeding up, A- slowing down, J") {
  std::vector<planner::AxisLimits> axes = {axis(100.0, 100.0, 1e4)};
  axes[0].d_max = 50.0;
  Audit audit(axes, 0.001, AxisVec{});
  Cycle c = motion(1, 0.001, nullptr);
  c.v[0] = 10.0;
  c.a[0] = -60.0;  // slowing down beyond A- = 50
  audit.on_cycle(c);
  CHECK(has(audit.verdict(), Quantity::acceleration, Method::closed_form));
  Audit audit2(axes, 0.001, AxisVec{});
  c.a[0] = 60.0;  // speeding up within A+ = 100
  c.j[0] = 2e4;   // beyond J
  audit2.on_cycle(c);
  CHECK_FALSE(has(audit2.verdict(), Quantity::acceleration, Method::closed_form));
  CHECK(has(audit2.verdict(), Quantity::jerk, Method::closed_form));
  Audit audit3(axes, 0.001, AxisVec{});
  c.jerk_limited = false;  // STEP slope: jerk not audited
  audit3.on_cycle(c);
  CHECK_FALSE(has(audit3.verdict(), Quantity::jerk, Method::closed_form));
}

TEST_CASE("a VELOJUMP step above C0 min(A+, A-) T is a violation; one within is listed apart") {
  const std::vector<planner::AxisLimits> axes = {axis(100.0, 10000.0, 1e5, 1.0),
                                                 axis(100.0, 10000.0, 1e5, 1.0)};
  Audit audit(axes, 0.001, AxisVec{});
  Joint j;
  j.cls = planner::TransitionClass::c0;
  j.v = 10.0;
  j.dv[0] = -10.0;
  j.dv[1] = 10.0;
  j.line = 4;
  audit.on_joint(j);
  CHECK(audit.verdict().ok());
  CHECK(audit.verdict().step_count == 2);
  CHECK(audit.verdict().steps[0].bound == doctest::Approx(10.0));
  j.dv[1] = 10.5;
  audit.on_joint(j);
  CHECK(has(audit.verdict(), Quantity::velojump, Method::formula));
  // Per kind: four VELOJUMP steps (two joints, two axes), the closest to its bound the 10.5.
  const StepKind& k = audit.verdict().step_kinds[step_kind(Quantity::velojump)];
  CHECK(k.count == 4);
  CHECK(k.closest.axis == 1);
  CHECK(k.closest.value == 10.5);
}

TEST_CASE("a VELOJUMP step at a joint with a G00 block is held to the slope of both blocks") {
  // P-AXIS-00004 a_grenz 4000 below the feed's 10000: C0 min(A+, A-) T = 4 mm/s (issue 36, F1).
  std::vector<planner::AxisLimits> axes = {axis(100.0, 10000.0, 1e5, 1.0)};
  axes[0].a_rapid = 4000.0;
  Joint j;
  j.cls = planner::TransitionClass::c0;
  j.v = 5.0;
  j.dv[0] = 5.0;
  Audit feed(axes, 0.001, AxisVec{});
  feed.on_joint(j);
  CHECK(feed.verdict().ok());  // within the feed's 10 mm/s
  for (const auto& [in, out] : {std::pair{true, false}, std::pair{false, true}}) {
    j.rapid_in = in;
    j.rapid_out = out;
    Audit audit(axes, 0.001, AxisVec{});
    audit.on_joint(j);
    CHECK(has(audit.verdict(), Quantity::velojump, Method::formula));
    CHECK(audit.verdict().steps[0].bound == doctest::Approx(4.0));
  }
}

TEST_CASE("a #TRANSVELMIN link is checked against v_min |dx'_i|, not VELOJUMP; beyond it fails") {
  // VELOJUMP allows 10 mm/s per axis (C0 = 1, A = 10000, T = 1 ms); #TRANSVELMIN 30 mm/s
  // raised the link of a 90 degree corner (|dx'_i| = 1) to 30 mm/s (isg-language.md 5.6).
  const std::vector<planner::AxisLimits> axes = {axis(100.0, 10000.0, 1e5, 1.0),
                                                 axis(100.0, 10000.0, 1e5, 1.0)};
  Audit audit(axes, 0.001, AxisVec{});
  Joint j;
  j.cls = planner::TransitionClass::c0;
  j.rule = planner::LinkRule::transvelmin;
  j.transvelmin = 30.0;
  j.v = 30.0;
  j.dv[0] = -30.0;
  j.dv[1] = 30.0;
  j.line = 6;
  audit.on_joint(j);
  CHECK(audit.verdict().ok());
  REQUIRE(audit.verdict().step_count == 2);
  CHECK(audit.verdict().steps[0].quantity == Quantity::transvelmin);
  CHECK(audit.verdict().steps[0].bound == doctest::Approx(30.0));
  CHECK(audit.verdict().steps[1].value == doctest::Approx(30.0));
  // A link faster than #TRANSVELMIN allowed is caught under that rule.
  j.v = 31.0;
  j.dv[0] = -31.0;
  j.dv[1] = 31.0;
  audit.on_joint(j);
  CHECK(has(audit.verdict(), Quantity::transvelmin, Method::formula));
  CHECK_FALSE(has(audit.verdict(), Quantity::velojump, Method::formula));
  CHECK(audit.verdict().violations.front().limit == doctest::Approx(30.0));
  CHECK(audit.verdict().violations.front().line == 6);
  // Without #TRANSVELMIN (or under G261: JointReport gives 0) it is a VELOJUMP violation.
  Audit plain(axes, 0.001, AxisVec{});
  j.rule = planner::LinkRule::velojump;
  j.transvelmin = 0.0;
  plain.on_joint(j);
  CHECK(has(plain.verdict(), Quantity::velojump, Method::formula));
}

TEST_CASE("a point off its programmed block beyond the tolerance is a contour violation") {
  const std::vector<planner::AxisLimits> axes = {axis(1e3, 1e6, 1e9), axis(1e3, 1e6, 1e9)};
  planner::Move m = line(AxisVec{}, vec(10.0, 0.0), 10.0, 3);
  m.axis_count = 2;
  Audit audit(axes, 0.001, AxisVec{});
  Cycle c = motion(1, 0.001, &m);
  c.x[0] = 0.001;
  c.x[1] = 0.001;  // 1 um off a block without tolerance ball
  audit.on_cycle(c);
  CHECK(has(audit.verdict(), Quantity::contour, Method::geometry));
  m.contour = planner::Contour::tolerance;
  m.path_dev = 0.01;
  Audit audit2(axes, 0.001, AxisVec{});
  audit2.on_cycle(c);
  CHECK(audit2.verdict().ok());
  CHECK(audit2.verdict().contour_max == doctest::Approx(0.001));
}

}  // namespace

namespace {

/// Runs `items` through the interpolator into `audit`.
void run_into(Audit& audit, const std::vector<planner::AxisLimits>& axes, std::vector<Item> items) {
  ListSource src(std::move(items));
  Config cfg;
  cfg.axes = axes;
  PathInterpolator ipo(cfg, src, &audit);
  while (ipo.step() == Status::running) {
  }
}

/// The C1 steps of `items` run and audited against `axes` (T = 1 ms); the run must be clean.
StepKind clean_c1_steps(const std::vector<planner::AxisLimits>& axes, std::vector<Item> items) {
  Audit audit(axes, 0.001, AxisVec{});
  run_into(audit, axes, std::move(items));
  CHECK(audit.verdict().ok());
  return audit.verdict().step_kinds[step_kind(Quantity::c1_step)];
}

TEST_CASE("a reversal at C0 = 1, A = 10000, T = 1 ms: link 5 mm/s, step 10 mm/s = the bound") {
  const std::vector<planner::AxisLimits> axes(3, axis(200.0, 10000.0, 1e5, 1.0));
  Audit audit(axes, 0.001, AxisVec{});
  run_into(audit, axes,
           {line(vec(0, 0), vec(50, 0), 100.0, 1), line(vec(50, 0), vec(0, 0), 100.0, 2)});
  const Verdict& v = audit.verdict();
  CHECK(v.ok());
  REQUIRE(v.step_count == 1);
  CHECK(v.steps[0].v_link == doctest::Approx(5.0).epsilon(1e-12));
  CHECK(v.steps[0].value == doctest::Approx(10.0).epsilon(1e-12));
  CHECK(v.steps[0].bound == doctest::Approx(10.0).epsilon(1e-12));
  CHECK(v.steps[0].line == 1);
}

/// The verdict on `moves` planned under `axes` and audited against half their jerk.
Verdict audited_with_half_jerk(const std::vector<planner::AxisLimits>& axes,
                               std::initializer_list<planner::Move> moves) {
  std::vector<planner::AxisLimits> half = axes;
  for (planner::AxisLimits& a : half)
    a.j_max *= 0.5;
  Audit strict(half, 0.001, AxisVec{});
  ListSource src(std::vector<Item>(moves.begin(), moves.end()));
  Config cfg;
  cfg.axes = axes;
  PathInterpolator ipo(cfg, src, &strict);
  while (ipo.step() == Status::running) {
  }
  return strict.verdict();
}

TEST_CASE("a line into a tangent arc R = 10 links at sqrt(J T R): its C1 step is j T, listed") {
  // docs/planner.md "C1" (P-CHAN-00009): the acceleration step v^2 |dx''_i| of each axis at
  // most j_i T. J = 1e5 mm/s^3, T = 1 ms, R = 10 mm: v_link = sqrt(1e5 * 1e-3 * 10) = 31.62
  // mm/s, Y's step v^2 / R = 100 mm/s^2 = j T. Audited against half the jerk it fails there.
  const std::vector<planner::AxisLimits> axes(3, axis(200.0, 10000.0, 1e5, 1.0));
  planner::Move in = line(vec(0, 0), vec(50, 0), 100.0, 1);
  planner::Move arc = line(vec(50, 0), vec(60, 10), 100.0, 2);
  arc.arc = planner::Arc{0, 1, 50.0, 10.0, false, false};  // G03, centre (50, 10)
  Audit audit(axes, 0.001, AxisVec{});
  run_into(audit, axes, {in, arc});
  const Verdict& v = audit.verdict();
  CHECK(v.ok());
  REQUIRE(v.step_count == 1);
  const Step& s = v.steps[0];
  CHECK(s.quantity == Quantity::c1_step);
  CHECK(s.axis == 1);
  CHECK(s.line == 1);
  CHECK(s.v_link == doctest::Approx(std::sqrt(1e5 * 1e-3 * 10.0)).epsilon(1e-9));
  CHECK(s.value == doctest::Approx(100.0).epsilon(1e-9));
  CHECK(s.bound == doctest::Approx(100.0).epsilon(1e-12));
  CHECK(v.step_kinds[step_kind(Quantity::c1_step)].count == 1);
  CHECK(v.step_kinds[step_kind(Quantity::c1_step)].closest.value == s.value);
  CHECK(v.step_kinds[step_kind(Quantity::velojump)].count == 0);
  CHECK(has(audited_with_half_jerk(axes, {in, arc}), Quantity::c1_step, Method::formula));
}

TEST_CASE("P-CHAN-00009 = 0: the C1 step is not reduced; it is listed against A+ + |A-|") {
  // corr_v_trans_jerk 0 (the manual's default, isg-language.md 7.1): the kernel passes a line
  // into a tangent arc at the segments' caps; the acceleration step is the channel's choice,
  // not held to j T, but listed with the only bound left, the acceleration limits on both
  // sides (issue 36 item 5: "every step the audit allows must be listed").
  const std::vector<planner::AxisLimits> axes(3, axis(200.0, 10000.0, 1e5, 1.0));
  planner::Move in = line(vec(0, 0), vec(50, 0), 100.0, 1);
  planner::Move arc = line(vec(50, 0), vec(60, 10), 100.0, 2);
  arc.arc = planner::Arc{0, 1, 50.0, 10.0, false, false};  // G03, centre (50, 10)
  Audit audit(axes, 0.001, AxisVec{});
  ListSource src({in, arc});
  Config cfg;
  cfg.axes = axes;
  cfg.channel.limit_c1_by_jerk = false;
  PathInterpolator ipo(cfg, src, &audit);
  double v_max_at_joint = 0.0;
  while (ipo.step() == Status::running)
    if (ipo.cycle().line == 2) v_max_at_joint = std::max(v_max_at_joint, ipo.cycle().path.v);
  const Verdict& v = audit.verdict();
  CHECK(v.ok());
  const StepKind& c1 = v.step_kinds[step_kind(Quantity::c1_step)];
  REQUIRE(c1.count >= 1);
  CHECK(c1.closest.bound == doctest::Approx(20000.0));
  CHECK(c1.closest.value > 1e5 * 1e-3 * 2.0);                  // far above j T
  CHECK(v_max_at_joint > 2.0 * std::sqrt(1e5 * 1e-3 * 10.0));  // not reduced to 31.6 mm/s
}

TEST_CASE("a knee into an arc: its acceleration step is held to j T like a C1 step, and audited") {
  // docs/planner.md "Corners" (session 31): the arc's centre 0.001 mm off the tangent, a knee
  // of 1e-4 rad. VELOJUMP alone would link at 100 mm/s (a Y acceleration step of v^2 / R =
  // 1000 mm/s^2 in one cycle: 10 x j T); the C1 rule at C0 joints links at sqrt(J T R).
  const std::vector<planner::AxisLimits> axes(3, axis(200.0, 10000.0, 1e5, 1.0));
  planner::Move in = line(vec(0, 0), vec(50, 0), 100.0, 1);
  planner::Move arc = line(vec(50, 0), vec(60.001, 10), 100.0, 2);
  arc.arc = planner::Arc{0, 1, 50.001, 10.0, false, false};  // G03, centre (50.001, 10)
  const StepKind c1 = clean_c1_steps(axes, {in, arc});
  REQUIRE(c1.count >= 1);
  CHECK(c1.closest.axis == 1);
  CHECK(c1.closest.v_link == doctest::Approx(std::sqrt(1e5 * 1e-3 * 10.0)).epsilon(1e-3));
  CHECK(c1.closest.value <= 100.0 * (1.0 + 1e-9));
  CHECK(c1.closest.value == doctest::Approx(100.0).epsilon(1e-3));
  // Audited against half the jerk, the same run's step is a violation (the audit bounds the
  // acceleration step at C0 joints too; before session 31 it passed unbounded).
  CHECK(has(audited_with_half_jerk(axes, {in, arc}), Quantity::c1_step, Method::formula));
}

TEST_CASE("a #TRANSVELMIN corner above VELOJUMP passes the audit, its steps listed apart") {
  // 90 degree corner: VELOJUMP gives 10 mm/s; #TRANSVELMIN 30 mm/s has priority (issue 12).
  const std::vector<planner::AxisLimits> axes(3, axis(200.0, 10000.0, 1e5, 1.0));
  planner::Move a = line(vec(0, 0), vec(40, 0), 100.0, 1);
  planner::Move b = line(vec(40, 0), vec(40, 40), 100.0, 2);
  a.transvelmin = 30.0;
  b.transvelmin = 30.0;
  Audit audit(axes, 0.001, AxisVec{});
  run_into(audit, axes, {a, b});
  const Verdict& v = audit.verdict();
  CHECK(v.ok());
  REQUIRE(v.step_count == 2);
  for (const Step& s : v.steps) {
    CHECK(s.quantity == Quantity::transvelmin);
    CHECK(s.v_link == doctest::Approx(30.0).epsilon(1e-12));
    CHECK(s.value == doctest::Approx(30.0).epsilon(1e-12));
    CHECK(s.bound == doctest::Approx(30.0).epsilon(1e-12));
    CHECK(s.line == 1);
  }
  // Audited against a lower #TRANSVELMIN than planned with, the corner fails under that rule.
  const std::vector<planner::AxisLimits> same = axes;
  class Lower final : public Sink {
   public:
    explicit Lower(Audit& a) : a_(a) {}
    void on_joint(const Joint& j) override {
      Joint k = j;
      k.transvelmin = 20.0;
      a_.on_joint(k);
    }
    void on_cycle(const Cycle& c) override { a_.on_cycle(c); }

   private:
    Audit& a_;
  };
  Audit strict(same, 0.001, AxisVec{});
  Lower lower(strict);
  ListSource src({a, b});
  Config cfg;
  cfg.axes = same;
  PathInterpolator ipo(cfg, src, &lower);
  while (ipo.step() == Status::running) {
  }
  CHECK(has(strict.verdict(), Quantity::transvelmin, Method::formula));
}

TEST_CASE("a #TRANSVELMIN knee into an arc keeps the jerk limitation (PROG-207486091)") {
  // Issue 36 item 5: a 30 degree knee into an R 1 arc under #TRANSVELMIN 100 mm/s. TF5200:
  // with a non-linear slope and P-CHAN-00009 "jerk limitation is prioritised": the link is at
  // most sqrt(j T / |dx''|) and the acceleration step is within j T (it was 14.6 x j T).
  const std::vector<planner::AxisLimits> axes(3, axis(500.0, 10000.0, 5e4, 1.0));
  // G03 from (50, 0), its start tangent at 30 degrees to X: centre (50 - sin 30, cos 30),
  // the start at -60 degrees from it, 1 rad of arc.
  const double cx = 50.0 - 0.5;
  const double cy = std::sqrt(0.75);
  const double phi = -M_PI / 3.0 + 1.0;
  planner::Move in = line(vec(0, 0), vec(50, 0), 100.0, 1);
  planner::Move arc = line(vec(50, 0), vec(cx + std::cos(phi), cy + std::sin(phi)), 100.0, 2);
  arc.arc = planner::Arc{0, 1, cx, cy, false, false};
  in.transvelmin = 100.0;
  const StepKind c1 = clean_c1_steps(axes, {in, arc});
  REQUIRE(c1.count >= 1);
  // Y's curvature jumps by cos 30 / R: v = sqrt(j T R / cos 30) = 7.60 mm/s, not 100.
  CHECK(c1.closest.v_link == doctest::Approx(std::sqrt(5e4 * 1e-3 / std::sqrt(0.75))));
  CHECK(c1.closest.value <= 5e4 * 1e-3 * (1.0 + 1e-9));
}

TEST_CASE("a real run audited against tighter limits than it was planned with fails") {
  const std::vector<planner::AxisLimits> planned(3, axis(100.0, 1000.0, 1e5));
  const std::vector<planner::AxisLimits> tighter(3, axis(100.0, 500.0, 1e5));
  Audit audit(tighter, 0.001, AxisVec{});
  run_into(audit, planned, {line(vec(0, 0), vec(80, 0), 90.0, 5)});
  const Verdict& v = audit.verdict();
  CHECK_FALSE(v.ok());
  CHECK(has(v, Quantity::acceleration, Method::closed_form));
  CHECK(has(v, Quantity::acceleration, Method::finite_difference));
  CHECK(v.violations.front().line == 5);
  CHECK(v.axes[0].a_closed > 500.0);
}

}  // namespace

TEST_CASE("G00 runs and is audited with its own slope P-AXIS-00004 / 00200, G01 with the feed's") {
  std::vector<planner::AxisLimits> axes = {axis(500.0, 1000.0, 1e5), axis(500.0, 1000.0, 1e5)};
  for (planner::AxisLimits& a : axes) {
    a.a_rapid = 3000.0;  // P-AXIS-00004: G00 speeds up 3x harder than feed motion
    a.j_rapid = 3e5;     // a_rapid / P-AXIS-00200 (10 ms)
  }
  planner::Move g00 = line(vec(0, 0), vec(200, 0), 0.0, 1);
  g00.axis_count = 2;
  g00.rapid = true;
  g00.slope = planner::SlopeType::trapez;
  planner::Move g01 = line(vec(200, 0), vec(200, 200), 400.0, 2);
  g01.axis_count = 2;
  g01.slope = planner::SlopeType::trapez;
  Config cfg;
  cfg.axes = axes;
  cfg.channel.t_cycle = 0.001;
  ListSource src({g00, g01});
  Audit audit(cfg.axes, cfg.channel.t_cycle, cfg.start);
  PathInterpolator ipo(cfg, src, &audit);
  double a_rapid = 0.0;
  double a_feed = 0.0;
  while (ipo.step() == Status::running) {
    const Cycle& c = ipo.cycle();
    (c.rapid ? a_rapid : a_feed) =
        std::max(c.rapid ? a_rapid : a_feed, std::max(std::abs(c.a[0]), std::abs(c.a[1])));
  }
  const Verdict& v = audit.verdict();
  CHECK(v.ok());
  CHECK(a_rapid > 1000.0 * 1.5);          // the G00 slope is used ...
  CHECK(a_rapid <= 3000.0 * (1 + 1e-9));  // ... and kept
  CHECK(a_feed <= 1000.0 * (1 + 1e-9));   // the feed block keeps the feed slope
  CHECK(v.axes[0].a_limit == 3000.0);     // the audit reports the larger allowed value
  // The feed slope alone would be broken by the G00 cycles: the audit would say so.
  for (planner::AxisLimits& a : axes)
    a.a_rapid = a.j_rapid = 0.0;
  Audit strict(axes, cfg.channel.t_cycle, cfg.start);
  ListSource again({g00, g01});
  PathInterpolator replay(cfg, again, &strict);
  while (replay.step() == Status::running) {
  }
  CHECK_FALSE(strict.verdict().ok());
}

// An axis moving with a belt that accelerates by itself (004 l.454).
TEST_CASE("an axis carried by an accelerating belt: the violation names its path share") {
  const std::vector<planner::AxisLimits> axes = {axis(100.0, 100.0, 1e6)};
  for (const double own : {0.0, 200.0}) {  // the path's own acceleration on top of the belt's
    CAPTURE(own);
    Audit audit(axes, 0.001, AxisVec{});
    std::array<ncsim::axes::Setpoint, planner::kMaxAxes> set{};
    BeltOffset belt;
    belt.following = true;
    belt.share[0] = 1.0;
    belt.acceleration = 300.0;  // the belt alone takes the axis beyond A = 100 mm/s^2
    audit.set_setpoints(&set);
    audit.set_belt(&belt);
    for (int k = 1; k <= 20; ++k) {
      const double t = 0.001 * k;
      belt.travel = 0.5 * 300.0 * t * t;
      set[0] = {belt.travel + 0.5 * own * t * t, (300.0 + own) * t, 300.0 + own, 0.0};
      audit.on_cycle(motion(static_cast<std::uint64_t>(k), 0.001, nullptr));
    }
    const Verdict& v = audit.verdict();
    REQUIRE_FALSE(v.ok());  // the axis did exceed its acceleration: a violation either way
    std::uint64_t split = 0;
    for (const Violation& x : v.violations) {
      CHECK(x.quantity == Quantity::acceleration);
      if (x.path < 0.0) continue;  // a stencil holding the start position (not with the belt)
      ++split;
      CHECK(x.value == doctest::Approx(300.0 + own).epsilon(1e-6));
      CHECK(x.path == doctest::Approx(own).epsilon(1e-6).scale(1.0));
    }
    CHECK(split >= 20 - 2);  // every cycle's closed form, the differences after the start
    CHECK(v.belt_count == (own == 0.0 ? split : 0));  // the belt's own only where the path kept A
  }
}

TEST_CASE("an axis not moving with the belt is not split") {
  const std::vector<planner::AxisLimits> axes = {axis(100.0, 100.0, 1e6)};
  Audit audit(axes, 0.001, AxisVec{});
  BeltOffset belt;  // following false: before #SYNC IN's catch-up, after the departure
  belt.share[0] = 1.0;
  audit.set_belt(&belt);
  for (int k = 1; k <= 5; ++k) {
    Cycle c = motion(static_cast<std::uint64_t>(k), 0.001, nullptr);
    c.x[0] = 0.5 * 300.0 * 1e-6 * k * k;
    audit.on_cycle(c);
  }
  REQUIRE_FALSE(audit.verdict().ok());
  for (const Violation& x : audit.verdict().violations)
    CHECK(x.path == -1.0);
  CHECK(audit.verdict().belt_count == 0);
}
