#include "interp/trace.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/number_text.hpp"
#include "interp/cs_select.hpp"

namespace ncsim::interp {
namespace {

/// A trace number: fixed with 4 decimals, never "-0.0000".
void num(std::string& out, double v) {
  out += core::decimals_text(v, 4);
}

void field(std::string& out, std::string_view name, double v) {
  out += ' ';
  out += name;
  out += '=';
  num(out, v);
}

void axes(std::string& out, const AxisValues& values, const machines::Machine& m) {
  for (std::size_t i = 0; i < m.axes.size() && i < kMaxAxes; ++i) {
    if (m.axes[i].kind == machines::AxisKind::spindle) continue;
    field(out, m.axes[i].name, values[i]);
  }
}

std::string_view axis_name(const machines::Machine& m, std::uint8_t i) {
  return i < m.axes.size() ? std::string_view(m.axes[i].name) : std::string_view("?");
}

void modal(std::string& out, const ModalSnapshot& s) {
  if (s.exact_stop) out += " G60";
  if (s.contouring) out += " G261";
  if (s.transition == Transition::stop_at_end) out += " G09";
  if (s.transition == Transition::decel_at_end) out += " G900";
  if (s.transition == Transition::decel_after_end) out += " G901";
  if (s.synchronised) out += " SYNC";
  if (s.cs_active) out += " CS";
  if (s.kinematics_on) out += " TRAFO";
  if (s.caxtrack) out += " CAXTRACK";
}

}  // namespace

std::pair<std::array<double, 2>, std::array<double, 2>> arc_extent(const Motion& m) {
  const Arc& a = *m.arc;
  const double s1 = m.start[a.axis_1] - a.centre_1, s2 = m.start[a.axis_2] - a.centre_2;
  const double e1 = m.end[a.axis_1] - a.centre_1, e2 = m.end[a.axis_2] - a.centre_2;
  std::array<double, 2> lo{std::min(s1, e1), std::min(s2, e2)};
  std::array<double, 2> hi{std::max(s1, e1), std::max(s2, e2)};
  // Angles counter-clockwise in the (axis_1, axis_2) plane, as the centre was built.
  constexpr double kTwoPi = 6.283185307179586;
  const bool ccw = m.kind == MotionKind::arc_ccw;
  const double a0 = std::atan2(s2, s1);
  // The angle start -> end from the cross and dot products with the chord (as the planner's
  // Segment::arc): a tiny sweep on a huge radius stays tiny (issue 34 item 4).
  const double r = a.radius;
  const double d1 = m.end[a.axis_1] - m.start[a.axis_1], d2 = m.end[a.axis_2] - m.start[a.axis_2];
  const double rs = std::hypot(s1, s2);
  double sweep = 0.0;
  if (rs > 0.0) sweep = std::atan2((s1 * d2 - s2 * d1) / rs, rs + (s1 * d1 + s2 * d2) / rs);
  if (ccw && sweep <= 0.0) sweep += kTwoPi;
  if (!ccw && sweep >= 0.0) sweep -= kTwoPi;
  if (a.full_circle) sweep = ccw ? kTwoPi : -kTwoPi;
  for (int q = 0; q < 4; ++q) {  // the axis directions at 0, 90, 180, 270 degrees
    const double angle = q * kTwoPi / 4.0;
    double d = std::remainder(angle - a0, kTwoPi);  // in (-pi, pi]
    if (ccw && d < 0.0) d += kTwoPi;
    if (!ccw && d > 0.0) d -= kTwoPi;
    if (std::fabs(d) > std::fabs(sweep)) continue;
    const double p1 = q == 0 ? r : (q == 2 ? -r : 0.0);
    const double p2 = q == 1 ? r : (q == 3 ? -r : 0.0);
    lo = {std::min(lo[0], p1), std::min(lo[1], p2)};
    hi = {std::max(hi[0], p1), std::max(hi[1], p2)};
  }
  return {{lo[0] + a.centre_1, lo[1] + a.centre_2}, {hi[0] + a.centre_1, hi[1] + a.centre_2}};
}

namespace {

void put(std::string& out, const Motion& b, const machines::Machine& m) {
  static constexpr const char* kNames[] = {"G00", "G01", "G02", "G03"};
  out += ' ';
  out += kNames[static_cast<int>(b.kind)];
  axes(out, b.end, m);
  if (b.kind != MotionKind::rapid) field(out, "F", b.feed);
  if (b.block_time) field(out, "TIME", *b.block_time);
  if (b.end_feed) field(out, "E", *b.end_feed);
  if (b.arc) {
    out += " centre";
    field(out, axis_name(m, b.arc->axis_1), b.arc->centre_1);
    field(out, axis_name(m, b.arc->axis_2), b.arc->centre_2);
    field(out, "R", b.arc->radius);
    if (b.arc->full_circle) out += " FULL";
  }
  modal(out, b.modal);
  out += " frame=" + frame_name(b.frame) + " start";
  axes(out, b.start, m);
}

void put(std::string& out, const SplineBegin& b, const machines::Machine& m) {
  out += b.type == SplineType::akima ? " SPLINE_BEGIN AKIMA" : " SPLINE_BEGIN BSPLINE";
  out += " frame=" + frame_name(b.frame) + " start";
  axes(out, b.start, m);
}

void put(std::string& out, const SplinePoint& b, const machines::Machine& m) {
  out += " SPLINE_POINT " + std::to_string(b.index);
  axes(out, b.point, m);
  field(out, "F", b.feed);
  out += " frame=" + frame_name(b.frame);
}

void put(std::string& out, const SplineEnd& b, const machines::Machine& /*m*/) {
  out += b.type == SplineType::akima ? " SPLINE_END AKIMA" : " SPLINE_END BSPLINE";
  out += " points=" + std::to_string(b.points);
}

void put(std::string& out, const Dwell& b, const machines::Machine& /*m*/) {
  out += b.tech ? " TECH-WAIT" : " DWELL";
  field(out, "t", b.seconds);
  if (b.since_output) out += " since=output";
}

void put(std::string& out, const Tech& b, const machines::Machine& /*m*/) {
  static constexpr const char* kNames[] = {"M", "H", "S", "T", "D"};
  out += " TECH ";
  out += kNames[static_cast<int>(b.kind)];
  out += '=';
  num(out, b.value);
  if (b.extra) field(out, "value", *b.extra);
  if (b.sync != machines::TechSync::mos) {  // the default is not shown
    static constexpr const char* kSync[] = {"NO_SYNCH", "MOS", "MVS_SVS", "MVS_SNS", "MNS_SNS"};
    out += " sync=";
    out += kSync[static_cast<int>(b.sync)];
  }
}

void put(std::string& out, const ProgramStop& b, const machines::Machine& /*m*/) {
  out += b.optional ? " STOP M01" : " STOP M00";
}

void put(std::string& out, const AxisCommand& b, const machines::Machine& m) {
  out += b.kind == IndpKind::syn ? " INDP_SYN " : " INDP_ASYN ";
  out += axis_name(m, b.axis);
  out += b.rapid ? " G00" : " G01";
  field(out, "POS", b.target);
  if (b.feed) field(out, "FEED", *b.feed);
  if (b.time) field(out, "TIME", *b.time);
  if (b.interruptible) out += " INTERRUPTIBLE";
  out += " frame=" + frame_name(b.frame);
}

void put(std::string& out, const MoveVelocity& b, const machines::Machine& m) {
  out += " MC_MOVEVELOCITY ";
  out += axis_name(m, b.axis);
  field(out, "v", b.velocity);
  field(out, "a", b.acceleration);
  field(out, "d", b.deceleration);
  field(out, "j", b.jerk);
  static constexpr const char* kDirections[] = {"1", "3", "4"};  // MC_Direction codes
  out += " dir=";
  out += kDirections[static_cast<int>(b.direction)];
}

void put(std::string& out, const ProbeArm& b, const machines::Machine& m) {
  out += " PROBE_ARM ";
  out += axis_name(m, b.axis);
  out += " channel=" + std::to_string(b.channel);
  if (b.edge) out += *b.edge == ProbeEdge::falling ? " mode=1" : " mode=2";
}

void put(std::string& out, const SyncIn& b, const machines::Machine& m) {
  out += " SYNC_IN ";
  out += axis_name(m, b.conveyor);
  field(out, "conv_vel", b.conv_vel);
  field(out, "latch", b.latch);
  if (b.feed_cont) field(out, "FEED_CONT", *b.feed_cont);
  if (b.feed_cont_auto) out += " FEED_CONT_AUTO";
}

void put(std::string& out, const SyncOut& b, const machines::Machine& /*m*/) {
  out += " SYNC_OUT";
  if (b.feed_cont) field(out, "FEED_CONT", *b.feed_cont);
  if (b.feed_cont_auto) out += " FEED_CONT_AUTO";
}

void put(std::string& out, const SelectCs& b, const machines::Machine& /*m*/) {
  static constexpr const char* kOps[] = {"DEF", "ON", "OFF", "OFF_ALL", "BASE"};
  out += " CS ";
  out += kOps[static_cast<int>(b.op)];
  if (b.id) out += " id=" + std::to_string(*b.id);
  if (b.values) {
    out += " [";
    for (std::size_t k = 0; k < 6; ++k) {
      if (k != 0) out += ',';
      num(out, (*b.values)[k]);
    }
    out += ']';
  }
  if (b.op == CsOp::base || b.base != std::array<double, 3>{}) {
    out += " base=[";
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != 0) out += ',';
      num(out, b.base[k]);
    }
    out += ']';
  }
  out += " active=" + std::to_string(b.active_count);
}

