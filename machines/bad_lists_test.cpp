// Every file in machines/testdata/bad/ replaces one list of machines/testdata/base/ and must
// produce the diagnostic its first line states, and no other error (issue 9: one bad value must
// not add follow-on errors such as "missing mandatory" for a key that is present):
//   # expect: replaces=<list> line=<n> id=<id> key=<key>
// (line 0: the diagnostic has no line, e.g. a missing mandatory key).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "machines/loader.hpp"

namespace ncsim::machines {
namespace {

std::filesystem::path testdata() {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  REQUIRE(root != nullptr);
  return std::filesystem::path(root) / "machines" / "testdata";
}

std::map<std::string, std::string> read_expectation(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  std::map<std::string, std::string> fields;
  const std::string prefix = "# expect:";
  INFO(file.string());
  REQUIRE(first.rfind(prefix, 0) == 0);
  std::istringstream words(first.substr(prefix.size()));
  std::string word;
  while (words >> word) {
    const auto eq = word.find('=');
    if (eq != std::string::npos) fields[word.substr(0, eq)] = word.substr(eq + 1);
  }
  return fields;
}

// Writes an index in a scratch folder that names the base lists, one replaced by `bad`.
std::filesystem::path make_machine(const std::filesystem::path& bad, const std::string& replaces) {
  const std::filesystem::path base = testdata() / "base";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("ncsim_machines_bad_" + bad.stem().string());
  std::filesystem::create_directories(dir);
  auto list = [&](const std::string& name) {
    return std::filesystem::absolute(name == replaces ? bad : base / name).string();
  };
  std::ofstream index(dir / kMachineIndexFile);
  index << "channel " << list("channel.lis") << "\n"
        << "axis X " << list("x.lis") << "\n"
        << "axis Y " << list("y.lis") << "\n"
        << "axis Z " << list("z.lis") << "\n"
        << "axis S " << list("s.lis") << "\n";
  return dir;
}

TEST_CASE("the base machine of the bad-list corpus loads cleanly") {
  const LoadResult r = load_machine(testdata() / "base");
  CHECK(r.machine.has_value());
  CHECK(r.diagnostics.items().empty());
}

TEST_CASE("every bad parameter list produces the diagnostic it documents") {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(testdata() / "bad")) {
    if (e.path().extension() == ".lis") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  CHECK(files.size() >= 25);
  for (const auto& bad : files) {
    CAPTURE(bad.filename().string());
    const auto want = read_expectation(bad);
    REQUIRE(want.count("replaces") == 1);
    const LoadResult r = load_machine(make_machine(bad, want.at("replaces")));
    CHECK_FALSE(r.machine.has_value());
    std::string got;
    bool found = false;
    int errors = 0;
    for (const core::Diagnostic& d : r.diagnostics.items()) {
      got += core::format(d);
      errors += d.severity == core::Severity::error ? 1 : 0;
      found = found || (d.file == std::filesystem::absolute(bad).string() &&
                        std::to_string(d.loc.line) == want.at("line") && d.id == want.at("id") &&
                        d.message.find(want.at("key")) != std::string::npos &&
                        d.severity == core::Severity::error);
    }
    INFO("diagnostics:\n" << got);
    CHECK(found);
    CHECK(errors == 1);
  }
}

}  // namespace
}  // namespace ncsim::machines
