#include "interp/trc.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "core/number_text.hpp"
#include "core/tolerance.hpp"

namespace ncsim::interp::trc {
namespace {

constexpr double kParallel = kRelTol;  // |sin| of a turn below this: the elements are tangent
/// |sin| of a turn and gap [mm] below which offset elements without an intersection still meet.
constexpr double kNearlyTangent = 1e-6;

Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
Vec2 operator*(Vec2 a, double s) {
  return {a.x * s, a.y * s};
}
double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
double norm(Vec2 a) {
  return std::hypot(a.x, a.y);
}
Vec2 unit(Vec2 a) {
  const double n = norm(a);
  return n > 0.0 ? a * (1.0 / n) : Vec2{1.0, 0.0};
}
Vec2 left(Vec2 a) {  // a turned by +90 degrees
  return {-a.y, a.x};
}
double radius_of(const Element& e) {
  return norm(e.start - e.centre);
}
double angle_pi(double a) {  // into (-pi, pi]
  while (a > std::numbers::pi)
    a -= 2.0 * std::numbers::pi;
  while (a <= -std::numbers::pi)
    a += 2.0 * std::numbers::pi;
  return a;
}
double angle_of(Vec2 v) {
  return std::atan2(v.y, v.x);
}

// Intersections of the elements taken whole (a line as its infinite line, an arc as its circle).
std::vector<Vec2> intersections(const Element& a, const Element& b) {
  std::vector<Vec2> out;
  if (!a.arc && !b.arc) {
    const Vec2 u = unit(a.end - a.start), v = unit(b.end - b.start);
    const double den = cross(u, v);
    if (std::fabs(den) < kParallel) return out;
    out.push_back(a.start + u * (cross(b.start - a.start, v) / den));
    return out;
  }
  if (a.arc != b.arc) {
    const Element& line = a.arc ? b : a;
    const Element& circle = a.arc ? a : b;
    const Vec2 u = unit(line.end - line.start);
    const Vec2 w = line.start - circle.centre;
    const double r = radius_of(circle);
    const double p = dot(u, w);
    const double disc = p * p - (dot(w, w) - r * r);
    if (disc < 0.0) return out;
    const double root = std::sqrt(disc);
    out.push_back(line.start + u * (-p - root));
    if (root > 0.0) out.push_back(line.start + u * (-p + root));
    return out;
  }
  const double r1 = radius_of(a), r2 = radius_of(b);
  const Vec2 dc = b.centre - a.centre;
  const double dist = norm(dc);
  if (dist < kSamePoint || dist > r1 + r2 || dist < std::fabs(r1 - r2)) return out;
  const double along = (dist * dist + r1 * r1 - r2 * r2) / (2.0 * dist);
  const double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
  const Vec2 e = dc * (1.0 / dist);
  const Vec2 m = a.centre + e * along;
  out.push_back(m + left(e) * h);
  if (h > 0.0) out.push_back(m - left(e) * h);
  return out;
}

Element line(Vec2 from, Vec2 to) {
  Element e;
  e.start = from;
  e.end = to;
  return e;
}

}  // namespace

Vec2 start_tangent(const Element& e) {
  if (!e.arc) return unit(e.end - e.start);
  const Vec2 radial = unit(e.start - e.centre);
  return e.ccw ? left(radial) : left(radial) * -1.0;
}

Vec2 end_tangent(const Element& e) {
  if (!e.arc) return unit(e.end - e.start);
  const Vec2 radial = unit(e.end - e.centre);
  return e.ccw ? left(radial) : left(radial) * -1.0;
}

std::optional<Element> offset(const Element& e, double d) {
  Element o = e;
  if (!e.arc) {
    const Vec2 n = left(unit(e.end - e.start)) * d;
    o.start = e.start + n;
    o.end = e.end + n;
    return o;
  }
  const double r = radius_of(e);
  const double r_new = e.ccw ? r - d : r + d;
  if (r_new <= kMinRadius) return std::nullopt;
  o.start = e.centre + (e.start - e.centre) * (r_new / r);
  o.end = e.centre + (e.end - e.centre) * (r_new / r);
  return o;
}

Join join(const Element& a, const Element& b, Vec2 corner, double d, TrcCorner mode,
          JoinError& error) {
  error = JoinError::none;
  Join j;
  const Vec2 ea = a.end, sb = b.start;
  const Vec2 ta = end_tangent(a), tb = start_tangent(b);
  const double turn = cross(ta, tb);  // > 0: the contour turns left
  const double along = dot(ta, tb);
  const Vec2 mid = (ea + sb) * 0.5;
  if (std::fabs(turn) < kParallel && along > 0.0) {  // tangent: the offset points meet
    j.a_end = j.b_start = mid;
    return j;
  }
  if (std::fabs(turn) >= kParallel && d * turn > 0.0) {  // inner: turns towards the tool
    const std::vector<Vec2> xs = intersections(a, b);
    if (xs.empty()) {
      if (std::fabs(turn) < kNearlyTangent && norm(ea - sb) < kNearlyTangent) {
        j.a_end = j.b_start = mid;
        return j;
      }
      error = JoinError::no_intersection;
      return j;
    }
    Vec2 best = xs.front();
    for (const Vec2& x : xs) {
      if (norm(x - corner) < norm(best - corner)) best = x;
    }
    j.a_end = j.b_start = best;
    return j;
  }
  // outer corner (a reversal too): bypassed with transition elements
  j.a_end = ea;
  j.b_start = sb;
  if (norm(ea - sb) < kSamePoint) return j;
  auto insert = [&j](Element e) {
    if (e.arc || norm(e.end - e.start) >= kSamePoint) j.inserted.push_back(e);
  };
  if (mode == TrcCorner::circle) {  // G26: a circle about the programmed corner
    Element arc;
    arc.arc = true;
    arc.start = ea;
    arc.end = sb;
    arc.centre = corner;
    arc.ccw = d < 0.0;  // tool on the left: the corner turns right, bypassed clockwise
    j.inserted.push_back(arc);
    return j;
  }
  const double r = std::fabs(d);
  if (along >= 0.0) {  // G25 up to 90 degrees of turn: the tangents meet
    const Vec2 q = ea + ta * (cross(sb - ea, tb) / cross(ta, tb));
    if (a.arc) {
      insert(line(ea, q));
    } else {
      j.a_end = q;
    }
    if (b.arc) {
      insert(line(q, sb));
    } else {
      j.b_start = q;
    }
    return j;
  }
  // G25 beyond 90 degrees: both tangents extended by the radius, then connected
  const Vec2 q1 = ea + ta * r, q2 = sb - tb * r;
  if (a.arc) {
    insert(line(ea, q1));
  } else {
    j.a_end = q1;
  }
  insert(line(q1, q2));
  if (b.arc) {
    insert(line(q2, sb));
  } else {
    j.b_start = q2;
  }
  return j;
}

bool keeps_direction(const Element& e, Vec2 start, Vec2 end) {
  if (!e.arc) return dot(end - start, unit(e.end - e.start)) >= -kSamePoint;
  const double dir = e.ccw ? 1.0 : -1.0;
  const double a0 = angle_of(e.start - e.centre), a1 = angle_of(e.end - e.centre);
  double sweep = e.full ? 2.0 * std::numbers::pi : dir * (a1 - a0);
  while (sweep <= 0.0)
    sweep += 2.0 * std::numbers::pi;
  const double u_start = angle_pi(dir * (angle_of(start - e.centre) - a0));
  const double u_end = sweep + angle_pi(dir * (angle_of(end - e.centre) - a1));
  return u_end - u_start >= -kRelTol;  // [rad]
}

namespace {

bool allowed_behind(const CommandBody& body) {
  return std::holds_alternative<Tech>(body) || std::holds_alternative<Dwell>(body) ||
         std::holds_alternative<Message>(body) || std::holds_alternative<ProgramStop>(body) ||
         std::holds_alternative<MachineData>(body);
}

std::string command_name(const CommandBody& body) {
  if (std::holds_alternative<Barrier>(body))
    return "a block that waits for run-time state (V.E. read, probe latch, actual position)";
  if (std::holds_alternative<SelectCs>(body)) return "#CS";
  if (std::holds_alternative<Kinematics>(body)) return "#KIN / #TRAFO";
  if (std::holds_alternative<SyncIn>(body) || std::holds_alternative<SyncOut>(body))
    return "#SYNC IN / OUT";
  if (std::holds_alternative<SplineBegin>(body) || std::holds_alternative<SplinePoint>(body) ||
      std::holds_alternative<SplineEnd>(body))
    return "a spline";
  if (std::holds_alternative<Flush>(body)) return "#FLUSH (a decoder stop)";
  if (std::holds_alternative<Homing>(body)) return "G74";
  if (std::holds_alternative<SetPosition>(body)) return "G92";
  if (std::holds_alternative<CaxTrack>(body)) return "#CAXTRACK";
  return "an INDP or MC_ axis command";
}

}  // namespace

bool Compensator::plane_of(const Motion& m, std::uint8_t& a1, std::uint8_t& a2) const {
  if (m.arc) {
    a1 = m.arc->axis_1;
    a2 = m.arc->axis_2;
    return true;
  }
  const int p1 = m.modal.plane == Plane::xy ? 0 : (m.modal.plane == Plane::zx ? 2 : 1);
  const int p2 = m.modal.plane == Plane::xy ? 1 : (m.modal.plane == Plane::zx ? 0 : 2);
  if (!xyz_[static_cast<std::size_t>(p1)] || !xyz_[static_cast<std::size_t>(p2)]) return false;
  a1 = *xyz_[static_cast<std::size_t>(p1)];
  a2 = *xyz_[static_cast<std::size_t>(p2)];
  return true;
}

Error Compensator::error_at(const Command& c, std::string id, std::string message) const {
  return Error{c.line, c.file, std::move(id), std::move(message)};
}

void Compensator::emit(const Command& pattern, const Element& e, std::uint32_t line,
                       CommandQueue& out, bool transition) const {
  Command c = pattern;
  c.line = line;
  Motion& m = std::get<Motion>(c.body);
  if (transition) {
    m.start = m.end = std::get<Motion>(pattern.body).start;  // the other axes stand still
    m.programmed = (AxisMask{1} << a1_) | (AxisMask{1} << a2_);
    m.block_time.reset();
    m.end_feed.reset();
    if (m.kind != MotionKind::rapid || e.arc) {
      m.kind = e.arc ? (e.ccw ? MotionKind::arc_ccw : MotionKind::arc_cw) : MotionKind::linear;
    }
  }
  m.start[a1_] = e.start.x;
  m.start[a2_] = e.start.y;
  m.end[a1_] = e.end.x;
  m.end[a2_] = e.end.y;
  if (e.arc) {
    const double r = radius_of(e);
    const bool full = e.full && norm(e.end - e.start) < kSamePoint;
    m.arc = Arc{e.centre.x, e.centre.y, a1_, a2_, r, full};
  } else {
    m.arc.reset();
  }
  out.push_back(std::move(c));
}

void Compensator::release(const Vec2& end, CommandQueue& out) {
  Held& h = *held_;
  Element e = h.offset;
  e.start = h.start;
  e.end = end;
  e.full = h.offset.full && norm(end - h.start) < kSamePoint;
  Motion& held = std::get<Motion>(h.command.body);
  if (e.arc && held.modal.trc.adapt_feed && held.kind != MotionKind::rapid) {
    // G11: the programmed feed acts on the contour (the tool's engagement point), so the centre
    // runs at F r_centre / r_contour; not on arcs below #TANGFEED RMIN (PROG-206473227,
    // PROG-207065483).
    const double r_contour = radius_of(h.programmed);
    if (r_contour >= held.modal.trc.tangfeed_rmin && r_contour > 0.0) {
      held.feed *= radius_of(e) / r_contour;
    }
  }
  emit(h.command, e, h.command.line, out, false);
  for (Command& c : behind_) {
    if (auto* m = std::get_if<Motion>(&c.body)) {  // a motion out of the plane: at the end
      m->start[a1_] = m->end[a1_] = end.x;
      m->start[a2_] = m->end[a2_] = end.y;
    }
    out.push_back(std::move(c));
  }
  behind_.clear();
}

void Compensator::finish(CommandQueue& out) {
  if (!held_) return;
  release(held_->offset.end, out);
  held_.reset();
}

std::optional<Error> Compensator::push(Command&& c, CommandQueue& out) {
  if (const auto* m = std::get_if<Motion>(&c.body)) {
    std::uint8_t a1 = 0, a2 = 0;
    const bool active = signed_offset(m->modal.trc) != 0.0;
    bool in_plane = false;
    if ((active || held_) && plane_of(*m, a1, a2)) {
      in_plane = m->arc.has_value() ||
                 std::hypot(m->end[a1] - m->start[a1], m->end[a2] - m->start[a2]) > kSamePoint;
    }
    if (!held_ && !(active && in_plane)) {
      out.push_back(std::move(c));
      return std::nullopt;
    }
    if (!in_plane) {  // a motion out of the plane (Z): runs where the compensated path is
      return hold_behind(std::move(c));
    }
    const Motion motion = *m;
    return plane_motion(std::move(c), motion, out);
  }
  if (!held_) {
    out.push_back(std::move(c));
    return std::nullopt;
  }
  if (std::holds_alternative<End>(c.body)) {
    finish(out);
    out.push_back(std::move(c));
    return std::nullopt;
  }
  if (!allowed_behind(c.body)) {
    return error_at(c, "NC4705",
                    "not supported: " + command_name(c.body) +
                        " while tool radius compensation is active (program G40 and a "
                        "deselection block before it)");
  }
  return hold_behind(std::move(c));
}

std::optional<Error> Compensator::hold_behind(Command c) {
  // 90011: the kernel's limit of blocks without a motion in the plane while compensating.
  if (behind_.size() >= kMaxHeldCommands) {
    return error_at(c, "90011",
                    "more than " + std::to_string(kMaxHeldCommands) +
                        " blocks without a motion in the TRC plane");
  }
  behind_.push_back(std::move(c));
  return std::nullopt;
}

std::optional<Error> Compensator::plane_motion(Command c, const Motion& m, CommandQueue& out) {
  std::uint8_t a1 = 0, a2 = 0;
  plane_of(m, a1, a2);
  Element pe;
  pe.start = {m.start[a1], m.start[a2]};
  pe.end = {m.end[a1], m.end[a2]};
  if (m.arc) {
    pe.arc = true;
    pe.centre = {m.arc->centre_1, m.arc->centre_2};
    pe.ccw = m.kind == MotionKind::arc_ccw;
    pe.full = m.arc->full_circle;
  }
  const double d = signed_offset(m.modal.trc);
  if (m.block_time && d != 0.0) {
    return error_at(c, "NC4704",
                    "not supported: G93 (block time) while tool radius compensation is active");
  }
  if (!held_) {
    a1_ = a1;
    a2_ = a2;
    return select(std::move(c), pe, m, pe.start, out);
  }
  Held& h = *held_;
  if (a1 != a1_ || a2 != a2_) {
    return error_at(c, "20133",
                    "plane selection not allowed during active tool radius compensation: the "
                    "deselection block must run in the plane of the compensated contour");
  }
  const bool deselection = d == 0.0;
  const bool change = !deselection && d != h.d;  // G41 <-> G42 or a new radius: off, then on
  const TrcApproach approach = m.modal.trc.approach;
  if (deselection && pe.arc && approach != TrcApproach::perpendicular) {
    return error_at(c, "NC4703",
                    "deselection of tool radius compensation within a circular motion block: "
                    "the first motion in the plane after G40 must be linear");
  }
  if (change && pe.arc) {
    return error_at(c, "NC4704",
                    "a change of the side (G41 <-> G42) or of the radius of tool radius "
                    "compensation within a circular motion block: it takes a linear block "
                    "(TF5200 \"Reaction on contour change\")");
  }
  const double d_b = deselection || change ? h.d : d;
  const std::optional<Element> b_off = offset(pe, d_b);
  if (!b_off) {
    const double r = radius_of(pe);
    return error_at(c, "90017",
                    "tool radius " + core::number_text(std::fabs(d_b)) +
                        " greater or equal to the contour radius " + core::number_text(r) +
                        ": the compensated circle would have radius " +
                        core::number_text(pe.ccw ? r - d_b : r + d_b));
  }
  Join j;
  const TrcApproach held_approach = std::get<Motion>(h.command.body).modal.trc.approach;
  const bool off = deselection || change;
  if (h.selection && (held_approach == TrcApproach::direct ||
                      held_approach == TrcApproach::no_block)) {  // G138 / G239: onto the path
    j.a_end = j.b_start = b_off->start;
  } else if (off && approach != TrcApproach::indirect) {
    // G138, G239: off the path from its perpendicular point; G237: and back to the contour
    j.a_end = j.b_start = h.offset.end;
    if (approach == TrcApproach::perpendicular) {
      j.inserted.push_back(Element{false, h.offset.end, h.programmed.end, {}, false, false});
      j.b_start = h.programmed.end;
    }
  } else {
    JoinError error = JoinError::none;
    j = join(h.offset, *b_off, pe.start, h.d, m.modal.trc.corner, error);
    if (error != JoinError::none) {
      return error_at(c, h.programmed.arc && pe.arc ? "90031" : "NC4702",
                      "the compensated elements of this block and the one before do not "
                      "intersect: tool radius " +
                          core::number_text(std::fabs(h.d)) + " too large for the inner corner");
    }
  }
  bool finite = std::isfinite(j.a_end.x + j.a_end.y + j.b_start.x + j.b_start.y);
  for (const Element& e : j.inserted)
    finite = finite && std::isfinite(e.start.x + e.start.y + e.end.x + e.end.y);
  if (!finite) {  // e.g. two lines meeting at an extremely small angle
    return error_at(c, "90134",
                    "the compensated end point is outside the permissible range (the offset "
                    "elements of this block and the one before meet too far away)");
  }
  if (!h.selection && !keeps_direction(h.offset, h.start, j.a_end)) {
    return error_at(h.command, "NC4701",
                    "contour violation: the compensated path of this block runs against its "
                    "programmed direction (TF5200 \"Limits of TRC\"); tool radius " +
                        core::number_text(std::fabs(h.d)) + " too large for its inner corners");
  }
  release(j.a_end, out);
  for (const Element& e : j.inserted)
    emit(c, e, c.line, out, true);
  held_.reset();
  if (change) return select(std::move(c), pe, m, j.b_start, out);
  if (deselection) {  // the departing block ends at its programmed end point
    Element e = pe;
    e.start = j.b_start;
    emit(c, e, c.line, out, false);
    return std::nullopt;
  }
  held_ = Held{std::move(c), pe, *b_off, j.b_start, d, false};
  return std::nullopt;
}

std::optional<Error> Compensator::select(Command c, const Element& pe, const Motion& m, Vec2 from,
                                         CommandQueue& out) {
  const double d = signed_offset(m.modal.trc);
  if (m.modal.trc.approach == TrcApproach::perpendicular) {
    // G237: a line square to the contour onto its offset start, then the element compensated;
    // any element may be the first (TF5200 "Perpendicular selection and deselection (G237)").
    const std::optional<Element> off = offset(pe, d);
    if (!off) {
      return error_at(c, "90017",
                      "tool radius " + core::number_text(std::fabs(d)) +
                          " greater or equal to the contour radius " +
                          core::number_text(radius_of(pe)));
    }
    emit(c, Element{false, from, off->start, {}, false, false}, c.line, out, true);
    held_ = Held{std::move(c), pe, *off, off->start, d, false};
    return std::nullopt;
  }
  // The selection block (TF5200 "Direct/indirect selection (G41/G42) of TRC").
  if (pe.arc) {
    return error_at(c, "90008",
                    "selection of tool radius compensation within a circular motion block: "
                    "the first motion in the plane after G41/G42 must be linear");
  }
  held_ = Held{std::move(c), pe, *offset(pe, d), from, d, true};
  return std::nullopt;
}

}  // namespace ncsim::interp::trc
