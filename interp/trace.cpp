#include "interp/trace.hpp"

#include <algorithm>
#include <charconv>

#include "core/number_text.hpp"

namespace ncsim::interp {
namespace {

void num(std::string& out, double v) {
  char buf[64];
  if (v == 0.0) v = 0.0;  // no "-0.0000"
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 4);
  std::string_view s(buf, static_cast<std::size_t>(r.ptr - buf));
  if (s == "-0.0000") s = "0.0000";
  out += s;
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

std::string to_trace_line(const Command& c, const machines::Machine& m) {
  std::string out = std::to_string(c.line) + ":";
  std::visit(
      [&](const auto& b) {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, Motion>) {
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
        } else if constexpr (std::is_same_v<T, Spline>) {
          out += b.type == SplineType::akima ? " SPLINE AKIMA" : " SPLINE BSPLINE";
          out += " points=" + std::to_string(b.points.size());
          field(out, "F", b.feed);
          for (const auto& p : b.points) {
            out += " [";
            std::string inner;
            axes(inner, p, m);
            out += inner.substr(1) + "]";
          }
        } else if constexpr (std::is_same_v<T, Dwell>) {
          out += " DWELL";
          field(out, "t", b.seconds);
        } else if constexpr (std::is_same_v<T, Tech>) {
          static constexpr const char* kNames[] = {"M", "H", "S", "T", "D"};
          out += " TECH ";
          out += kNames[static_cast<int>(b.kind)];
          out += '=';
          num(out, b.value);
        } else if constexpr (std::is_same_v<T, ProgramStop>) {
          out += b.optional ? " STOP M01" : " STOP M00";
        } else if constexpr (std::is_same_v<T, AxisCommand>) {
          out += b.kind == IndpKind::syn ? " INDP_SYN " : " INDP_ASYN ";
          out += axis_name(m, b.axis);
          out += b.rapid ? " G00" : " G01";
          field(out, "POS", b.target);
          if (b.feed) field(out, "FEED", *b.feed);
          if (b.time) field(out, "TIME", *b.time);
          if (b.interruptible) out += " INTERRUPTIBLE";
        } else if constexpr (std::is_same_v<T, MoveVelocity>) {
          out += " MC_MOVEVELOCITY ";
          out += axis_name(m, b.axis);
          field(out, "v", b.velocity);
          field(out, "a", b.acceleration);
          field(out, "d", b.deceleration);
          field(out, "j", b.jerk);
          out += " dir=" + std::to_string(b.direction);
        } else if constexpr (std::is_same_v<T, ProbeArm>) {
          out += " PROBE_ARM ";
          out += axis_name(m, b.axis);
          out += " channel=" + std::to_string(b.channel);
          if (b.mode) out += " mode=" + std::to_string(*b.mode);
        } else if constexpr (std::is_same_v<T, WaitProbe>) {
          out += " WAIT_PROBE ";
          out += axis_name(m, b.axis);
        } else if constexpr (std::is_same_v<T, SyncIn>) {
          out += " SYNC_IN ";
          out += axis_name(m, b.conveyor);
          field(out, "conv_vel", b.conv_vel);
          if (b.feed_cont) field(out, "FEED_CONT", *b.feed_cont);
          if (b.feed_cont_auto) out += " FEED_CONT_AUTO";
        } else if constexpr (std::is_same_v<T, SyncOut>) {
          out += " SYNC_OUT";
          if (b.feed_cont) field(out, "FEED_CONT", *b.feed_cont);
          if (b.feed_cont_auto) out += " FEED_CONT_AUTO";
        } else if constexpr (std::is_same_v<T, SelectCs>) {
          static constexpr const char* kOps[] = {"DEF", "ON", "OFF", "OFF_ALL"};
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
          out += " active=" + std::to_string(b.active_count);
        } else if constexpr (std::is_same_v<T, Kinematics>) {
          out += " KIN";
          if (b.kin_id) out += " id=" + std::to_string(*b.kin_id);
          out += b.trafo_on ? " TRAFO_ON" : " TRAFO_OFF";
        } else if constexpr (std::is_same_v<T, CaxTrack>) {
          out += b.on ? " CAXTRACK_ON" : " CAXTRACK_OFF";
          if (b.axis) {
            out += " AX=";
            out += axis_name(m, *b.axis);
          }
          field(out, "ANGLIMIT", b.anglimit);
          field(out, "OFFSET", b.offset);
          if (!b.on) field(out, "ANGPOS", b.angpos);
        } else if constexpr (std::is_same_v<T, MachineData>) {
          out += " MACHINE_DATA";
          if (b.syn) out += " SYN";
          if (b.axis) {
            out += " AX=";
            out += axis_name(m, *b.axis);
          }
          out += " \"" + b.parameter + "\"";
          if (b.wait) out += " WAIT";
        } else if constexpr (std::is_same_v<T, Message>) {
          out += " MSG";
          if (!b.mode.empty()) out += " " + b.mode;
          out += " \"" + b.text + "\"";
        } else if constexpr (std::is_same_v<T, Flush>) {
          static constexpr const char* kKinds[] = {" FLUSH", " FLUSH CONTINUE", " FLUSH WAIT",
                                                   " FLUSH V.E.READ"};
          out += kKinds[static_cast<int>(b.kind)];
        } else if constexpr (std::is_same_v<T, WaitIndp>) {
          out += " WAIT_INDP";
          if (b.axes == 0) out += " ALL";
          for (std::size_t i = 0; i < kMaxAxes; ++i) {
            if ((b.axes >> i) & 1u) {
              out += ' ';
              out += axis_name(m, static_cast<std::uint8_t>(i));
            }
          }
        } else if constexpr (std::is_same_v<T, Homing>) {
          out += " HOME";
          for (const auto& [axis, order] : b.axes) {
            out += ' ';
            out += axis_name(m, axis);
            out += '=' + std::to_string(order);
          }
        } else if constexpr (std::is_same_v<T, SetPosition>) {
          out += " G92";
          for (std::size_t i = 0; i < kMaxAxes; ++i) {
            if ((b.axes >> i) & 1u)
              field(out, axis_name(m, static_cast<std::uint8_t>(i)), b.values[i]);
          }
        } else if constexpr (std::is_same_v<T, End>) {
          out += " END";
          if (b.code != 0) out += (b.code < 10 ? " M0" : " M") + std::to_string(b.code);  // M02
        }
      },
      c.body);
  return out;
}

int write_trace(const core::SourceFile& file, const machines::Machine& machine,
                const TraceOptions& options, std::ostream& out, core::DiagnosticList& diags) {
  Interpreter interp(file, machine, options.interp);
  std::uint64_t count = 0;
  while ((options.max_commands == 0 || count < options.max_commands) && out.good()) {
    auto c = interp.next();
    if (!c) break;
    ++count;
    out << to_trace_line(*c, machine) << '\n';
  }
  // The stream's diagnostics end the trace too, so that a trace (and a golden) is a complete
  // record of what the decoder made of the program.
  for (const auto& d : interp.diagnostics().items()) {
    out << "# " << d.id << " line " << d.loc.line << '\n';
    diags.add(d);
  }
  return interp.error() != nullptr ? 1 : 0;
}

core::DiagnosticList check_semantics(const core::SourceFile& file, const machines::Machine& machine,
                                     const Options& options) {
  Interpreter interp(file, machine, options);
  core::DiagnosticList out;
  // Finite programs are checked to their end; an endless one up to its first repeat.
  const std::uint64_t max_commands =
      std::max<std::uint64_t>(kCheckMaxCommands, kCheckCommandsPerLine * file.line_count());
  std::uint64_t count = 0;
  bool ended = false;
  while (count < max_commands && !interp.endless_from()) {
    auto c = interp.next();
    if (!c) {
      ended = true;
      break;
    }
    ++count;
    if (const auto* m = std::get_if<Motion>(&c->body)) {
      // soft limits where decidable: no #CS, no conveyor frame, no kinematics
      if (m->modal.cs_active || m->modal.synchronised || m->modal.kinematics_on) continue;
      for (std::size_t i = 0; i < machine.axes.size() && i < kMaxAxes; ++i) {
        if (((m->programmed >> i) & 1u) == 0) continue;
        const auto& lim = machine.axes[i].soft_limits;
        if (m->end[i] < lim.neg || m->end[i] > lim.pos) {
          out.add({core::Severity::error,
                   interp.file_name(c->file),
                   {c->line, 1},
                   "NC4601",
                   "target " + machine.axes[i].name + "=" + core::number_text(m->end[i]) +
                       " is outside the software limits [" + core::number_text(lim.neg) + ", " +
                       core::number_text(lim.pos) + "] (P-AXIS-00177/00178)"});
        }
      }
    }
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
             "loops, position) after motion; checked through one repetition"});
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
