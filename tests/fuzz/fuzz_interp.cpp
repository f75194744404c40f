// fuzz_interp: libFuzzer target for the interpreter. Any input bytes become a program file;
// when grammar::check_program finds no error, the interpreter runs it on a bundled machine and
// the driver pulls a bounded number of commands; small inputs also go through
// interp::check_semantics. Every run must end (program errors are fine) without a crash, a
// hang, unbounded growth or a sanitizer report, and every command must carry finite numbers.
// Built by tests/fuzz.cmake (NCSIM_FUZZ=ON, clang); run by tests/fuzz/run.sh.
//
// Input layout: a first byte 0x01 selects delta_picker, 0x02 laser_portal, 0x03 static_saw
// (the byte is not part of the program); any other input is a program for portal_3x. The machines
// are loaded once from the source tree (NCSIM_SOURCE_ROOT). The program file is named inside a
// directory created once by this driver that holds only the fixed subroutine files below, and
// Options::confine_subroutine_files keeps `L file` inside it: a fuzzed program can open no
// other file. No clock, no randomness: the same input always runs the same way.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <variant>

#include "core/source_file.hpp"
#include "grammar/check.hpp"
#include "interp/interpreter.hpp"
#include "interp/trace.hpp"
#include "machines/loader.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ncsim;

constexpr std::size_t kMaxCommands = 4000;           // commands pulled per input
constexpr std::uint64_t kMaxQuietBlocks = 20'000;    // Options::max_blocks_without_motion
constexpr std::size_t kCheckSemanticsMaxSize = 512;  // [bytes] inputs also run by check mode

/// Subroutine files the fuzzed programs may call with `L <name>` (seeds in corpus_interp/).
constexpr const char* kSubroutineFiles[][2] = {
    {"sub.nc", "%sub\nG01 X[P1] Y2 F100\nP2 = P1 * 2\nM17\n"},
    {"self.nc", "%self\nP3 = 1\nL self.nc\nM17\n"},
    {"local.nc", "%L INNER\nG00 Z1\nM17\n%local\nLL INNER\nM29\n"},
};

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_interp: %s\n", what.c_str());
  std::abort();
}

struct Sandbox {
  fs::path dir;
  Sandbox() {
    std::string templ = (fs::temp_directory_path() / "ncsim-fuzz-interp-XXXXXX").string();
    if (mkdtemp(templ.data()) == nullptr) fail("cannot create a temporary directory");
    dir = templ;
    for (const auto& [name, text] : kSubroutineFiles) {
      std::ofstream out(dir / name, std::ios::binary);
      out << text;
      if (!out) fail(std::string("cannot write ") + name);
    }
  }
  ~Sandbox() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;
};

const fs::path& sandbox_dir() {
  static const Sandbox sandbox;  // fuzz driver only: created once per process
  return sandbox.dir;
}

machines::Machine load(std::string_view name) {
  auto loaded = machines::load_machine(machines::bundled_machine_dir(NCSIM_SOURCE_ROOT, name));
  if (!loaded.machine) fail("bundled machine " + std::string(name) + " does not load");
  return std::move(*loaded.machine);
}

const machines::Machine& machine(int index) {
  static const machines::Machine machines[4] = {load("portal_3x"), load("delta_picker"),
                                                load("laser_portal"),
                                                load("static_saw")};  // loaded once
  return machines[index];
}

bool finite(const interp::AxisValues& v) {
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}
bool finite(const std::optional<double>& v) {
  return !v || std::isfinite(*v);
}

/// The numbers a command hands to the planner are finite.
bool numbers_finite(const interp::Command& c) {
  using namespace interp;
  if (const auto* m = std::get_if<Motion>(&c.body)) {
    bool ok = finite(m->start) && finite(m->end) && std::isfinite(m->feed) &&
              finite(m->block_time) && finite(m->end_feed);
    if (m->arc) {
      ok = ok && std::isfinite(m->arc->centre_1) && std::isfinite(m->arc->centre_2) &&
           std::isfinite(m->arc->radius);
    }
    return ok;
  }
  if (const auto* s = std::get_if<SplineBegin>(&c.body)) return finite(s->start);
  if (const auto* s = std::get_if<SplinePoint>(&c.body)) {
    return finite(s->point) && std::isfinite(s->feed);
  }
  if (const auto* d = std::get_if<Dwell>(&c.body)) return std::isfinite(d->seconds);
  if (const auto* a = std::get_if<AxisCommand>(&c.body)) {
    return std::isfinite(a->target) && finite(a->feed) && finite(a->time);
  }
  if (const auto* v = std::get_if<MoveVelocity>(&c.body)) return std::isfinite(v->velocity);
  if (const auto* p = std::get_if<SetPosition>(&c.body)) return finite(p->values);
  if (const auto* s = std::get_if<SyncIn>(&c.body)) return std::isfinite(s->conv_vel);
  return true;
}

void run_interpreter(const core::SourceFile& file, const machines::Machine& m,
                     const interp::Options& options) {
  interp::Interpreter interp(file, m, options);
  for (std::size_t n = 0; n < kMaxCommands; ++n) {
    auto c = interp.next_decode_only();
    if (!c) break;
    if (c->file == 0 && c->line > file.line_count()) fail("command line beyond the file");
    if (!numbers_finite(*c)) fail("non-finite number in: " + interp::to_trace_line(*c, m));
    (void)interp::to_trace_line(*c, m);
  }
  if (const auto* e = interp.error()) {
    if (e->id.empty()) fail("error without id");
    if (e->file == file.name() && e->loc.line > file.line_count())
      fail("error position beyond the file");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  int machine_index = 0;
  if (size > 0 && data[0] >= 0x01 && data[0] <= 0x03) {
    machine_index = data[0];
    ++data;
    --size;
  }
  const core::SourceFile file((sandbox_dir() / "fuzz.nc").string(),
                              std::string(reinterpret_cast<const char*>(data), size));
  if (grammar::check_program(file).has_errors()) return 0;

  interp::Options options;
  options.max_blocks_without_motion = kMaxQuietBlocks;
  options.confine_subroutine_files = true;
  const machines::Machine& m = machine(machine_index);
  run_interpreter(file, m, options);

  if (size <= kCheckSemanticsMaxSize) {
    const auto diagnostics = interp::check_semantics(file, m, options);
    for (const auto& d : diagnostics.items()) {
      if (d.file == file.name() && d.loc.line > file.line_count())
        fail("check diagnostic position beyond the file");
    }
  }
  return 0;
}
