#include "cli/run_commands.hpp"

#include <CLI/CLI.hpp>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "audit/audit.hpp"
#include "audit/time.hpp"
#include "audit/workpiece_cycles.hpp"  // --- line
#include "channel/channel.hpp"
#include "cli/commands.hpp"
#include "cli/cycle_option.hpp"
#include "cli/number_format.hpp"
#include "cli/run_progress.hpp"
#include "cli/workpiece_report.hpp"  // --- line
#include "conveyor/world.hpp"
#include "core/diagnostic.hpp"
#include "core/output_file.hpp"
#include "core/source_file.hpp"
#include "grammar/check.hpp"
#include "interp/interpreter.hpp"
#include "ipo/interpolator.hpp"
#include "machines/loader.hpp"
#include "program/program_source.hpp"
#include "program/trafo.hpp"    // --- trafo-jerk
#include "report/html.hpp"      // --- report:
#include "report/recorder.hpp"  // --- report:
#include "scenario/player.hpp"

namespace ncsim::cli {
namespace {

namespace fs = std::filesystem;

void append_num(std::string& s, double v) {
  s += num(v);
}

struct Loaded {
  core::SourceFile file;
  machines::Machine machine;
  double t_cycle = ipo::kDefaultCycle;  ///< --cycle-us, else the channel's NCSIM-CHAN-610 [s]
  interp::Options interp;               ///< the scenario's V.E. initial values (barrier answers)
  std::optional<scenario::Scenario> scenario;  ///< played by the channel when it has events
  /// The conveyor world (docs/conveyor.md "The world") on a machine with a conveyor axis.
  std::unique_ptr<conveyor::Port> port;
};

// What the channel plays of a scenario (docs/scenario.md "Wiring into the channel loop"):
// built only when the scenario has events or [stop]; wires the barrier answers and the player.
struct Playing {
  std::unique_ptr<scenario::Player> player;
  Playing(const Loaded& in, ipo::ProgramSource& src) {
    if (!in.scenario || !in.scenario->needs_channel()) return;
    player = std::make_unique<scenario::Player>(*in.scenario);
    // A V.E. write at run time must reach the barrier after it: then the path stops before
    // every V.E. read (the kernel's synchronous read); without writes the answer is known.
    bool writes = in.scenario->workpiece_ve();  // written when a workpiece is measured
    for (const scenario::Event& e : in.scenario->events)
      for (const scenario::Action& a : e.actions)
        writes = writes || std::holds_alternative<scenario::VeWrite>(a);
    src.answer_barriers_from(&player->ve(), writes);
  }
  void attach(ipo::Channel& channel, conveyor::Port* port) {
    channel.play(player.get());
    channel.attach_conveyor(port);
  }
};

// Program and machine, syntax-checked; an exit status on failure (printed on `err`).
std::variant<Loaded, int> load(const ProgramOptions& options,
                               const std::optional<std::uint64_t>& cycle_us, std::ostream& err) {
  if (!options.external.empty()) {
    err << "ncsim: error: not supported: --ve with time / run (V.E. values come with the "
           "scenario)\n";
    return kExitUsage;
  }
  std::error_code ec;
  if (!fs::is_regular_file(options.program, ec)) {
    err << "ncsim: error: no such file: '" << options.program.string() << "'\n";
    return kExitUsage;
  }
  const std::optional<fs::path> dir = machine_folder(options, err);
  if (!dir) return kExitUsage;
  machines::LoadResult loaded = machines::load_machine(*dir);
  for (const core::Diagnostic& d : loaded.diagnostics.items())
    err << core::format(d);
  if (!loaded.machine) {
    err << "ncsim: error: machine '" << dir->string() << "' could not be loaded\n";
    return kExitUsage;
  }
  core::SourceFile file = core::SourceFile::load(options.program);
  // Scenario (docs/scenario.md): its V.E. initial values answer the barriers; the channel
  // plays its V.E. writes, [stop], path and axis overrides and feed hold (overrides beyond the
  // machine's are refused by the loader: NC6102, NC6105).
  auto scenario = load_scenario_for(options, file, *loaded.machine, err);
  if (const int* status = std::get_if<int>(&scenario)) return *status;
  interp::Options interp_options;
  apply_cycle_options(options, interp_options);
  auto& s = std::get<std::optional<scenario::Scenario>>(scenario);
  // --max-time: the scenario's [stop] time, the earlier of both; without a scenario one that
  // holds only this condition (its file name empty: printed as --max-time).
  if (options.max_time) {
    if (!s) s.emplace();
    if (!s->stop.time || *s->stop.time > *options.max_time) s->stop.time = *options.max_time;
  }
  if (s) {
    for (const scenario::VeInitial& v : s->ve)
      interp_options.external.emplace(v.name, v.value);
    // [tech]: execution times over the machine's NCSIM-CHAN-650..653 (docs/scenario.md).
    machines::TechTable& tech = loaded.machine->channel.tech;
    for (const scenario::TechDuration& d : s->tech) {
      machines::TechFunction& f = d.kind == 'M'   ? tech.m[d.number]
                                  : d.kind == 'H' ? tech.h[d.number]
                                  : d.kind == 'S' ? tech.s
                                                  : tech.t;
      f.duration = d.seconds;
    }
  }
  const core::DiagnosticList syntax = grammar::check_program(file);
  for (const core::Diagnostic& d : syntax.items())
    err << core::format(d, file);
  if (syntax.error_count() > 0) return kExitProgramErrors;
  // The channel list's NCSIM-CHAN-610 ncsim.cycle_time (default 1 ms), --cycle-us over it
  // (docs/ipo.md "The cycle time"); both whole microseconds, converted the same way.
  const double t =
      cycle_us ? static_cast<double>(*cycle_us) * 1e-6 : loaded.machine->channel.cycle_time;
  // The position controller needs Kv x T <= 1 (axes/control): a cycle too long for an axis's
  // Kv is a usage error naming where the cycle came from, the axis and the longest cycle it
  // takes, before the channel is built (issue 34: it failed there with Kv's message alone).
  for (const std::uint8_t i : ipo::interpolated_axes(*loaded.machine)) {
    const machines::AxisParams& a = loaded.machine->axes[i];
    if (a.control.kv * t <= 1.0) continue;
    err << "ncsim: error: "
        << (cycle_us ? "--cycle-us " + std::to_string(*cycle_us)
                     : std::string("the channel list's ncsim.cycle_time (NCSIM-CHAN-610) ") +
                           human(t * 1e6) + " us")
        << ": axis " << a.name << "'s Kv P-AXIS-00099 getriebe[0].kv = " << human(a.control.kv)
        << " 1/s takes a cycle of at most " << human(std::floor(1e6 / a.control.kv))
        << " us (Kv x cycle <= 1: the position controller's stability)\n";
    return kExitUsage;
  }
  // The conveyor world (belt, encoder, probe, filters) of a machine with a conveyor axis.
  std::unique_ptr<conveyor::Port> port;
  if (loaded.machine->conveyor_axis() != nullptr) {
    try {
      port = conveyor::make_port(*loaded.machine, s ? &*s : nullptr, t);
    } catch (const std::invalid_argument& e) {
      err << "ncsim: error: the conveyor of machine '" << dir->string() << "': " << e.what()
          << '\n';
      return kExitUsage;
    }
  }
  return Loaded{
      std::move(file), std::move(*loaded.machine), t, std::move(interp_options), std::move(s),
      std::move(port)};
}

// The program error that ended a run, with its source line when it is in the main program.
std::string diagnostic_text(const Loaded& in, const interp::Interpreter& interp,
                            const ipo::ProgramSource& src, const std::string& fallback) {
  const core::Diagnostic* d = src.error();
  if (d == nullptr) d = interp.error();
  if (d == nullptr) return "ncsim: error: " + fallback + "\n";
  std::string text;
  if (d->file == in.file.name()) {
    text = core::format(*d, in.file);
  } else {
    // A subroutine file's block is echoed too (the interpreter's files 1, 2, ... in call order;
    // file_name() throws std::out_of_range past the last).
    text = core::format(*d);
    try {
      for (std::uint16_t f = 1; f != 0; ++f) {
        if (interp.file_name(f) == d->file) {
          text = core::format(*d, interp.source_file(f));
          break;
        }
      }
    } catch (const std::out_of_range&) {
    }
  }
  // A subroutine file's syntax errors (NC4306 stands at the call): each with its own position,
  // after the error that ended the run, as `check` lists them (issue 34).
  for (const core::Diagnostic& e : interp.diagnostics().items()) {
    const bool same = e.id == d->id && e.file == d->file && e.loc == d->loc;
    if (e.severity == core::Severity::error && e.file != in.file.name() && !same)
      text += core::format(e);
  }
  return text;
}

std::string first_line(const std::string& s) {
  return s.substr(0, s.find('\n'));
}

std::vector<std::string> axis_names(const machines::Machine& m) {
  std::vector<std::string> out;
  for (const std::uint8_t i : ipo::interpolated_axes(m))
    out.push_back(m.axes[i].name);
  return out;
}

// The length unit of each interpolated axis: deg for a rotary axis, mm otherwise.
std::vector<std::string> axis_units(const machines::Machine& m) {
  std::vector<std::string> out;
  for (const std::uint8_t i : ipo::interpolated_axes(m))
    out.push_back(m.axes[i].kind == machines::AxisKind::rotary ? "deg" : "mm");
  return out;
}

// --- planner: where a block is, in `time --blocks` and the audit's violations: its line in
// the main program, `file:line` in a subroutine file (docs/ipo.md "Blocks of subroutine files").
std::string block_where(const interp::Interpreter& interp, std::uint16_t file, std::uint32_t line) {
  if (file == 0) return std::to_string(line);
  return interp.file_name(file) + ':' + std::to_string(line);
}

// A run-time position as a diagnostic in its own file (the main program or a subroutine
// file), echoing the block's text.
std::string positioned(const interp::Interpreter& interp, const ipo::RunTimeError& e,
                       core::Severity severity, const std::string& message) {
  const core::SourceFile& file = interp.source_file(e.file);
  core::Diagnostic d;
  d.severity = severity;
  d.file = file.name();
  d.loc = {e.line, 1};
  d.id = e.id;
  d.message = message;
  return core::format(d, file);
}

// The audit verdict, one line per axis, then the documented steps and every violation listed.
void print_audit(const ipo::Verdict& v, const std::vector<std::string>& names,
                 const std::vector<std::string>& units, const interp::Interpreter& interp,
                 std::ostream& os, bool each_step) {
  for (std::size_t i = 0; i < v.axes.size(); ++i) {
    const ipo::AxisAudit& a = v.axes[i];
    const std::string& u = i < units.size() ? units[i] : std::string("mm");
    os << "audit: " << names[i] << " |v| " << human(std::max(a.v_closed, a.v_diff)) << " / "
       << human(a.v_limit) << ' ' << u << "/s, |a| " << human(std::max(a.a_closed, a.a_diff))
       << " / " << human(a.a_limit) << ' ' << u << "/s^2, |j| ";
    if (a.jerk_cycles == 0) {  // STEP slope throughout: the jerk is not limited, not audited
      os << "not limited (acceleration-limited slope)\n";
      continue;
    }
    os << human(std::max(a.j_closed, a.j_diff)) << " / " << human(a.j_limit) << ' ' << u
       << "/s^3\n";
  }
  // --- trafo: under #TRAFO ON the joints (the machine axes) are checked apart.
  for (std::size_t i = 0; i < v.joints.size(); ++i) {
    const ipo::AxisAudit& a = v.joints[i];
    if (a.v_closed == 0.0 && a.v_diff == 0.0) continue;  // no transformed cycle moved it
    os << "audit: " << (i < names.size() ? names[i] : std::to_string(i)) << " under #TRAFO |v| "
       << human(std::max(a.v_closed, a.v_diff)) << " / " << human(a.v_limit) << ", |a| "
       << human(std::max(a.a_closed, a.a_diff)) << " / " << human(a.a_limit) << ", |j| "
       << human(std::max(a.j_closed, a.j_diff)) << " / " << human(a.j_limit) << " (deg | mm, s)\n";
  }
  os << "audit: contour deviation " << human(v.contour_max) << " mm (tolerance "
     << human(v.contour_tolerance) << " mm), " << v.step_count
     << " documented VELOJUMP / TRANSVELMIN / C1 steps within their formulas, " << v.cycles
     << " cycles\n";
  // One documented step: where, which axis, its value against its formula's bound.
  const auto step_text = [&](const ipo::Step& s) {
    const bool c1 = s.quantity == ipo::Quantity::c1_step;  // an acceleration step
    const char* unit = c1 ? "/s^2" : "/s";
    const std::string& u = s.axis < units.size() ? units[s.axis] : std::string("mm");
    std::ostringstream t;
    t << "t=" << num(s.t) << " s line " << block_where(interp, s.file, s.line) << " axis "
      << (s.axis < names.size() ? names[s.axis] : std::to_string(s.axis))
      << (s.joint ? " under #TRAFO " : " ") << (c1 ? "|da| " : "|dv| ") << human(s.value) << " of "
      << human(s.bound) << ' ' << u << unit << " at the link velocity " << human(s.v_link)
      << " mm/s";
    return t.str();
  };
  // The documented steps listed apart (issue 12): per kind, how many and the closest to its
  // formula's bound (the axis that came closest at that joint); with --audit-steps each one.
  for (std::size_t k = 0; k < ipo::kStepKindNames.size(); ++k) {
    const ipo::StepKind& sk = v.step_kinds[k];
    if (sk.count == 0) continue;
    os << "audit: " << ipo::kStepKindNames[k] << " steps " << sk.count << ", closest to "
       << ipo::kStepKindFormulas[k] << ": " << step_text(sk.closest) << '\n';
  }
  if (each_step) {
    for (const ipo::Step& s : v.steps)
      os << "audit: step " << ipo::kStepKindNames[ipo::step_kind(s.quantity)] << ' ' << step_text(s)
         << '\n';
    if (v.step_count > v.steps.size())
      os << "audit: ... " << (v.step_count - v.steps.size()) << " more steps\n";
  }
  for (const ipo::Violation& x : v.violations) {
    os << "audit: violation t=" << num(x.t) << " s line " << block_where(interp, x.file, x.line)
       << " axis " << (x.axis < names.size() ? names[x.axis] : std::to_string(x.axis)) << ' '
       << ipo::quantity_name(x.quantity) << " (" << ipo::method_name(x.method) << ") "
       << num(x.value) << " > " << num(x.limit);
    if (x.path >= 0.0)  // --- conveyor: the axis moved with the belt (audit/audit.hpp)
      os << " (" << num(x.path) << " without the belt's share)";
    os << '\n';
  }
  if (v.violation_count > v.violations.size()) {
    os << "audit: ... " << (v.violation_count - v.violations.size()) << " more violations\n";
  }
  if (v.belt_count > 0)  // --- conveyor: 004 l.454
    os << "audit: " << v.belt_count
       << " of the violations are the belt's own acceleration or jerk on top of a path within "
          "the axis's limits (004 l.454: \"dynamic overshoots ... caused by fluctuations in "
          "conveyor belt velocity\"; docs/conveyor.md \"The belt's own dynamics\")\n";
  os << "audit: " << (v.ok() ? "ok" : std::to_string(v.violation_count) + " violations") << '\n';
}

/// A Sink that passes every cycle and joint to two sinks (either may be null).
class Tee final : public ipo::Sink {
 public:
  Tee(ipo::Sink* a, ipo::Sink* b) : a_(a), b_(b) {}
  void on_joint(const ipo::Joint& j) override {
    if (a_) a_->on_joint(j);
    if (b_) b_->on_joint(j);
  }
  void on_cycle(const ipo::Cycle& c) override {
    if (a_) a_->on_cycle(c);
    if (b_) b_->on_cycle(c);
  }

