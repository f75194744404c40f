// Preparation: stops (G09, G60, G00 -> G01, end of stream), VELOJUMP links, tolerance-ball
// blends inserted between trimmed blocks, zero-length moves, and joined, bounded output.

#include "planner/prepare.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "planner/test_support.hpp"

namespace {

using namespace ncsim::planner;
using test::vec;

std::array<AxisLimits, 3> limits() {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = 1000.0;
  ax.a_max = ax.d_max = 10000.0;
  ax.j_max = 1e6;
  return {ax, ax, ax};
}

Move line(AxisVec a, AxisVec b, double feed = 100.0, std::uint32_t n = 1) {
  Move m;
  m.start = a;
  m.end = b;
  m.feed = feed;
  m.line = n;
  return m;
}

double gap(const AxisVec& a, const AxisVec& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

TEST_CASE("a 90 degree corner without contouring links at the VELOJUMP velocity") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  prep.push(line(vec(0, 0), vec(10, 0)), out);
  CHECK(out.empty());  // the joint needs the next block
  prep.push(line(vec(10, 0), vec(10, 10)), out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].v_end == doctest::Approx(10.0));
  CHECK(out[0].joint == TransitionClass::c0);
  CHECK(out[0].rule == LinkRule::velojump);
  CHECK(out[0].a_zero_at_end);
  prep.finish(out);
  REQUIRE(out.size() == 2);
  CHECK(out[1].v_end == 0.0);
  CHECK(out[1].stop == StopReason::end_of_stream);
}

TEST_CASE("a corner with a G00 block takes the slope in force in both blocks (P-AXIS-00004)") {
  // C0 = 1, T = 1 ms, 90 degrees: v = C0 min(A+, A-) T / |dx'| = A T (feed A 10000: 10 mm/s).
  // With a G00 slope a_grenz of 4000 on either side the link is 4 mm/s (issue 36, F1).
  auto ax = limits();
  for (AxisLimits& a : ax)
    a.a_rapid = 4000.0;
  for (const auto& [rapid_in, rapid_out] : {std::pair{true, true}, std::pair{false, true}}) {
    Preparer prep(ax, ChannelLimits{});
    std::vector<PreparedSegment> out;
    Move first = line(vec(0, 0), vec(10, 0));
    Move second = line(vec(10, 0), vec(10, 10), 100.0, 2);
    first.rapid = rapid_in;
    second.rapid = rapid_out;
    prep.push(first, out);
    prep.push(second, out);
    REQUIRE(out.size() == 1);
    CHECK(out[0].rule == LinkRule::velojump);
    CHECK(out[0].v_end == doctest::Approx(4.0));
  }
  // A G00 slope above the feed slope leaves the feed's at a feed-to-G00 joint.
  for (AxisLimits& a : ax)
    a.a_rapid = 20000.0;
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  Move second = line(vec(10, 0), vec(10, 10), 100.0, 2);
  second.rapid = true;
  prep.push(line(vec(0, 0), vec(10, 0)), out);
  prep.push(second, out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].v_end == doctest::Approx(10.0));
}

TEST_CASE("G09, G60 and G00 followed by G01 stop at the block end") {
  const auto ax = limits();
  for (int which = 0; which < 3; ++which) {
    Preparer prep(ax, ChannelLimits{});
    std::vector<PreparedSegment> out;
    Move first = line(vec(0, 0), vec(10, 0));
    if (which == 0) first.transition = Transition::stop_at_end;
    if (which == 1) first.exact_stop = true;
    if (which == 2) first.rapid = true;
    prep.push(first, out);
    prep.push(line(vec(10, 0), vec(20, 0)), out);
    REQUIRE(out.size() == 1);
    CHECK(out[0].v_end == 0.0);
    const StopReason expected[] = {StopReason::stop_at_end, StopReason::exact_stop,
                                   StopReason::rapid_to_feed};
    CHECK(out[0].stop == expected[which]);
  }
}

TEST_CASE("collinear blocks join as C2 at the smaller cap") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  prep.push(line(vec(0, 0), vec(10, 0), 100.0), out);
  prep.push(line(vec(10, 0), vec(20, 0), 60.0), out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].joint == TransitionClass::c2);
  CHECK(out[0].v_end == doctest::Approx(60.0));
  CHECK_FALSE(out[0].a_zero_at_end);
}

