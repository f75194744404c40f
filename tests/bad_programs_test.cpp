// Runs check_program over every tests/bad/*.nc and compares with the file's own header:
// one `; expect: <line>:<col> <id> [substring of the message]` line per diagnostic, no more,
// no less.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "grammar/check.hpp"

namespace {

struct Expected {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::string id;
  std::string substring;
};

std::vector<Expected> expectations(const ncsim::core::SourceFile& file) {
  std::vector<Expected> out;
  const std::string_view prefix = "; expect: ";
  for (std::uint32_t l = 1; l <= file.line_count(); ++l) {
    const std::string_view text = file.line_text(l);
    if (!text.starts_with(prefix)) break;
    std::istringstream in(std::string(text.substr(prefix.size())));
    Expected e;
    char colon = 0;
    in >> e.line >> colon >> e.column >> e.id;
    std::getline(in >> std::ws, e.substring);
    out.push_back(e);
  }
  return out;
}

std::filesystem::path bad_dir() {
  const char* root = std::getenv("NCSIM_SOURCE_DIR");
  return std::filesystem::path(root != nullptr ? root : ".") / "tests" / "bad";
}

}  // namespace

TEST_CASE("the bad-program corpus has at least 45 programs, each stating its diagnostics") {
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(bad_dir())) {
    if (entry.path().extension() != ".nc") continue;
    ++count;
    const auto file = ncsim::core::SourceFile::load(entry.path());
    CHECK_MESSAGE(!expectations(file).empty(), entry.path().filename().string());
  }
  CHECK(count >= 45);
}

TEST_CASE("every bad program produces exactly its expected diagnostics") {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(bad_dir())) {
    if (entry.path().extension() == ".nc") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  REQUIRE(!files.empty());
  for (const auto& path : files) {
    INFO(path.filename().string());
    const auto file = ncsim::core::SourceFile::load(path);
    const auto expected = expectations(file);
    const ncsim::core::DiagnosticList diags = ncsim::grammar::check_program(file);
    std::vector<bool> used(diags.items().size(), false);
    for (const Expected& e : expected) {
      bool found = false;
      for (std::size_t i = 0; i < diags.items().size() && !found; ++i) {
        const auto& d = diags.items()[i];
        if (!used[i] && d.loc.line == e.line && d.loc.column == e.column && d.id == e.id &&
            d.message.find(e.substring) != std::string::npos) {
          used[i] = true;
          found = true;
        }
      }
      CHECK_MESSAGE(found,
                    "missing " << e.line << ":" << e.column << " " << e.id << " " << e.substring);
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
      const auto& d = diags.items()[i];
      CHECK_MESSAGE(used[i], "unexpected " << d.loc.line << ":" << d.loc.column << " " << d.id
                                           << " " << d.message);
    }
  }
}