 private:
  ipo::Sink* a_;
  ipo::Sink* b_;
};

// The text of a run's end when it failed: the run-time error (file:line:col, the time, the id)
// or the program error that ended the source.
std::string failure_text(const Loaded& in, const interp::Interpreter& interp,
                         const ipo::ProgramSource& src, const ipo::Channel& ch) {
  if (const auto& e = ch.run_time_error())
    return positioned(interp, *e, core::Severity::error,
                      "run-time error at t=" + seconds(e->t) + " s: " + e->message);
  return diagnostic_text(in, interp, src, ch.message());
}

// --- trafo: the channel's warning (NC6210: a joint beyond its dynamics while synchronised
// under #TRAFO ON), positioned like a run-time error; the run goes on.
std::string warning_text(const interp::Interpreter& interp, const ipo::Channel& ch) {
  const auto& w = ch.trafo_warning();
  if (!w) return {};
  return positioned(interp, *w, core::Severity::warning,
                    "at t=" + seconds(w->t) + " s: " + w->message);
}

// The interpreter's warnings (a skipped cycle NC4307, a main program without M30 NC2019, ...),
// each once as the decoder reported it.
std::string interp_warnings(const interp::Interpreter& interp) {
  std::string out;
  for (const core::Diagnostic& d : interp.diagnostics().items())
    if (d.severity == core::Severity::warning) out += core::format(d);
  return out;
}

// A run that ended at the program's end with axes still moving (the end does not wait for
// the belt's share after #SYNC OUT, say): a warning naming them, "" when all stand (issue 34).
// Not after an error or a scenario's [stop], which end a run wherever it is.
std::string still_moving_text(const Loaded& in, const ipo::Channel& ch) {
  constexpr double kStanding = 1e-6;  // [mm/s | deg/s] below this an axis stands
  const std::vector<std::string> names = axis_names(in.machine);
  const std::vector<std::string> units = axis_units(in.machine);
  std::string moving;
  for (std::size_t i = 0; i < ch.axis_count() && i < names.size(); ++i) {
    const double v = ch.setpoints()[i].v;
    if (std::abs(v) <= kStanding) continue;
    moving += (moving.empty() ? "" : ", ") + names[i] + " at " + human(v) + ' ' + units[i] + "/s";
  }
  if (moving.empty()) return {};
  return "ncsim: warning: the run ended at t=" + seconds(ch.cycle().t) +
         " s with axes still moving: " + moving +
         " (the program end did not wait for them to stand, e.g. M30 right after #SYNC OUT) "
         "[NC6106]\n";
}

void json_string(std::ostream& os, const std::string& s) {
  os << '"';
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      os << '\\' << c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      std::array<char, 8> buf{};
      std::snprintf(buf.data(), buf.size(), "\\u%04x", c);
      os << buf.data();
    } else {
      os << c;
    }
  }
  os << '"';
}

