// programs_tests: every NC program in programs/ passes the syntax and structure check, each
// program folder is complete (one program named after the folder, a machine file naming a
// bundled machine), and the generated benchmark program checks clean (so the benchmark
// measures the clean path, not error recovery).

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/grammar_generator.hpp"
#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/check.hpp"

namespace fs = std::filesystem;

namespace {

// The machines bundled under machines/ (laser_queue: report-lib, laser_portal_encoder: line,
// delta_picker_belt: trafo-conveyor, laser_portal_simple and laser_portal_workspace: workspace,
// static_saw_encoder: the static synchro_lag listing, portal_3x_override: override above 100 %,
// portal_3x_slow: issue 12's 200-move benchmark limits, portal_3x_tools: a tool list for tool
// radius compensation, docs/trc.md; dispenser_3x, mill_3x, laser_flatbed: programs/real).
constexpr std::array<std::string_view, 17> kMachines = {"laser_portal",
                                                        "delta_picker",
                                                        "static_saw",
                                                        "portal_3x",
                                                        "laser_queue",
                                                        "laser_portal_encoder",
                                                        "delta_picker_belt",
                                                        "laser_portal_simple",
                                                        "laser_portal_workspace",
                                                        "static_saw_encoder",
                                                        "portal_3x_override",
                                                        "portal_3x_slow",
                                                        "portal_3x_tools",
                                                        "dispenser_3x",
                                                        "mill_3x",
                                                        "laser_flatbed",
                                                        "arm6_belt"};

// The seed's listings (TF5264, seed 004) and the reference's section 10 example: these must
// never silently disappear from programs/.
constexpr std::array<std::string_view, 9> kSeedPrograms = {
    "kontur_2",       "sync_wait",  "synchro_lag_static", "synchro_lag_comoving", "laser",
    "pick_and_place", "static_saw", "touch_probe_mode",   "isg_reference_example"};

fs::path programs_dir() {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  REQUIRE_MESSAGE(root != nullptr, "NCSIM_SOURCE_DIR must point to the repository root");
  return fs::path(root) / "programs";
}

std::vector<fs::path> program_folders() {
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(programs_dir())) {
    if (!entry.is_directory()) continue;
    // programs/lines/<name>/: production lines, several programs and a line file each, checked
    // by their own `ncsim line check` test (tests/lines.cmake, docs/lines.md)
    if (entry.path().filename() == "lines") continue;
    if (entry.path().filename() == "real") {  // programs/real/<name>/: the real-program library
      for (const auto& sub : fs::directory_iterator(entry.path()))
        if (sub.is_directory()) folders.push_back(sub.path());
      continue;
    }
    folders.push_back(entry.path());
  }
  std::sort(folders.begin(), folders.end());
  return folders;
}

std::vector<fs::path> nc_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".nc") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string formatted(const ncsim::core::DiagnosticList& list,
                      const ncsim::core::SourceFile& file) {
  std::string text;
  for (const auto& d : list.items())
    text += ncsim::core::format(d, file);
  return text;
}

}  // namespace

TEST_CASE("every program in programs/ checks without a diagnostic") {
  std::size_t checked = 0;
  for (const auto& folder : program_folders()) {
    for (const auto& path : nc_files(folder)) {
      const auto file = ncsim::core::SourceFile::load(path);
      const auto diagnostics = ncsim::grammar::check_program(file);
      CHECK_MESSAGE(diagnostics.items().empty(), "\n" << formatted(diagnostics, file));
      ++checked;
    }
  }
  CHECK(checked >= kSeedPrograms.size());
}

TEST_CASE("every seed listing is transcribed in programs/") {
  for (const auto name : kSeedPrograms) {
    const auto path = programs_dir() / name / (std::string(name) + ".nc");
    CHECK_MESSAGE(fs::is_regular_file(path), path.string());
  }
}

TEST_CASE("each program folder holds one program named after it and names a bundled machine") {
  for (const auto& folder : program_folders()) {
    const auto name = folder.filename().string();
    CAPTURE(name);
    const auto files = nc_files(folder);
    REQUIRE(files.size() == 1);
    CHECK(files.front().filename() == name + ".nc");
    std::ifstream in(folder / "machine");
    REQUIRE_MESSAGE(in.good(), "missing " << (folder / "machine").string());
    std::string machine;
    std::getline(in, machine);
    std::string rest;
    const bool more = static_cast<bool>(in >> rest);
    CHECK_MESSAGE(!more, "the machine file holds one line");
    CHECK_MESSAGE(std::find(kMachines.begin(), kMachines.end(), machine) != kMachines.end(),
                  "unknown machine '" << machine << "'");
  }
}

TEST_CASE("the generated benchmark program checks without a diagnostic") {
  const ncsim::core::SourceFile file(
      "bench.nc",
      ncsim::bench::generate_program(ncsim::bench::Dialect::isg, {.blocks = 5000, .seed = 1}));
  const auto diagnostics = ncsim::grammar::check_program(file);
  CHECK_MESSAGE(diagnostics.items().empty(), "\n" << formatted(diagnostics, file));
}

TEST_CASE("a program with an error is reported by the check the programs test relies on") {
  // Guards the test above against a check_program that accepts everything.
  const ncsim::core::SourceFile file("bad.nc", "%bad\nN10 $ENDIF\nN20 M30\n");
  CHECK(ncsim::grammar::check_program(file).has_errors());
}
