#pragma once
// scenario/line_file: a production line's TOML file (docs/lines.md "The line file"), read and
// validated like a scenario.
//
// Purpose: the channels of a line (number, name, program, machine folder, the channel's own
// scenario) and the one conveyor world they share: the scenario's `[conveyor]` table, read by
// the scenario's own reader (docs/scenario.md "[conveyor]"). The files named are not opened
// here (runner/ does, with the positions kept here).
// Inputs: the file (path or text with its name). Outputs: LineFile when there are no errors,
// and every diagnostic of the file, each at file:line:col with its key (`channel[2].program`):
// TOML syntax (NC7001), unknown keys (NC7101, "did you mean"), wrong types (NC7003), values
// out of range (NC7004), a missing key (NC7102), a channel number given twice (NC7103), no
// channel (NC7104), the conveyor's own (NC70xx). Never throws for bad input.
// Invariants: 1 .. interp::kMaxChannels channels with distinct numbers 1 .. kMaxChannels, in
// file order; paths as written (relative to the line file's folder: resolved()).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::scenario {

/// Most channels of a line (interp::kMaxChannels, the CH=.. range).
inline constexpr std::uint8_t kLineChannelsMax = 12;

/// A path of the line file with the position of its value.
struct LinePath {
  std::string text;     ///< as written
  core::SourceLoc loc;  ///< the value's position in the line file
};

/// One `[[channel]]`.
struct LineChannel {
  std::uint8_t number = 1;           ///< `number`, 1 .. kLineChannelsMax (the CH of #SIGNAL)
  std::string name;                  ///< `name` (default "channel <number>")
  LinePath program;                  ///< `program`: the NC program
  LinePath machine;                  ///< `machine`: the machine folder
  std::optional<LinePath> scenario;  ///< `scenario`: the channel's own (no [conveyor])
  double sensor_at = 0.0;  ///< `sensor_at` [mm]: its sensor's belt travel after the line's sensor
  core::SourceLoc loc;     ///< its `[[channel]]` header
};

/// The line file.
struct LineFile {
  std::string file;                       ///< the file it was read from, as given
  std::string description;                ///< `description`
  std::optional<std::uint64_t> cycle_us;  ///< `cycle_us`: the line's cycle [us] over the machines'
  core::SourceLoc cycle_loc;              ///< its position
  std::vector<LineChannel> channels;      ///< in file order
  std::optional<Conveyor> conveyor;       ///< `[conveyor]`: the shared world
  std::optional<double> belt_end;  ///< `belt_end` [mm]: the belt's end after the line's sensor
  core::SourceLoc belt_end_loc;    ///< its position
  /// `path` of the file relative to the line file's folder (absolute paths unchanged).
  std::filesystem::path resolved(const LinePath& path) const;
};

struct LineLoad {
  std::optional<LineFile> line;      ///< set when diagnostics has no errors
  core::DiagnosticList diagnostics;  ///< every error and warning of the file
};

/// Validates `file` (its name is the one diagnostics show).
LineLoad parse_line(const core::SourceFile& file);
/// Loads and validates the file at `path`; a file that cannot be read is NC7010.
LineLoad load_line(const std::filesystem::path& path);

}  // namespace ncsim::scenario