// Why a run ended (docs/scenario.md "[stop]"): an error, the scenario's [stop], or the end.
// What set the stop condition: "scenario 'f.toml'", or "--max-time" for the one the option made.
std::string stop_source(const scenario::Scenario& s) {
  return s.file.empty() ? std::string("--max-time") : "scenario '" + s.file + "'";
}

std::string stop_reason(bool failed, const ipo::Channel& ch) {
  if (failed) return std::string(scenario::to_string(scenario::StopReason::error));
  if (const auto& s = ch.scenario_stop()) return std::string(scenario::to_string(*s));
  return std::string(scenario::to_string(scenario::StopReason::program_end));
}

void json_split(std::ostream& os, const ipo::TimeSplit& s) {
  os << "{\"rapid\":" << json_num(s.rapid) << ",\"feed\":" << json_num(s.feed)
     << ",\"dwell\":" << json_num(s.dwell) << ",\"tech\":" << json_num(s.tech)
     << ",\"exact_stop\":" << json_num(s.exact_stop) << ",\"waiting\":" << json_num(s.starved)
     << ",\"held\":" << json_num(s.held) << '}';
}

}  // namespace

int run_time(const TimeOptions& options, std::ostream& out, std::ostream& err) {
  auto loaded = load(options.program, options.cycle_us, err);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  const Loaded& in = std::get<Loaded>(loaded);

  interp::Interpreter interp(in.file, in.machine, in.interp);
  ipo::ProgramSource src(interp, in.machine, in.t_cycle);
  src.refuse_beyond_soft_limits(true);  // check's NC4601 before the block moves (issue 34)
  bool first_block = true;
  if (options.json) {
    out << "{\"program\":";
    json_string(out, in.file.name());
    out << ",\"machine\":";
    json_string(out, in.machine.name);
    out << ",\"cycle_s\":" << json_num(in.t_cycle);
    if (options.blocks) out << ",\"blocks\":[";
  } else if (options.blocks) {
    out << "# line time_s distance_mm feed_programmed_mm_min feed_reached_mm_min rapid_s feed_s "
           "dwell_s tech_s exact_stop_s waiting_s held_s lost_s feed_cap_mm_min\n";
  }
  const auto on_block = [&](const ipo::BlockTime& b) {
    if (!options.blocks) return;
    if (options.json) {
      out << (first_block ? "" : ",") << "{\"line\":" << b.line;
      if (b.file != 0) {  // --- planner: a block of a subroutine file
        out << ",\"file\":";
        json_string(out, interp.file_name(b.file));
      }
      out << ",\"time_s\":" << json_num(b.time) << ",\"distance_mm\":" << json_num(b.distance)
          << ",\"feed_programmed_mm_min\":" << json_num(b.feed_programmed * 60.0)
          << ",\"feed_reached_mm_min\":" << json_num(b.feed_reached * 60.0);
      if (b.feed_cap > 0.0) out << ",\"feed_cap_mm_min\":" << json_num(b.feed_cap * 60.0);
      out << ",\"lost_s\":" << json_num(b.lost) << ",\"split_s\":";
      json_split(out, b.split);
      out << '}';
    } else {
      out << block_where(interp, b.file, b.line) << ' ' << num(b.time) << ' ' << num(b.distance)
          << ' ' << num(b.feed_programmed * 60.0) << ' ' << num(b.feed_reached * 60.0) << ' '
          << num(b.split.rapid) << ' ' << num(b.split.feed) << ' ' << num(b.split.dwell) << ' '
          << num(b.split.tech) << ' ' << num(b.split.exact_stop) << ' ' << num(b.split.starved)
          << ' ' << num(b.split.held) << ' ' << num(b.lost) << ' ';
      if (b.feed_cap > 0.0)
        out << num(b.feed_cap * 60.0) << '\n';
      else
        out << "-\n";
    }
    first_block = false;
  };
  // The channel loop of `run` with the sinks off (the audit sink with --audit, in the same
  // pass): the same cycles, so the total equals run's last t to the cycle.
  ipo::ChannelConfig cfg = ipo::channel_config(in.machine, in.t_cycle);
  std::unique_ptr<ipo::Audit> audit;
  if (options.audit || options.audit_steps)
    audit = std::make_unique<ipo::Audit>(cfg.path.axes, cfg.path.channel.t_cycle, cfg.path.start);
  if (audit && cfg.path.joints)  // --- trafo: the joints are the machine axes
    audit->set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  Playing playing(in, src);
  ipo::Channel channel(std::move(cfg), src, audit.get());
  src.answer_positions_from(&channel.axes().command);  // --- planner: position barriers
  playing.attach(channel, in.port.get());
  if (audit) audit->set_setpoints(&channel.setpoints());  // axis limits on the setpoints
  if (audit) audit->set_belt(&channel.belt_share());      // --- conveyor: the belt's share
  const bool channel_plays = playing.player != nullptr;
  ipo::TimeCounter counter(channel.t_cycle(), on_block);
  // --- line: the time per workpiece on a channel that tracks a conveyor (cli/workpiece_report)
  const ipo::ConveyorSync* sync = in.port != nullptr ? channel.conveyor_sync() : nullptr;
  std::optional<WorkpieceReport> rows;
  std::optional<ipo::WorkpieceCycles> cycles;
  if (sync != nullptr) {
    try {
      rows.emplace(options.json);
    } catch (const std::runtime_error& e) {
      err << "ncsim: error: " << e.what() << '\n';
      return kExitUsage;
    }
    cycles.emplace(channel.t_cycle(), [&rows](const ipo::WorkpieceCycle& r) { rows->on_row(r); });
  }
  Progress progress(err);
  ipo::Status status;
  while ((status = channel.step()) == ipo::Status::running) {
    if (audit && channel.transformed()) audit->on_joints(channel.cycle(), channel.joints());
    counter.add(channel.cycle());
    if (cycles) cycles->add(sync->phase(), in.port->last_latch().workpiece);  // --- line
    progress.update(channel.cycle().t, channel.cycle().line);
  }
  progress.finish();
  const ipo::TimeResult r = counter.finish();
  // A program error ends the source: the blocks before it ran, then the channel stopped. A
  // run-time error stops the channel in the cycle it is raised.
  // A [stop] of the scenario ends the run before a program error the look-ahead decoded later.
  const bool failed =
      status == ipo::Status::error || (src.error() != nullptr && !channel.scenario_stop());
  std::string error_text;
  if (failed) error_text = failure_text(in, interp, src, channel);
  bool spooled = true;  // --- line: the workpiece rows were copied out

  if (options.json) {
    if (options.blocks) out << ']';
    out << ",\"status\":" << (failed ? "\"error\"" : "\"ok\"");
    if (failed) {
      out << ",\"error\":";
      json_string(out, first_line(error_text));
    }
    out << ",\"cycles\":" << r.cycles << ",\"total_s\":" << json_num(r.total)
        << ",\"distance_mm\":" << json_num(r.distance) << ",\"lost_s\":" << json_num(r.lost)
        << ",\"split_s\":";
    json_split(out, r.split);
    spooled = !cycles || rows->finish(cycles->finish(), out);  // --- line: before "stop"
    out << ",\"stop\":";
    json_string(out, stop_reason(failed, channel));
    out << "}\n";
  } else {
    out << in.file.name() << ": " << (failed ? "stopped after " : "") << seconds(r.total) << " s ("
        << r.cycles << " cycles of " << num(in.t_cycle * 1e3) << " ms), path " << human(r.distance)
        << " mm; rapid " << human(r.split.rapid) << " s, feed " << human(r.split.feed)
        << " s, dwell " << human(r.split.dwell) << " s, tech " << human(r.split.tech)
        << " s, exact stop " << human(r.split.exact_stop) << " s, waiting "
        << human(r.split.starved) << " s, held " << human(r.split.held) << " s";
    // Under a scenario: the time lost to override and holds (docs/ipo.md "Time lost").
    if (channel_plays) out << "; lost to override and holds " << human(r.lost) << " s";
    out << '\n';
    spooled = !cycles || rows->finish(cycles->finish(), out);  // --- line
    if (const auto& stop = channel.scenario_stop())
      out << "stop: " << scenario::to_string(*stop) << " (" << stop_source(*in.scenario) << ") at "
          << seconds(r.total) << " s\n";
  }
  if (!spooled) {  // --- line
    err << "ncsim: error: cannot read back the workpiece rows' temporary file\n";
    return kExitUsage;
  }
  err << interp_warnings(interp) << warning_text(interp, channel);  // --- trafo
  if (!failed && !channel.scenario_stop()) err << still_moving_text(in, channel);
  if (failed) {
    err << error_text;
    return kExitProgramErrors;
  }
  if (audit) {
    const ipo::Verdict& v = audit->verdict();
    print_audit(v, axis_names(in.machine), axis_units(in.machine), interp, options.json ? err : out,
                options.audit_steps);
    if (!v.ok()) return kExitAudit;
  }
  return kExitOk;
}