void put(std::string& out, const Kinematics& b, const machines::Machine& /*m*/) {
  out += " KIN";
  if (b.kin_id) out += " id=" + std::to_string(*b.kin_id);
  out += b.trafo_on ? " TRAFO_ON" : " TRAFO_OFF";
}

void put(std::string& out, const CaxTrack& b, const machines::Machine& m) {
  out += b.on ? " CAXTRACK_ON" : " CAXTRACK_OFF";
  if (b.axis) {
    out += " AX=";
    out += axis_name(m, *b.axis);
  }
  field(out, "ANGLIMIT", b.anglimit);
  field(out, "OFFSET", b.offset);
  if (!b.on) field(out, "ANGPOS", b.angpos);
}

void put(std::string& out, const MachineData& b, const machines::Machine& m) {
  out += " MACHINE_DATA";
  if (b.syn) out += " SYN";
  if (b.axis) {
    out += " AX=";
    out += axis_name(m, *b.axis);
  }
  for (const auto& p : b.settings) {
    out += ' ';
    out += p.id;
    out += ' ';
    out += p.key;
    if (p.index) out += '[' + std::to_string(*p.index) + ']';
    out += '=';
    num(out, p.value);
  }
  if (b.wait) out += " WAIT";
}

void put(std::string& out, const Message& b, const machines::Machine& /*m*/) {
  if (b.mode == MessageMode::accepted) {
    out += " ACCEPTED \"" + b.text + "\"";
  } else {
    out += " MSG";
    static constexpr const char* kModes[] = {"", " SYN", " SYN_ACK", " ACK"};
    out += kModes[static_cast<int>(b.mode)];
    out += " \"" + b.text + "\"";
  }
}

