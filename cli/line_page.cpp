// cli/line_page: the line page's recorders (see the header).

#include "cli/line_page.hpp"

#include <sstream>

#include "cli/line_report.hpp"
#include "cli/run_commands.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {

LinePage::LinePage(const runner::LineRun& line)
    : lanes_(line.size(), line.belt() != nullptr), state_(line.size(), report::LaneState::running) {
  for (std::size_t k = 0; k < line.size(); ++k)
    recorders_.push_back(
        make_recorder(line.channel(k), runner::axis_names(line.channel(k).loaded().machine)));
}

void LinePage::wire(const runner::LineRun& line) {
  for (std::size_t k = 0; k < line.size(); ++k)
    wire_recorder(line.channel(k), *recorders_[k]);
}

void LinePage::on_cycle(const runner::LineRun& line) {
  for (std::size_t k = 0; k < line.size(); ++k) {
    const bool running = line.status(k) == ipo::Status::running;
    // Under #TRAFO ON the recorder's audit checks the joints apart (as run --report's).
    const channel::Channel& ch = line.channel(k).channel();
    if (running && ch.transformed()) recorders_[k]->on_joints(ch.cycle(), ch.joints());
    state_[k] = !running          ? report::LaneState::ended
                : line.waiting(k) ? report::LaneState::waiting
                                  : report::LaneState::running;
  }
  const conveyor::BeltState* belt = line.belt_state();
  lanes_.add(line.t(), belt != nullptr ? belt->p : 0.0, belt != nullptr ? belt->v : 0.0, state_);
}

report::LineReportData LinePage::finish(const runner::LineRun& line) {
  std::vector<report::ReportData> channels;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::Run& run = line.channel(k);
    const runner::Ending end = run.ending(line.status(k));
    const auto& stop = run.channel().scenario_stop();
    channels.push_back(recorders_[k]->finish(
        {run.loaded().file.name(), run.loaded().machine.name,
         stop ? std::string(scenario::to_string(*stop)) : std::string(), end.error_text}));
  }
  std::ostringstream summary;
  print_line_json(line, summary);
  std::string json = summary.str();
  if (!json.empty() && json.back() == '\n') json.pop_back();
  return lanes_.finish(line.file().file, line.file().description, std::move(json),
                       std::move(channels));
}

}  // namespace ncsim::cli