namespace {

/// Writes the CSV rows: buffered, numbers by std::to_chars. With --every N the rows of every Nth
/// cycle, and the last cycle of the run whatever its index (`write_last()`): the program end, the
/// last good cycle before a run-time error or the scenario's stop, so the CSV ends where the run
/// did (issue 12: "up to the stop ... never silently cut").
class CsvSink final : public ipo::Sink {
 public:
  CsvSink(std::FILE* f, std::size_t axes, std::uint64_t every, bool detail)
      : f_(f), axes_(axes), every_(every), detail_(detail) {
    buf_.reserve(kFlushAt + 4096);
  }
  void on_joint(const ipo::Joint&) override {}
  void on_cycle(const ipo::Cycle& c) override {
    capture(c);
    if (c.index % every_ != 0) {
      pending_ = true;
      return;
    }
    write_row();
  }
  /// The last cycle seen, when --every skipped it (call once, after the run's last cycle).
  void write_last() {
    if (pending_) write_row();
  }
  void text(const std::string& s) {
    buf_ += s;
    if (buf_.size() >= kFlushAt) flush();
  }
  /// Writes what is buffered; false (errno kept) on a write error, which sticks.
  bool flush() {
    if (!failed_ && f_ != nullptr && !buf_.empty() &&
        std::fwrite(buf_.data(), 1, buf_.size(), f_) != buf_.size()) {
      failed_ = true;
      errno_ = errno;
    }
    buf_.clear();
    return !failed_;
  }
  bool failed() const { return failed_; }
  int error_number() const { return errno_; }
  void set_failed(int e) {
    failed_ = true;
    errno_ = e;
  }
  std::uint64_t rows() const { return rows_; }
  /// The axes whose following error --detail writes (the channel's, read at each on_cycle).
  void set_axes(const ipo::AxesState* state) { axes_state_ = state; }
  /// The channel whose conveyor display variables --detail writes (null: none). --- line
  void set_conveyor(const ipo::Channel* channel) { conveyor_ = channel; }
  /// --- trafo: the setpoints the axes received (the joints under #TRAFO), read at each on_cycle.
  void set_setpoints(const std::array<axes::Setpoint, planner::kMaxAxes>* set) { set_ = set; }

