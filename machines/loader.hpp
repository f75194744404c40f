#pragma once
// machines/loader: reads a machine folder (index file + ISG lists) into a Machine.
//
// Inputs: a folder holding `machine.lis` (the index, docs/machines.md "Machine folder") and the
// channel and axis lists it names. Outputs: LoadResult with the Machine when there are no
// errors, and every diagnostic found (all lists are read and checked; loading does not stop
// at the first error). Diagnostics carry the list file and line; the id is the manual's where
// it has one (21483, 292005), else NC3xxx (docs/diagnostics.md); messages name the key and its
// parameter id.
// Invariants: a returned Machine satisfies the invariants listed in machine.hpp.
// Usage (CLI):
//   auto loaded = ncsim::machines::load_machine(dir);
//   for (const auto& d : loaded.diagnostics.items()) std::cerr << core::format(d);
//   if (!loaded.machine) return 2;
//   if (auto lim = loaded.machine->soft_limits("X")) ... lim->neg, lim->pos [mm]

#include <filesystem>
#include <optional>

#include "core/diagnostic.hpp"
#include "machines/machine.hpp"

namespace ncsim::machines {

struct LoadResult {
  std::optional<Machine> machine;    ///< set when diagnostics has no errors
  core::DiagnosticList diagnostics;  ///< errors and warnings of all lists
};

/// Name of the index file in a machine folder.
inline constexpr const char* kMachineIndexFile = "machine.lis";

/// Loads the machine in `dir`. Never throws for bad or missing files: they are diagnostics.
LoadResult load_machine(const std::filesystem::path& dir);

/// Folder of a bundled machine ("laser_portal", "delta_picker", "static_saw", "portal_3x")
/// below a source tree root.
std::filesystem::path bundled_machine_dir(const std::filesystem::path& source_root,
                                          std::string_view name);

/// The bundled machine used when a program names none.
inline constexpr std::string_view kDefaultMachine = "portal_3x";

}  // namespace ncsim::machines
