#include "runner/line.hpp"

#include <exception>
#include <ostream>

#include "runner/load.hpp"
#include "runner/run.hpp"
#include "runner/texts.hpp"

namespace ncsim::runner {

std::string error_id(const Run& run) {
  if (const auto& e = run.channel().run_time_error()) return e->id;
  if (const core::Diagnostic* d =
          run.source().error() ? run.source().error() : run.interpreter().error())
    return d->id;
  return {};
}

LineOutcome run_line(const RunSpec& spec,
                     const std::function<void(const channel::Channel&)>& on_cycle,
                     std::ostream& err) {
  LineOutcome o;
  LoadResult loaded = load(spec);
  err << loaded.messages;
  if (loaded.thrown) std::rethrow_exception(loaded.thrown);
  if (!loaded.ok()) {
    o.status = loaded.exit;
    o.error = loaded.failure;
    return o;
  }
  Run run(std::move(loaded.loaded), spec);
  run.start();
  const ipo::Status status = run.run(on_cycle);
  o.t_end = run.channel().cycle().t;
  const Ending end = run.ending(status);
  if (end.failed) {
    o.status = Exit::program_errors;
    o.error = first_line(end.error_text);
    o.id = error_id(run);
    return o;
  }
  if (run.audit() && !run.audit()->verdict().ok()) {
    o.status = Exit::audit;
    o.audit_violations = run.audit()->verdict().violation_count;
    o.error = first_violation(run);
  }
  return o;
}

std::vector<std::uint32_t> machine_data_lines(const ProgramSpec& program, std::string_view id,
                                              std::size_t max_commands) {
  RunSpec spec;
  spec.program = program;
  LoadResult loaded = load(spec);  // its diagnostics are the runs' to report
  if (loaded.thrown) std::rethrow_exception(loaded.thrown);
  std::vector<std::uint32_t> lines;
  if (!loaded.ok()) return lines;
  const Loaded& in = *loaded.loaded;
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

}  // namespace ncsim::runner