TEST_CASE("collinear blocks at one feed leave as one chain of two parts") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  prep.push(line(vec(0, 0), vec(10, 0), 100.0, 1), out);
  prep.push(line(vec(10, 0), vec(20, 0), 100.0, 2), out);
  CHECK(out.empty());  // held: a next block could join
  prep.finish(out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].path.parts() == 2);
  CHECK(out[0].path.length() == doctest::Approx(20.0));
  CHECK(out[0].path.line_at(5.0) == 1);
  CHECK(out[0].path.line_at(15.0) == 2);
  CHECK(out[0].stop == StopReason::end_of_stream);
  CHECK(out[0].path.at(12.0).x[0] == doctest::Approx(12.0));
}

TEST_CASE("a zero-length G09 block stops the joint before it") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  prep.push(line(vec(0, 0), vec(10, 0)), out);
  Move still = line(vec(10, 0), vec(10, 0));
  still.transition = Transition::stop_at_end;
  prep.push(still, out);
  prep.push(line(vec(10, 0), vec(20, 0)), out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].stop == StopReason::stop_at_end);
}

TEST_CASE("G261 inserts a blend between the trimmed blocks; every joint is C2") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  const AxisVec square[] = {vec(0, 0), vec(20, 0), vec(20, 20), vec(0, 20), vec(0, 0)};
  for (int k = 0; k < 4; ++k) {
    Move m = line(square[k], square[k + 1], 100.0, static_cast<std::uint32_t>(k + 1));
    m.contour = Contour::tolerance;
    m.path_dev = 1.0;
    prep.push(m, out);
  }
  prep.finish(out);
  // line, blend, line, blend, line, blend, line
  REQUIRE(out.size() == 7);
  double total = 0.0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    CHECK(out[k].blend == (k % 2 == 1));
    total += out[k].path.length();
    if (k + 1 < out.size()) {
      CHECK(gap(out[k].path.end(), out[k + 1].path.start()) < 1e-9);
      CHECK(out[k].joint == TransitionClass::c2);
      CHECK(out[k].v_end > 10.0);  // faster than the VELOJUMP corner
    }
  }
  CHECK(out[0].path.length() == doctest::Approx(19.0));
  CHECK(out[2].path.length() == doctest::Approx(18.0));
  CHECK(total < 80.0);
  CHECK(out[1].line == 1);
  CHECK(out.back().stop == StopReason::end_of_stream);
}

TEST_CASE("G261 with DIST trims PRE_DIST off the incoming block and POST_DIST off the next") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  const AxisVec square[] = {vec(0, 0), vec(20, 0), vec(20, 20), vec(0, 20)};
  for (int k = 0; k < 3; ++k) {
    Move m = line(square[k], square[k + 1], 100.0, static_cast<std::uint32_t>(k + 1));
    m.contour = Contour::distance;
    m.pre_dist = 2.0;
    m.post_dist = 0.5;
    prep.push(m, out);
  }
  prep.finish(out);
  // line, blend, line, blend, line
  REQUIRE(out.size() == 5);
  for (std::size_t k = 0; k < out.size(); ++k) {
    CHECK(out[k].blend == (k % 2 == 1));
    if (k + 1 < out.size()) {
      CHECK(gap(out[k].path.end(), out[k + 1].path.start()) < 1e-9);
      CHECK(out[k].joint == TransitionClass::c2);
    }
  }
  CHECK(gap(out[1].path.start(), vec(18, 0)) < 1e-9);    // PRE_DIST before (20, 0)
  CHECK(gap(out[1].path.end(), vec(20, 0.5)) < 1e-9);    // POST_DIST after it
  CHECK(out[2].path.length() == doctest::Approx(17.5));  // 20 - 0.5 - 2
  CHECK(out[4].path.length() == doctest::Approx(19.5));
}

