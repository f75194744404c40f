#include "cli/line_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>

#include "cli/json_text.hpp"
#include "cli/number_format.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {
namespace {

std::uint64_t taken_by(const runner::LineRun& line, std::size_t k) {
  const auto s = line.station(k);
  return s && line.belt() != nullptr ? line.belt()->taken(*s) : 0;
}

std::string channel_label(const scenario::LineChannel& c) {
  const std::string number = "channel " + std::to_string(c.number);
  return number + (c.name == number ? "" : " " + c.name);
}

void print_belt_text(const runner::LineRun& line, std::ostream& out) {
  const conveyor::LineWorld& b = *line.belt();
  out << "  belt: " << b.arrived() << " workpiece" << (b.arrived() == 1 ? "" : "s") << " arrived, "
      << b.taken_total() << " taken (";
  bool first = true;
  for (std::size_t k = 0; k < line.size(); ++k) {
    if (!line.station(k)) continue;
    out << (first ? "" : ", ") << channel_label(line.channel_spec(k)) << ' ' << taken_by(line, k);
    first = false;
  }
  out << "), " << b.missed() << " missed, " << b.on_belt() << " on the belt (" << b.held()
      << " held); "
      << human(std::round(line_per_minute(b.taken_total(), line.t_end()) * 100.0) / 100.0)
      << " workpieces per minute\n";
  for (const conveyor::WorkpieceFate& f : b.fates()) {
    out << "  workpiece " << f.workpiece << ": arrived " << seconds(f.t_arrived) << " s, ";
    switch (f.fate) {
      case conveyor::Fate::taken:
        out << "taken by channel " << int{f.channel} << " at " << seconds(f.t) << " s\n";
        break;
      case conveyor::Fate::missed:
        out << "missed at " << seconds(f.t) << " s (past the belt's end)\n";
        break;
      case conveyor::Fate::held:
        out << "on the belt at the end, held by channel " << int{f.channel} << " (measured at "
            << seconds(f.t) << " s)\n";
        break;
      case conveyor::Fate::free:
        out << "on the belt at the end\n";
        break;
    }
  }
  if (b.fates().size() < b.arrived())
    out << "  ... " << (b.arrived() - b.fates().size()) << " more workpieces (counted above)\n";
}

void print_belt_json(const runner::LineRun& line, std::ostream& out) {
  const conveyor::LineWorld& b = *line.belt();
  out << ",\"workpieces\":{\"arrived\":" << b.arrived() << ",\"taken\":" << b.taken_total()
      << ",\"missed\":" << b.missed() << ",\"on_belt\":" << b.on_belt() << ",\"held\":" << b.held()
      << ",\"per_minute\":" << json_num(line_per_minute(b.taken_total(), line.t_end()))
      << ",\"fates\":[";
  for (std::size_t i = 0; i < b.fates().size(); ++i) {
    const conveyor::WorkpieceFate& f = b.fates()[i];
    out << (i == 0 ? "" : ",") << "{\"workpiece\":" << f.workpiece
        << ",\"arrived_s\":" << json_num(f.t_arrived) << ",\"fate\":";
    json_string(out, f.fate == conveyor::Fate::free ? "on_belt" : conveyor::fate_name(f.fate));
    if (f.channel != 0) out << ",\"channel\":" << int{f.channel};
    if (f.fate != conveyor::Fate::free) out << ",\"t_s\":" << json_num(f.t);
    out << '}';
  }
  out << "]}";
}

}  // namespace

double line_utilisation(const runner::LineRun& line, std::size_t k) {
  const double t_line = line.t_end();
  const runner::LineChannelTime& t = line.time(k);
  return t_line > 0.0 ? std::max(0.0, std::round((t.t_end - t.t_waiting) / t_line * 1000.0)) / 10.0
                      : 0.0;
}

double line_per_minute(std::uint64_t n, double t_line) {
  return t_line > 0.0 ? 60.0 * static_cast<double>(n) / t_line : 0.0;
}

void print_line_text(const runner::LineRun& line, std::ostream& out) {
  const double t_line = line.t_end();
  const auto cycles = static_cast<std::uint64_t>(std::llround(t_line / line.t_cycle()));
  out << line.file().file << ": " << seconds(t_line) << " s (" << cycles << " cycles of "
      << human(line.t_cycle() * 1e3) << " ms), " << line.size() << " channel"
      << (line.size() == 1 ? "" : "s") << '\n';
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::LineChannelTime& t = line.time(k);
    out << "  " << channel_label(line.channel_spec(k)) << ": end " << seconds(t.t_end)
        << " s, waiting " << seconds(t.t_waiting) << " s, utilisation "
        << human(line_utilisation(line, k)) << " %, "
        << line.channel(k).ending(line.status(k)).stop;
    if (line.station(k))
      out << ", took " << taken_by(line, k) << " (sensor at "
          << human(line.channel_spec(k).sensor_at) << " mm)";
    out << '\n';
  }
  if (line.belt() != nullptr) print_belt_text(line, out);
}

void print_line_json(const runner::LineRun& line, std::ostream& out) {
  out << "{\"line\":";
  json_string(out, line.file().file);
  out << ",\"cycle_s\":" << json_num(line.t_cycle()) << ",\"end_s\":" << json_num(line.t_end())
      << ",\"channels\":[";
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::LineChannelTime& t = line.time(k);
    const scenario::LineChannel& c = line.channel_spec(k);
    const runner::Ending end = line.channel(k).ending(line.status(k));
    out << (k == 0 ? "" : ",") << "{\"number\":" << int{c.number} << ",\"name\":";
    json_string(out, c.name);
    out << ",\"end_s\":" << json_num(t.t_end) << ",\"waiting_s\":" << json_num(t.t_waiting)
        << ",\"utilisation_percent\":" << json_num(line_utilisation(line, k)) << ",\"stop\":";
    json_string(out, end.stop);
    if (end.failed) {
      out << ",\"error\":";
      json_string(out, runner::first_line(end.error_text));
    }
    if (line.station(k))
      out << ",\"sensor_at_mm\":" << json_num(c.sensor_at) << ",\"taken\":" << taken_by(line, k)
          << ",\"per_minute\":" << json_num(line_per_minute(taken_by(line, k), line.t_end()));
    out << '}';
  }
  out << ']';
  if (line.belt() != nullptr) print_belt_json(line, out);
  out << "}\n";
}

}  // namespace ncsim::cli