 private:
  /// The values of cycle `c`'s row, read from the channel's state while it is that cycle's.
  void capture(const ipo::Cycle& c) {
    row_.t = c.t;
    row_.line = c.line;
    for (std::size_t i = 0; i < axes_; ++i) {
      // The machine axes' setpoints (the channel's; under #TRAFO the joints, not the TCP).
      row_.p[i] = set_ != nullptr ? (*set_)[i].p : c.x[i];
      if (!detail_) continue;
      row_.v[i] = set_ != nullptr ? (*set_)[i].v : c.v[i];
      row_.a[i] = set_ != nullptr ? (*set_)[i].a : c.a[i];
      row_.ferr[i] = axes_state_ != nullptr ? axes_state_->following_error[i] : 0.0;
    }
    if (!detail_) return;
    row_.v_path = c.path.v;
    row_.feed = c.feed;
    // --- line: the conveyor display variables with synchro_lag (seed 004 §6,
    // Channel::master_display, tracking/synchro_lag.hpp)
    if (conveyor_ != nullptr) row_.master = conveyor_->master_display();
  }
  void write_row() {
    pending_ = false;
    append_num(buf_, row_.t);
    buf_ += ',';
    buf_ += std::to_string(row_.line);
    for (std::size_t i = 0; i < axes_; ++i) {
      buf_ += ',';
      append_num(buf_, row_.p[i]);
    }
    if (detail_) {
      for (std::size_t i = 0; i < axes_; ++i) {
        buf_ += ',';
        append_num(buf_, row_.v[i]);
        buf_ += ',';
        append_num(buf_, row_.a[i]);
      }
      buf_ += ',';
      append_num(buf_, row_.v_path);
      buf_ += ',';
      append_num(buf_, row_.feed);
      for (std::size_t i = 0; i < axes_; ++i) {
        buf_ += ',';
        append_num(buf_, row_.ferr[i]);
      }
      if (conveyor_ != nullptr) {
        const ipo::MasterDisplay& d = row_.master;
        for (const double v :
             {d.current_pos_master, d.current_v_master, d.current_a_master, d.pos_master_comp,
              d.v_master_comp, d.a_master_comp, d.synchro_lag}) {
          buf_ += ',';
          append_num(buf_, v);
        }
      }
    }
    buf_ += '\n';
    ++rows_;
    if (buf_.size() >= kFlushAt) flush();
  }

