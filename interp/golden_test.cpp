// Golden traces: every program under programs/<name>/ with a <name>.trace is interpreted on
// its machine and its trace (first kGoldenCommands commands, then the error or END) must match
// byte for byte. A golden is what `ncsim trace --max-commands 400` prints; scripts/bless_traces.sh
// rewrites them all (an explicit step, reviewed by hand with git diff).
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST_CASE("each seed program's trace matches its golden file") {
  const auto programs = test::source_root() / "programs";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(programs)) {
    const std::string name = entry.path().filename().string();
    const auto golden = entry.path() / (name + ".trace");
    if (!std::filesystem::exists(golden)) continue;
    std::string machine_name = "portal_3x";
    if (std::filesystem::exists(entry.path() / "machine")) {
      std::istringstream in(read(entry.path() / "machine"));
      in >> machine_name;
    }
    const auto nc = entry.path() / (name + ".nc");
    core::SourceFile file(nc.filename().string(), read(nc));
    std::ostringstream out;
    core::DiagnosticList diags;
    TraceOptions options;
    options.max_commands = kGoldenCommands;
    write_trace(file, test::machine(machine_name), options, out, diags);
    CAPTURE(name);
    CHECK(out.str() == read(golden));
    ++checked;
  }
  CHECK(checked >= 10);
}

}  // namespace
}  // namespace ncsim::interp