void put(std::string& out, const Flush& b, const machines::Machine& /*m*/) {
  static constexpr const char* kKinds[] = {" FLUSH", " FLUSH CONTINUE", " FLUSH WAIT"};
  out += kKinds[static_cast<int>(b.kind)];
}

void channels(std::string& out, const std::vector<std::uint8_t>& list) {
  for (const std::uint8_t c : list)
    out += " CH" + std::to_string(c);
  if (list.empty()) out += " BROADCAST";
}

void put(std::string& out, const Signal& b, const machines::Machine& /*m*/) {
  if (b.remove) {  // #SIGNAL REMOVE [SYN]: the numbers it clears
    out += b.syn ? " SIGNAL_REMOVE SYN ID" : " SIGNAL_REMOVE ID";
    out += std::to_string(b.id);
    if (b.range) out += ".." + std::to_string(b.id_max);
    return channels(out, b.receivers);
  }
  out += b.syn ? " SIGNAL SYN ID" : " SIGNAL ID";
  out += std::to_string(b.id);
  if (b.count) out += " COUNT" + std::to_string(*b.count);
  for (const auto& [i, v] : b.params) {
    out += " P[" + std::to_string(i) + "]=";
    num(out, v);
  }
  channels(out, b.receivers);
}

void put(std::string& out, const SignalWait& b, const machines::Machine& /*m*/) {
  out += " WAIT SYN ID" + std::to_string(b.id);
  channels(out, b.senders);
}