TEST_CASE("property: random polylines give joined segments with bounded joint velocities") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto ax = limits();
  for (int run = 0; run < 20; ++run) {
    Preparer prep(ax, ChannelLimits{});
    std::vector<PreparedSegment> out;
    std::size_t emitted = 0;
    AxisVec p = vec(0, 0, 0);
    for (int k = 0; k < 200; ++k) {
      const AxisVec q = vec(p[0] + 5 * u(rng), p[1] + 5 * u(rng), p[2] + u(rng));
      Move m = line(p, q, 10 + 100 * std::abs(u(rng)));
      m.contour = run % 2 == 0 ? Contour::tolerance : Contour::none;
      m.path_dev = 0.01 + std::abs(u(rng));
      m.slope = SlopeType::trapez;
      prep.push(m, out);
      p = q;
      CHECK(out.size() <= 3);  // bounded: at most a block and a blend per push
      for (std::size_t i = 0; i + 1 < out.size(); ++i)
        CHECK(gap(out[i].path.end(), out[i + 1].path.start()) < 1e-9);
      for (const auto& s : out) {
        CHECK(s.v_end <= s.limits.v_max * (1 + 1e-12));
        CHECK(s.v_end >= 0.0);
      }
      emitted += out.size() > 0 ? out.size() - 1 : 0;
      if (out.size() > 1) out.erase(out.begin(), out.end() - 1);  // keep the last for joins
    }
    prep.finish(out);
    CHECK(out.back().v_end == 0.0);
    CHECK(emitted > 150);
  }
}

TEST_CASE("0.1 mm chords of a gentle curve leave as chains: the knees carry the acceleration") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  AxisVec p = vec(0, 0);
  double dir = 0.0;
  for (int k = 0; k < 200; ++k) {
    dir += 0.1 / 20.0;  // radius of curvature 20 mm
    const AxisVec q = vec(p[0] + 0.1 * std::cos(dir), p[1] + 0.1 * std::sin(dir));
    prep.push(line(p, q, 100.0, static_cast<std::uint32_t>(k + 1)), out);
    p = q;
  }
  prep.finish(out);
  REQUIRE(out.size() == 4);  // 200 chords in chains of at most Chain::kMaxParts
  std::size_t parts = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    parts += out[k].path.parts();
    if (k + 1 < out.size()) {
      CHECK(out[k].joint == TransitionClass::c0);
      CHECK(out[k].v_end == doctest::Approx(100.0));
    }
  }
  CHECK(parts == 200);
  CHECK(out[0].path.parts() == Chain::kMaxParts);
  CHECK(out[0].path.line_at(0.05) == 1);
  CHECK(out[0].path.line_at(0.15) == 2);
}

TEST_CASE("G261 leaves the small knees of dense chords unblended: they chain as without G261") {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  AxisVec p = vec(0, 0);
  double dir = 0.0;
  for (int k = 0; k < 100; ++k) {
    dir += 0.1 / 20.0;
    const AxisVec q = vec(p[0] + 0.1 * std::cos(dir), p[1] + 0.1 * std::sin(dir));
    Move m = line(p, q, 100.0, static_cast<std::uint32_t>(k + 1));
    m.contour = Contour::tolerance;
    m.path_dev = 0.01;
    prep.push(m, out);
    p = q;
  }
  // A 10 mm line on along the chords (its knee as small as theirs), then a 90 degree corner
  // with PATH_DEV 1: that corner is still blended. (A 0.01 mm ball there would be slower than
  // the corner's VELOJUMP link, and the corner would be kept: "G261 keeps a corner ...".)
  dir += 0.1 / 20.0;
  const AxisVec q = vec(p[0] + 10.0 * std::cos(dir), p[1] + 10.0 * std::sin(dir));
  Move m = line(p, q, 100.0, 101);
  m.contour = Contour::tolerance;
  m.path_dev = 1.0;
  prep.push(m, out);
  m = line(q, vec(q[0] - 10.0 * std::sin(dir), q[1] + 10.0 * std::cos(dir)), 100.0, 102);
  m.contour = Contour::tolerance;
  m.path_dev = 1.0;
  prep.push(m, out);
  prep.finish(out);
  std::size_t blends = 0;
  std::size_t parts = 0;
  for (const PreparedSegment& ps : out) {
    blends += ps.blend ? 1 : 0;
    parts += ps.path.parts();
  }
  CHECK(blends == 1);
  CHECK(parts == 103);  // 102 blocks and the one blend
  CHECK(out[0].path.parts() == Chain::kMaxParts);
}

