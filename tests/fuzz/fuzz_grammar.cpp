// fuzz_grammar: libFuzzer target for the syntax and structure check. Any input bytes become a
// program file; check_program must return (diagnostics are fine) without crashing, hanging,
// or a sanitizer report. Built by tests/fuzz.cmake (NCSIM_FUZZ=ON, clang); run by
// tests/fuzz/run.sh.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/source_file.hpp"
#include "grammar/check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const ncsim::core::SourceFile file("fuzz.nc",
                                     std::string(reinterpret_cast<const char*>(data), size));
  const auto diagnostics = ncsim::grammar::check_program(file);
  // Every position a diagnostic names must lie inside the file (line 0 = no position).
  for (const auto& d : diagnostics.items()) {
    if (d.loc.line > file.line_count()) __builtin_trap();
  }
  return 0;
}