void put(std::string& out, const Barrier& b, const machines::Machine& m) {
  out += " BARRIER";
  if (b.wants(BarrierNeed::external)) {
    out += " FLUSH V.E.READ";
    for (const auto& name : b.external)
      out += " V.E." + name;
  }
  if (b.wants(BarrierNeed::probe_latch) && b.probe) {
    out += " PROBE_LATCH ";
    out += axis_name(m, *b.probe);
  }
  if (b.wants(BarrierNeed::signal) && b.signal) {
    out += b.signal->read ? " SIGNAL_READ ID" : " WAIT ID";
    out += std::to_string(b.signal->id);
    channels(out, b.signal->senders);
  }
  if (b.wants(BarrierNeed::position)) {
    out += " POSITION frame=" + frame_name(b.frame);
    for (std::size_t i = 0; i < kMaxAxes; ++i) {
      if ((b.axes >> i) & 1u) {
        out += ' ';
        out += axis_name(m, static_cast<std::uint8_t>(i));
      }
    }
  }
}

void put(std::string& out, const WaitIndp& b, const machines::Machine& m) {
  out += " WAIT_INDP";
  if (b.axes == 0) out += " ALL";
  for (std::size_t i = 0; i < kMaxAxes; ++i) {
    if ((b.axes >> i) & 1u) {
      out += ' ';
      out += axis_name(m, static_cast<std::uint8_t>(i));
    }
  }
}

void put(std::string& out, const Homing& b, const machines::Machine& m) {
  out += " HOME";
  for (const auto& [axis, order] : b.axes) {
    out += ' ';
    out += axis_name(m, axis);
    out += '=' + std::to_string(order);
  }
}

void put(std::string& out, const SetPosition& b, const machines::Machine& m) {
  out += " G92";
  for (std::size_t i = 0; i < kMaxAxes; ++i) {
    if ((b.axes >> i) & 1u) field(out, axis_name(m, static_cast<std::uint8_t>(i)), b.values[i]);
  }
}

void put(std::string& out, const End& b, const machines::Machine& /*m*/) {
  out += " END";
  if (b.code != 0) out += (b.code < 10 ? " M0" : " M") + std::to_string(b.code);  // M02
}

}  // namespace

std::string to_trace_line(const Command& c, const machines::Machine& m) {
  std::string out = std::to_string(c.line) + ":";
  std::visit([&](const auto& b) { put(out, b, m); }, c.body);
  return out;
}

int write_trace(const core::SourceFile& file, const machines::Machine& machine,
                const TraceOptions& options, std::ostream& out, core::DiagnosticList& diags) {
  Interpreter interp(file, machine, options.interp);
  std::uint64_t count = 0;
  bool truncated = false;
  while (out.good()) {
    auto c = interp.next_decode_only();
    if (!c) break;
    if (options.max_commands != 0 && count == options.max_commands) {
      truncated = true;  // there is more: say so instead of ending as if complete
      break;
    }
    ++count;
    // A command from a global subroutine file names that file; main-program lines stay bare.
    if (c->file != 0) {
      out << std::filesystem::path(interp.file_name(c->file)).filename().string() << ':';
    }
    out << to_trace_line(*c, machine) << '\n';
  }
  if (truncated) {
    out << "# truncated after " << count << " commands (--max-commands)\n";
    diags.add({core::Severity::note,
               file.name(),
               {},
               "NC4905",
               "trace truncated after " + std::to_string(count) +
                   " commands (--max-commands); the program goes on"});
  }
  // The stream's diagnostics end the trace too, so that a trace (and a golden) is a complete
  // record of what the decoder made of the program.
  for (const auto& d : interp.diagnostics().items()) {
    out << "# " << d.id << " line " << d.loc.line;
    if (d.file != file.name()) out << " of " << std::filesystem::path(d.file).filename().string();
    out << '\n';
    diags.add(d);
  }
  return interp.error() != nullptr ? 1 : 0;
}

