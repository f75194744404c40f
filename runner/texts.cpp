#include "runner/texts.hpp"

#include <cmath>
#include <stdexcept>

#include "core/diagnostic.hpp"
#include "core/number_text.hpp"
#include "runner/run.hpp"

namespace ncsim::runner {
namespace {

using core::human;
using core::num;
using core::seconds;

// The program error that ended a run, with its source line when it is in the main program.
std::string diagnostic_text(const Run& run, const std::string& fallback) {
  const interp::Interpreter& interp = run.interpreter();
  const core::SourceFile& main_file = run.loaded().file;
  const core::Diagnostic* d = run.source().error();
  if (d == nullptr) d = interp.error();
  if (d == nullptr) return "ncsim: error: " + fallback + "\n";
  std::string text;
  if (d->file == main_file.name()) {
    text = core::format(*d, main_file);
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
    if (e.severity == core::Severity::error && e.file != main_file.name() && !same)
      text += core::format(e);
  }
  return text;
}

// A run-time position as a diagnostic in its own file (the main program or a subroutine
// file), echoing the block's text.
std::string positioned(const interp::Interpreter& interp, const channel::RunTimeError& e,
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

}  // namespace

std::string failure_text(const Run& run) {
  if (const auto& e = run.channel().run_time_error())
    return positioned(run.interpreter(), *e, core::Severity::error,
                      "run-time error at t=" + seconds(e->t) + " s: " + e->message);
  return diagnostic_text(run, run.channel().message());
}

std::string warnings_text(const Run& run) {
  std::string out;
  for (const core::Diagnostic& d : run.interpreter().diagnostics().items())
    if (d.severity == core::Severity::warning) out += core::format(d);
  // The channel's warning (NC6210: a joint beyond its dynamics while synchronised
  // under #TRAFO ON), positioned like a run-time error; the run goes on.
  if (const auto& w = run.channel().trafo_warning())
    out += positioned(run.interpreter(), *w, core::Severity::warning,
                      "at t=" + seconds(w->t) + " s: " + w->message);
  return out;
}

std::string still_moving_text(const Run& run) {
  constexpr double kStanding = 1e-6;  // [mm/s | deg/s] below this an axis stands
  const channel::Channel& ch = run.channel();
  const std::vector<std::string> names = axis_names(run.loaded().machine);
  const std::vector<std::string> units = axis_units(run.loaded().machine);
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

std::string endless_note(const Ending& end) {
  if (!end.endless_from) return {};
  return "ncsim: note: the program runs endlessly from line " + std::to_string(*end.endless_from) +
         ": it came back there in the same state with nothing outside the program between, so "
         "the run ended there, after whole repetitions (NC4904); --max-time S or a scenario "
         "[stop] runs it longer\n";
}

std::string stop_source(const scenario::Scenario& s) {
  return s.file.empty() ? std::string("--max-time") : "scenario '" + s.file + "'";
}

std::string stop_reason(bool failed, const channel::Channel& ch, bool endless) {
  if (failed) return std::string(scenario::to_string(scenario::StopReason::error));
  if (const auto& s = ch.scenario_stop()) return std::string(scenario::to_string(*s));
  if (endless) return std::string(scenario::to_string(scenario::StopReason::endless));
  return std::string(scenario::to_string(scenario::StopReason::program_end));
}

std::string block_where(const interp::Interpreter& interp, std::uint16_t file, std::uint32_t line) {
  if (file == 0) return std::to_string(line);
  return interp.file_name(file) + ':' + std::to_string(line);
}

std::vector<std::string> axis_names(const machines::Machine& m) {
  std::vector<std::string> out;
  for (const std::uint8_t i : program::interpolated_axes(m))
    out.push_back(m.axes[i].name);
  return out;
}

std::vector<std::string> axis_units(const machines::Machine& m) {
  std::vector<std::string> out;
  for (const std::uint8_t i : program::interpolated_axes(m))
    out.push_back(m.axes[i].kind == machines::AxisKind::rotary ? "deg" : "mm");
  return out;
}

std::string first_line(const std::string& s) {
  return s.substr(0, s.find('\n'));
}

std::string first_violation(const Run& run) {
  if (run.audit() == nullptr || run.audit()->verdict().violations.empty()) return {};
  const audit::Violation& x = run.audit()->verdict().violations.front();
  const std::vector<std::string> names = axis_names(run.loaded().machine);
  return "audit: t=" + num(x.t) + " s line " + block_where(run.interpreter(), x.file, x.line) +
         " axis " + (x.axis < names.size() ? names[x.axis] : std::to_string(x.axis)) + " " +
         audit::quantity_name(x.quantity) + " " + num(x.value) + " > " + num(x.limit);
}

}  // namespace ncsim::runner