  /// One row's values (the columns of the head).
  struct Row {
    double t = 0.0;                                ///< end of the cycle [s]
    std::uint32_t line = 0;                        ///< source line of the active block
    std::array<double, planner::kMaxAxes> p{};     ///< command positions [mm | deg]
    std::array<double, planner::kMaxAxes> v{};     ///< --detail: velocities [mm/s | deg/s]
    std::array<double, planner::kMaxAxes> a{};     ///< --detail: accelerations
    std::array<double, planner::kMaxAxes> ferr{};  ///< --detail: following errors [mm | deg]
    double v_path = 0.0;                           ///< --detail: path velocity [mm/s]
    double feed = 0.0;                             ///< --detail: programmed feed [mm/s]
    ipo::MasterDisplay master{};                   ///< --detail on a conveyor machine
  };

  static constexpr std::size_t kFlushAt = 1 << 20;
  std::FILE* f_;
  std::size_t axes_;
  std::uint64_t every_;
  bool detail_;
  const ipo::AxesState* axes_state_ = nullptr;
  const ipo::Channel* conveyor_ = nullptr;  // --- line: the channel's master_display()
  const std::array<axes::Setpoint, planner::kMaxAxes>* set_ = nullptr;
  std::string buf_;
  Row row_;               // the last cycle's values
  bool pending_ = false;  // row_ not written yet (--every skipped it)
  bool failed_ = false;
  int errno_ = 0;
  std::uint64_t rows_ = 0;
};

// --- indp: the technology functions output in the last step as comments
// `# tech t=<s> line=<n> M3` (docs/ipo.md "INDP axes and technology functions").
void write_tech(const ipo::Channel& channel, CsvSink& csv) {
  static constexpr char kLetter[] = {'M', 'H', 'S', 'T', 'D'};
  for (const ipo::TechOutput& o : channel.tech_outputs()) {
    std::string s = "# tech t=" + num(o.t) + " line=" + std::to_string(o.line);
    if (o.file != 0) s += " file=" + std::to_string(o.file);
    s += ' ';
    s += kLetter[static_cast<std::size_t>(o.kind)];
    s += num(o.value);
    if (o.extra) s += '=' + num(*o.extra);
    s += '\n';
    csv.text(s);
  }
}

}  // namespace

int run_run(const RunOptions& options, std::ostream& out, std::ostream& err) {
  if (options.every == 0) {
    err << "ncsim: error: --every must be at least 1\n";
    return kExitUsage;
  }
  auto loaded = load(options.program, options.cycle_us, err);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  const Loaded& in = std::get<Loaded>(loaded);

  // Output: stdout through `out`'s buffer is avoided: the CSV goes through a FILE*. "-" writes
  // to stdout; a file goes through core::OutputFile (a unique temporary file renamed when
  // complete; a pipe or device written in place; docs/design.md "Output files"). Every output
  // is opened before the run: an unwritable one is reported at once.
  const bool to_stdout = options.output == "-";
  std::optional<core::OutputFile> csv_file;
  std::optional<core::OutputFile> page_file;  // --- report:
  if (options.csv && !to_stdout) {
    auto opened = core::OutputFile::open(options.output);
    if (const auto* why = std::get_if<std::string>(&opened)) {
      err << "ncsim: error: " << *why << " [NC9150]\n";
      return kExitUsage;
    }
    csv_file.emplace(std::move(std::get<core::OutputFile>(opened)));
  }
  if (!options.report.empty()) {
    auto opened = core::OutputFile::open(options.report);
    if (const auto* why = std::get_if<std::string>(&opened)) {
      err << "ncsim: error: the report: " << *why << " [NC8100]\n";
      return kExitUsage;
    }
    page_file.emplace(std::move(std::get<core::OutputFile>(opened)));
  }
  std::FILE* f = nullptr;
  if (to_stdout && options.csv) {
    out.flush();
    f = stdout;
  } else if (csv_file) {
    f = csv_file->stream();
  }

  interp::Interpreter interp(in.file, in.machine, in.interp);
  ipo::ProgramSource src(interp, in.machine, in.t_cycle);
  src.refuse_beyond_soft_limits(true);  // check's NC4601 before the block moves (issue 34)
  ipo::ChannelConfig cfg = ipo::channel_config(in.machine, in.t_cycle);
  const std::vector<std::string> names = axis_names(in.machine);
  CsvSink csv(f, names.size(), options.every, options.detail);
  std::unique_ptr<ipo::Audit> audit;
  if (options.audit || options.audit_steps) {
    audit = std::make_unique<ipo::Audit>(cfg.path.axes, cfg.path.channel.t_cycle, cfg.path.start);
    if (cfg.path.joints)  // --- trafo: the joints are the machine axes
      audit->set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  }
  Tee tee(options.csv ? &csv : nullptr, audit.get());
  // --- report: the page's recorder sees the same joints and cycles (docs/report.md)
  std::unique_ptr<report::Recorder> recorder;
  if (!options.report.empty())
    recorder = std::make_unique<report::Recorder>(names, cfg.path.axes, cfg.path.channel.t_cycle,
                                                  cfg.path.start);
  if (recorder) recorder->set_limits(cfg);
  // --- trafo-jerk: on a kinematic machine the MCS toolpath before #TRAFO ON is the joints' TCP.
  if (recorder && cfg.path.joints) {
    if (const auto trafo = ipo::machine_trafo(in.machine, cfg.path))
      recorder->set_forward(ipo::forward_map(trafo->kinematics, trafo->xyz));
  }
  Tee with_report(&tee, recorder.get());

  std::string head = "# ncsim run\n# program: " + in.file.name() +
                     "\n# machine: " + in.machine.name + "\n# cycle: " + num(in.t_cycle) +
                     " s\n# units: mm | deg, s; v [mm/s], a [mm/s^2]\nt,line";
  for (const std::string& n : names)
    head += ',' + n;
  if (options.detail) {
    for (const std::string& n : names)
      head += ',' + n + ".v," + n + ".a";
    head += ",v_path,feed";
    for (const std::string& n : names)
      head += ',' + n + ".ferr";
  }

  Playing playing(in, src);
  ipo::Channel channel(std::move(cfg), src, &with_report);
  src.answer_positions_from(&channel.axes().command);  // --- planner: position barriers
  playing.attach(channel, in.port.get());
  if (audit) audit->set_setpoints(&channel.setpoints());  // axis limits on the setpoints
  if (audit) audit->set_belt(&channel.belt_share());      // --- conveyor: the belt's share
  if (recorder) recorder->set_setpoints(&channel.setpoints());
  if (recorder) recorder->set_belt(&channel.belt_share());
  if (recorder) recorder->set_tcp(&channel.tcp());
  if (recorder) recorder->set_conveyor(channel.conveyor_sync());
  // The conveyor display variables (seed 004 §6; docs/conveyor.md) with --detail on a channel
  // that tracks a conveyor: mm, mm/s, mm/s^2, 0 before the first measurement; synchro_lag
  // [mm] machine minus real workpiece (tracking/synchro_lag.hpp), 0 unless the frame moves.
  if (options.detail && in.port != nullptr && channel.conveyor_sync() != nullptr) {
    head +=
        ",current_pos_master,current_v_master,current_a_master,pos_master_comp,v_master_comp,"
        "a_master_comp,synchro_lag";  // --- line: synchro_lag
    csv.set_conveyor(&channel);
  }
  head += '\n';
  csv.text(head);
  csv.set_axes(&channel.axes());
  if (recorder) recorder->set_axes(&channel.axes());  // --- report:
  csv.set_setpoints(&channel.setpoints());
  Progress progress(err);
  ipo::Status s;
  while ((s = channel.step()) == ipo::Status::running && !csv.failed()) {
    if (channel.transformed()) {
      if (audit) audit->on_joints(channel.cycle(), channel.joints());
      if (recorder) recorder->on_joints(channel.cycle(), channel.joints());
    }
    progress.update(channel.cycle().t, channel.cycle().line);
    write_tech(channel, csv);  // --- indp
  }
  csv.write_last();          // --every N: the run's last cycle, whatever its index
  write_tech(channel, csv);  // --- indp: those of the program's final wait
  progress.finish();
  std::string error_text;
  const bool failed =
      s == ipo::Status::error ||
      (s == ipo::Status::finished && src.error() != nullptr && !channel.scenario_stop());
  if (failed) {
    error_text = failure_text(in, interp, src, channel);
    csv.text("# error: " + first_line(error_text) + "\n");
    // --- workspace: an error while synchronised: the motion after it (004 §2.3)
    if (const std::string note = channel.after_error_note(); !note.empty()) {
      csv.text("# after the error: " + note + "\n");
      error_text += "ncsim: note: " + note + "\n";
    }
  } else if (const auto& stop = channel.scenario_stop()) {
    err << "ncsim: run stopped (" << stop_source(*in.scenario)
        << "): " << scenario::to_string(*stop) << " at t=" << seconds(channel.cycle().t) << " s\n";
  }
  // The closing comment: why the run ended (program end, error, stop.time, ...), when it did
  // (not after a write error, which ends the loop early).
  if (s != ipo::Status::running) csv.text("# stop: " + stop_reason(failed, channel) + "\n");
  csv.flush();
  if (to_stdout && !csv.failed() && std::fflush(f) != 0) csv.set_failed(errno);
  if (csv.failed()) {
    err << "ncsim: error: cannot write '"
        << (to_stdout ? std::string("stdout") : csv_file->written().string())
        << "': " << std::strerror(csv.error_number()) << " [NC9151]\n";
    return kExitUsage;  // the temporary file goes with csv_file
  }
  if (csv_file) {
    std::string why;
    if (!csv_file->commit(why)) {
      err << "ncsim: error: " << why << " [NC9151]\n";
      return kExitUsage;
    }
  }
  // --- report: the page, also after a run-time error (it shows it)
  if (recorder) {
    const auto& stop = channel.scenario_stop();
    const report::ReportData data = recorder->finish(
        {in.file.name(), in.machine.name,
         stop ? std::string(scenario::to_string(*stop)) : std::string(), error_text});
    std::string why;
    if (!report::write_html_file(data, *page_file, why)) {
      err << "ncsim: error: " << why << '\n';
      return kExitUsage;
    }
    (options.csv ? err : out) << "report: " << options.report << '\n';
  }
  err << interp_warnings(interp) << warning_text(interp, channel);  // --- trafo
  if (!failed && !channel.scenario_stop()) err << still_moving_text(in, channel);
  if (!error_text.empty()) {
    err << error_text;
    return kExitProgramErrors;
  }
  if (audit) {
    print_audit(audit->verdict(), names, axis_units(in.machine), interp, err, options.audit_steps);
    if (!audit->verdict().ok()) return kExitAudit;
  }
  return kExitOk;
}