namespace {

// Whether the extent of an arc (arc_extent) is inside the software limits for certain, without
// its angles: on each plane axis arc_extent's extremes are the centre plus one of start - centre,
// end - centre, +-radius and 0, computed as here, and adding the centre keeps their order.
bool arc_extent_inside(const Motion& m, const machines::Machine& machine) {
  const Arc& a = *m.arc;
  for (int k = 0; k < 2; ++k) {
    const std::size_t i = k == 0 ? a.axis_1 : a.axis_2;
    if (i >= machine.axes.size()) continue;
    const double c = k == 0 ? a.centre_1 : a.centre_2;
    const double s = m.start[i] - c, e = m.end[i] - c;
    const double lo = std::min({s, e, -a.radius, a.radius, 0.0}) + c;
    const double hi = std::max({s, e, -a.radius, a.radius, 0.0}) + c;
    const auto& lim = machine.axes[i].soft_limits;
    if (!(lo >= lim.neg && hi <= lim.pos)) return false;  // NaN too: the full computation
  }
  return true;
}

}  // namespace

void add_soft_limit_errors(const Command& c, const machines::Machine& machine,
                           const std::string& file, core::DiagnosticList& out) {
  if (const auto* m = std::get_if<Motion>(&c.body)) {
    // soft limits where decidable: in the MCS without kinematics (axis values)
    if (!(m->frame == CoordFrame{})) return;
    const auto outside = [&](std::size_t i, double v) {
      const auto& lim = machine.axes[i].soft_limits;
      return v < lim.neg || v > lim.pos;
    };
    const auto report = [&](std::size_t i, const std::string& what, double v) {
      const auto& lim = machine.axes[i].soft_limits;
      out.add({core::Severity::error,
               file,
               {c.line, 1},
               "NC4601",
               what + " " + machine.axes[i].name + "=" + core::number_text(v) +
                   " is outside the software limits [" + core::number_text(lim.neg) + ", " +
                   core::number_text(lim.pos) + "] (P-AXIS-00177/00178)"});
    };
    AxisMask reported = 0;
    for (std::size_t i = 0; i < machine.axes.size() && i < kMaxAxes; ++i) {
      if (((m->programmed >> i) & 1u) == 0 || !outside(i, m->end[i])) continue;
      report(i, "target", m->end[i]);
      reported |= AxisMask{1} << i;
    }
    if (m->arc && !arc_extent_inside(*m, machine)) {
      // The circle's extent: its extreme points on each plane axis that the arc passes.
      const auto [lo, hi] = arc_extent(*m);
      for (int k = 0; k < 2; ++k) {
        const std::size_t i = k == 0 ? m->arc->axis_1 : m->arc->axis_2;
        if (i >= machine.axes.size() || ((reported >> i) & 1u) != 0) continue;
        if (outside(i, lo[k])) report(i, "the arc reaches", lo[k]);
        if (outside(i, hi[k])) report(i, "the arc reaches", hi[k]);
      }
    }
  } else if (const auto* p = std::get_if<SplinePoint>(&c.body)) {
    // A spline vertex is a programmed point like a motion's target (the curve between
    // vertices is the planner's: an Akima or B-spline may overshoot them).
    if (!(p->frame == CoordFrame{})) return;
    for (std::size_t i = 0; i < machine.axes.size() && i < kMaxAxes; ++i) {
      const auto& lim = machine.axes[i].soft_limits;
      const double v = p->point[i];
      if (((p->programmed >> i) & 1u) == 0 || (v >= lim.neg && v <= lim.pos)) continue;
      out.add({core::Severity::error,
               file,
               {c.line, 1},
               "NC4601",
               "spline point " + machine.axes[i].name + "=" + core::number_text(v) +
                   " is outside the software limits [" + core::number_text(lim.neg) + ", " +
                   core::number_text(lim.pos) + "] (P-AXIS-00177/00178)"});
    }
  }
}