/// The segments two 20 mm lines at 90 degrees leave as, the first with contour `c` and
/// PATH_DEV (DEV) or PRE_DIST = POST_DIST (DIST) `r`.
std::vector<PreparedSegment> right_angle(Contour c, double r) {
  const auto ax = limits();
  Preparer prep(ax, ChannelLimits{});
  std::vector<PreparedSegment> out;
  Move a = line(vec(0, 0), vec(20, 0), 100.0, 1);
  a.contour = c;
  a.path_dev = a.pre_dist = a.post_dist = r;
  prep.push(a, out);
  prep.push(line(vec(20, 0), vec(20, 20), 100.0, 2), out);
  prep.finish(out);
  return out;
}

TEST_CASE("G261 keeps a corner that VELOJUMP passes faster than its ball (issue 36)") {
  // A ball of 0.01 mm at a right angle is passed more slowly than the corner, which VELOJUMP
  // links at C0 a T = 10 mm/s (000 l.108). The corner is kept, planned exactly as under G260
  // (docs/planner.md "Tolerance balls", with TF5200 PROG-475164939): never slower than not
  // blending.
  const auto g260 = right_angle(Contour::none, 0.0);
  const auto kept = right_angle(Contour::tolerance, 0.01);
  REQUIRE(kept.size() == 2);
  REQUIRE(g260.size() == 2);
  CHECK_FALSE(kept[0].blend);
  CHECK(kept[0].joint == TransitionClass::c0);
  CHECK(kept[0].rule == LinkRule::velojump);
  CHECK(kept[0].v_end == g260[0].v_end);
  CHECK(kept[0].v_end == doctest::Approx(10.0));
  CHECK(kept[0].path.length() == doctest::Approx(20.0));
  // A ball of 1 mm passes the corner faster: it stays.
  const auto ball = right_angle(Contour::tolerance, 1.0);
  REQUIRE(ball.size() == 3);
  CHECK(ball[1].blend);
  CHECK(ball[0].v_end > 10.0);
  // DIST's distances are the curve the program asks for: its 0.01 mm curve stays.
  const auto dist = right_angle(Contour::distance, 0.01);
  REQUIRE(dist.size() == 3);
  CHECK(dist[1].blend);
  CHECK(dist[0].v_end < 10.0);
}

// NCSIM-CHAN-640 (docs/conveyor.md "The belt's own dynamics", 004 l.454)
TEST_CASE("a PCS1 block keeps the belt's dynamics reserve on the axes the belt moves, only there") {
  auto ax = limits();
  ax[0].j_max = 2e5;  // X the belt moves; Y the stiffer axis
  ChannelLimits channel;
  channel.belt_reserve = 0.01;
  // The path limits one block is prepared with.
  const auto prepared = [&ax](const ChannelLimits& ch, const Move& m) {
    Preparer prep(ax, ch);
    std::vector<PreparedSegment> out;
    prep.push(m, out);
    prep.finish(out);
    REQUIRE(out.size() == 1);
    return out[0].limits;
  };
  Move along_x = line(vec(0, 0), vec(100, 0), 500.0);
  along_x.slope = SlopeType::trapez;  // jerk-limited, as #SYNC IN forces (004 l.280)
  // Off the conveyor (Move::belt all 0) the reserve changes nothing.
  CHECK(prepared(channel, along_x).a_max == prepared(ChannelLimits{}, along_x).a_max);
  CHECK(prepared(channel, along_x).j_max == prepared(ChannelLimits{}, along_x).j_max);
  along_x.belt[0] = 110.0;  // in PCS1: the belt takes 110 mm/s of X
  const PathLimits p = prepared(ChannelLimits{}, along_x);
  const PathLimits r = prepared(channel, along_x);
  CHECK(r.v_max == p.v_max);  // the velocity split is the belt's velocity, not the reserve
  CHECK(r.a_max == doctest::Approx(0.99 * p.a_max));
  CHECK(r.d_max == doctest::Approx(0.99 * p.d_max));
  CHECK(r.j_max == doctest::Approx(0.99 * p.j_max));
  // A block along Y in PCS1: Y keeps its full dynamics (X does not move).
  Move along_y = line(vec(0, 0), vec(0, 100), 500.0);
  along_y.slope = SlopeType::trapez;
  along_y.belt[0] = 110.0;
  CHECK(prepared(channel, along_y).a_max == prepared(ChannelLimits{}, along_y).a_max);
  CHECK(prepared(channel, along_y).j_max == prepared(ChannelLimits{}, along_y).j_max);
}