// --- report:
int run_report(const ReportOptions& options, std::ostream& out, std::ostream& err) {
  RunOptions run;
  run.program = options.program;
  run.cycle_us = options.cycle_us;
  run.report = options.output;
  run.csv = false;
  if (run.report.empty()) {
    err << "ncsim: error: report: -o needs a file name [NC8101]\n";
    return kExitUsage;
  }
  return run_run(run, out, err);
}

std::vector<std::uint32_t> machine_data_lines(const ProgramOptions& program, std::string_view id,
                                              std::size_t max_commands) {
  std::ostringstream quiet;  // the runs report the load's diagnostics
  auto loaded = load(program, std::nullopt, quiet);
  std::vector<std::uint32_t> lines;
  if (std::holds_alternative<int>(loaded)) return lines;
  const Loaded& in = std::get<Loaded>(loaded);
  interp::Interpreter interp(in.file, in.machine, in.interp);
  for (std::size_t n = 0; n < max_commands; ++n) {
    const auto c = interp.next_decode_only();
    if (!c) break;
    const auto* md = std::get_if<interp::MachineData>(&c->body);
    if (md == nullptr || c->file != 0) continue;
    for (const interp::MachineSetting& setting : md->settings)
      if (setting.id == id && (lines.empty() || lines.back() != c->line)) lines.push_back(c->line);
  }
  return lines;
}