core::DiagnosticList check_semantics(const core::SourceFile& file, const machines::Machine& machine,
                                     const Options& options, grammar::ProgramCheck* program_check) {
  Interpreter interp(file, machine, options);
  if (program_check != nullptr) interp.share_first_parse(*program_check);
  core::DiagnosticList out;
  // Finite programs are checked to their end; an endless one up to its first repeat.
  const std::uint64_t max_commands =
      std::max<std::uint64_t>(kCheckMaxCommands, kCheckCommandsPerLine * file.line_count());
  std::uint64_t count = 0;
  bool ended = false;
  // The #CS chain as the adapter follows it (program/program_frames.cpp): PCS targets to MCS.
  machines::CsStack cs(machine.channel.cs_rotation_sequence);
  machines::Frame cs_frame = cs.active_frame();
  // A soft-limit error of a block inside a loop is the same on every pass: reported once, with
  // how often it repeated (note NC4602), not once per pass.
  std::map<std::string, std::pair<core::Diagnostic, std::uint64_t>> repeats;
  const auto add_once = [&](core::Diagnostic d) {
    std::string key = d.file + ':' + std::to_string(d.loc.line) + ':' + d.id + ':' + d.message;
    auto [it, fresh] = repeats.try_emplace(std::move(key), d, 0);
    if (fresh) {
      out.add(std::move(d));
    } else {
      ++it->second.second;
    }
  };
  while (count < max_commands && !interp.endless_from()) {
    // A program with syntax errors gets no semantic check: stop at the first one found.
    if (program_check != nullptr && program_check->has_errors()) break;
    auto c = interp.next_decode_only();
    if (!c) {
      ended = true;
      break;
    }
    ++count;
    // through add_once: a block in a loop reports its soft-limit error once (NC4602)
    core::DiagnosticList found;
    if (const auto* sel = std::get_if<SelectCs>(&c->body)) {
      apply_selection(cs, *sel);
      cs_frame = cs.active_frame();
    }
    const std::optional<Command> in_mcs = command_in_mcs(*c, cs_frame, machine);
    add_soft_limit_errors(in_mcs ? *in_mcs : *c, machine, interp.file_name(c->file), found);
    for (const core::Diagnostic& d : found.items())
      add_once(d);
  }
  if (program_check != nullptr) interp.parse_rest();
  for (const auto& [key, repeat] : repeats) {
    if (repeat.second == 0) continue;
    const core::Diagnostic& d = repeat.first;
    out.add({core::Severity::note, d.file, d.loc, "NC4602",
             "the " + d.id + " above repeats " + std::to_string(repeat.second) + " more time" +
                 (repeat.second == 1 ? "" : "s") +
                 " (the block runs again in a loop); reported once"});
  }
  for (const auto& d : interp.diagnostics().items()) {
    const bool syntax = d.id.rfind("NC1", 0) == 0 || d.id.rfind("NC2", 0) == 0;
    if (syntax && d.file == file.name()) continue;  // the main file's syntax: grammar
    out.add(d);
  }
  if (!ended && interp.endless_from()) {
    out.add({core::Severity::note,
             file.name(),
             {*interp.endless_from(), 1},
             "NC4904",
             "the program runs endlessly: from here it returns to the same state (variables, "
             "loops, position) after motion or a run-time wait; checked through one repetition"});
  } else if (!ended) {
    out.add({core::Severity::warning,
             file.name(),
             {},
             "NC4902",
             "check stopped after " + std::to_string(max_commands) +
                 " commands without reaching the end or a repeated state; the rest of the "
                 "program was not checked"});
  }
  return out;
}

}  // namespace ncsim::interp
