#include "core/source_file.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

using ncsim::core::SourceFile;
using ncsim::core::SourceLoc;

TEST_CASE("offsets map to 1-based line and column") {
  const SourceFile f("p.nc", "N10 G01\nX10\r\n\nY5");
  CHECK(f.loc_of(0) == SourceLoc{1, 1});
  CHECK(f.loc_of(4) == SourceLoc{1, 5});
  CHECK(f.loc_of(8) == SourceLoc{2, 1});
  CHECK(f.loc_of(14) == SourceLoc{4, 1});
  CHECK(f.loc_of(1000) == SourceLoc{4, 3});  // past the end clamps to after the last byte
  CHECK(f.line_count() == 4);
}

TEST_CASE("line text has no line end, also for CRLF files") {
  const SourceFile f("p.nc", "N10 G01\nX10\r\n\nY5");
  CHECK(f.line_text(1) == "N10 G01");
  CHECK(f.line_text(2) == "X10");
  CHECK(f.line_text(3).empty());
  CHECK(f.line_text(4) == "Y5");
  CHECK(f.line_text(5).empty());
  CHECK(f.line_text(0).empty());
  CHECK(f.line_start(2) == 8);
}

TEST_CASE("loading a missing file names the path") {
  CHECK_THROWS_WITH(SourceFile::load("/nonexistent/x.nc"), doctest::Contains("/nonexistent/x.nc"));
}

TEST_CASE("loading reads the whole file byte for byte, CR and NUL included") {
  const auto path = std::filesystem::temp_directory_path() / "ncsim_source_file_test.nc";
  constexpr char kBytes[] = "N10 G01\r\nX1\0Y2\n(no newline at the end)";
  const std::string bytes(kBytes, sizeof(kBytes) - 1);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const SourceFile f = SourceFile::load(path);
  std::filesystem::remove(path);
  CHECK(f.text() == bytes);
  CHECK(f.name() == path.string());
  CHECK(f.line_count() == 3);
  CHECK(f.line_text(3) == "(no newline at the end)");
}

TEST_CASE("an empty file has one empty line") {
  const SourceFile f("e.nc", "");
  CHECK(f.line_count() == 1);
  CHECK(f.line_text(1).empty());
  CHECK(f.loc_of(0) == SourceLoc{1, 1});
}

TEST_CASE("the sparse line index answers lines and offsets far apart in a long file") {
  std::string text;
  for (int i = 1; i <= 5000; ++i)
    text += "L" + std::to_string(i) + (i % 3 == 0 ? "\r\n" : "\n");
  const SourceFile f("long.nc", text);
  // Queries out of order: the index grows on demand and answers the same afterwards.
  for (const std::uint32_t line : {4321u, 1u, 1024u, 1025u, 2049u, 5000u, 3u}) {
    CAPTURE(line);
    CHECK(f.line_text(line) == "L" + std::to_string(line));
    CHECK(f.loc_of(f.line_start(line)) == SourceLoc{line, 1});
    CHECK(f.loc_of(f.line_start(line) + 1) == SourceLoc{line, 2});
  }
  CHECK(f.line_count() == 5001);
  CHECK(f.line_text(5001).empty());
  CHECK(f.line_text(5002).empty());
  CHECK(f.line_start(6000) == text.size());
}

TEST_CASE("a mapped file reads the same after its pages are released") {
  const auto path = std::filesystem::temp_directory_path() / "ncsim_source_file_map_test.nc";
  std::string text;
  for (int i = 0; i < 400000; ++i)  // ~ 20 MB, beyond two release steps
    text += "N" + std::to_string(i) + " G01 X" + std::to_string(i % 977) + " Y1 F100\n";
  {
    std::ofstream out(path, std::ios::binary);
    out << text;
  }
  const SourceFile f = SourceFile::load(path);
  std::filesystem::remove(path);  // the mapping keeps the data
  REQUIRE(f.text().size() == text.size());
  f.release_before(text.size());
  CHECK(f.text() == text);  // released pages fault in again
  CHECK(f.line_text(300001) == "N300000 G01 X61 Y1 F100");
  CHECK(f.loc_of(text.size()) == SourceLoc{400001, 1});
}