// --- line: one headless run (cli/run_commands.hpp LineRun)
LineOutcome run_line(const ProgramOptions& program, std::optional<std::uint64_t> cycle_us,
                     const LineRun& run, std::ostream& err) {
  LineOutcome o;
  auto loaded = load(program, cycle_us, err);
  if (const int* status = std::get_if<int>(&loaded)) {
    o.status = *status;
    o.error = "the program, machine or scenario could not be loaded";
    return o;
  }
  Loaded& in = std::get<Loaded>(loaded);
  if (run.adjust) {
    run.adjust(in.machine, in.scenario, in.t_cycle);
    if (in.machine.conveyor_axis() != nullptr) {
      try {
        in.port =
            conveyor::make_port(in.machine, in.scenario ? &*in.scenario : nullptr, in.t_cycle);
      } catch (const std::invalid_argument& e) {
        o.status = kExitUsage;
        o.error = std::string("the conveyor: ") + e.what();
        return o;
      }
    }
  }
  if (run.wrap && in.port) in.port = run.wrap(std::move(in.port));
  if (run.conv_vel) in.interp.conv_vel = run.conv_vel;
  interp::Interpreter interp(in.file, in.machine, in.interp);
  ipo::ProgramSource src(interp, in.machine, in.t_cycle);
  src.refuse_beyond_soft_limits(true);  // check's NC4601 before the block moves (issue 34)
  ipo::ChannelConfig cfg = ipo::channel_config(in.machine, in.t_cycle);
  std::unique_ptr<ipo::Audit> audit;
  if (run.audit) {
    audit = std::make_unique<ipo::Audit>(cfg.path.axes, cfg.path.channel.t_cycle, cfg.path.start);
    if (cfg.path.joints) audit->set_joint_limits(cfg.path.joints->joints, cfg.path.start, true);
  }
  Playing playing(in, src);
  ipo::Channel channel(std::move(cfg), src, audit.get());
  playing.attach(channel, in.port.get());
  if (audit) audit->set_setpoints(&channel.setpoints());
  if (audit) audit->set_belt(&channel.belt_share());  // --- conveyor: the belt's share
  ipo::Status status;
  while ((status = channel.step()) == ipo::Status::running) {
    if (audit && channel.transformed()) audit->on_joints(channel.cycle(), channel.joints());
    if (run.on_cycle) run.on_cycle(channel);
  }
  o.t_end = channel.cycle().t;
  const bool failed =
      status == ipo::Status::error || (src.error() != nullptr && !channel.scenario_stop());
  if (failed) {
    o.status = kExitProgramErrors;
    o.error = first_line(failure_text(in, interp, src, channel));
    if (const auto& e = channel.run_time_error()) {
      o.id = e->id;
    } else if (const core::Diagnostic* d = src.error() ? src.error() : interp.error()) {
      o.id = d->id;
    }
    return o;
  }
  if (audit && !audit->verdict().ok()) {
    const ipo::Verdict& v = audit->verdict();
    o.status = kExitAudit;
    o.audit_violations = v.violation_count;
    if (!v.violations.empty()) {
      const ipo::Violation& x = v.violations.front();
      const std::vector<std::string> names = axis_names(in.machine);
      o.error = "audit: t=" + num(x.t) + " s line " + block_where(interp, x.file, x.line) +
                " axis " + (x.axis < names.size() ? names[x.axis] : std::to_string(x.axis)) + " " +
                ipo::quantity_name(x.quantity) + " " + num(x.value) + " > " + num(x.limit);
    }
  }
  return o;
}

void add_run_program_options(CLI::App& cmd, ProgramOptions& program) {
  cmd.add_option("program", program.program, "NC program file (.nc)")->required();
  cmd.add_option("--machine", program.machine_dir,
                 "Machine folder (parameter lists); default: the program folder's 'machine' "
                 "file, else the bundled portal_3x");
  cmd.add_option("--scenario", program.scenario,
                 "Scenario TOML file (docs/scenario.md); default: the program folder's "
                 "scenario.toml");
  add_cycle_options(cmd, program);
  cmd.add_option("--max-time", program.max_time,
                 "Stop the run after S seconds of machine time (an endless production loop), "
                 "like a scenario's [stop] time; the reason is printed")
      ->check(CLI::Range(1e-6, 1e9));
}

void add_cycle_options(CLI::App& cmd, ProgramOptions& program) {
  cmd.add_option("--cycles", program.cycle_dirs,
                 "Folder of the machine builder's cycle files (G80-G89, G800-G839, L CYCLE), "
                 "looked in before the machine folder's cycles/ and the program's folder "
                 "(repeatable)")
      ->check(CLI::ExistingDirectory);
  cmd.add_option("--missing-cycles", program.missing_cycles,
                 "A cycle whose file is not configured or not found: error (default) or skip "
                 "(a zero-time step with warning NC4307 once per G code)")
      ->check(CLI::IsMember({"error", "skip"}));
}

void add_cycle_us_option(CLI::App& cmd, std::optional<std::uint64_t>& cycle_us) {
  cmd.add_option("--cycle-us", cycle_us,
                 "Interpolation cycle [us], 1 .. 1000000 (default: the channel list's "
                 "ncsim.cycle_time, 1000 when it has none)")
      ->check(CLI::Validator([](const std::string& text) { return cycle_us_error(text); }, "US",
                             "cycle"));
}

RunCommands::RunCommands(CLI::App& app) {
  time_cmd_ = app.add_subcommand("time", "Machining time, total and per block");
  add_run_program_options(*time_cmd_, time_.program);
  time_cmd_->add_flag("--blocks", time_.blocks, "Per executed block: time, distance, feeds, split");
  time_cmd_->add_flag("--json", time_.json, "JSON instead of text");
  time_cmd_->add_flag("--audit", time_.audit, "Check every limit; exit 3 on a violation");
  time_cmd_->add_flag("--audit-steps", time_.audit_steps,
                      "As --audit, and list every documented step (the first 1000)");
  add_cycle_us_option(*time_cmd_, time_.cycle_us);

  run_cmd_ = app.add_subcommand("run", "Run on the path interpolator and write the CSV trajectory");
  add_run_program_options(*run_cmd_, run_.program);
  run_cmd_->add_option("-o,--output", run_.output, "CSV file, '-' for stdout (default)");
  run_cmd_
      ->add_option("--every", run_.every, "One row every N cycles, and the last cycle (default 1)")
      ->check(
          CLI::Validator([](const std::string& text) { return every_error(text); }, "N", "every"));
  add_cycle_us_option(*run_cmd_, run_.cycle_us);
  run_cmd_->add_flag("--audit", run_.audit, "Check every limit (verdict on stderr); exit 3");
  run_cmd_->add_flag("--audit-steps", run_.audit_steps,
                     "As --audit, and list every documented step (the first 1000)");
  run_cmd_->add_flag(
      "--detail", run_.detail,
      "Add each axis's v and a, the path velocity, the programmed feed and each axis's "
      "following error");
  run_cmd_->add_option(
      "--report", run_.report,
      "Also write the HTML run report of the same pass (docs/report.md)");  // --- report:

  // --- report:
  report_cmd_ = app.add_subcommand(
      "report", "Run on the path interpolator and write the HTML run report (docs/report.md)");
  add_run_program_options(*report_cmd_, report_.program);
  report_cmd_->add_option("-o,--output", report_.output, "HTML file (default report.html)");
  add_cycle_us_option(*report_cmd_, report_.cycle_us);
}

std::optional<int> RunCommands::dispatch(std::ostream& out, std::ostream& err) const {
  if (time_cmd_->parsed()) return run_time(time_, out, err);
  if (run_cmd_->parsed()) return run_run(run_, out, err);
  if (report_cmd_->parsed()) return run_report(report_, out, err);  // --- report:
  return std::nullopt;
}

}  // namespace ncsim::cli
