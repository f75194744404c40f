// Control flow across the block cache: $GOTO / $IF / loops whose partners lie more than
// BlockSource::kCacheSlots blocks apart (issue 9, defects 1 and 4), and the endless-loop
// verdicts (defects 5 and 6).
#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

std::string repeat(const std::string& line, std::size_t n) {
  std::string out;
  out.reserve(line.size() * n);
  for (std::size_t i = 0; i < n; ++i)
    out += line;
  return out;
}

/// The X values of the G01 motions of a trace, in order.
std::vector<int> visited(const test::Run& r) {
  std::vector<int> xs;
  for (const std::string& l : r.lines) {
    const auto g = l.find(": G01 X=");
    if (g == std::string::npos) continue;
    xs.push_back(std::stoi(l.substr(g + 8)));
  }
  return xs;
}

TEST_CASE("a forward $GOTO over 2048 blocks lands on its own label (cache slot reuse)") {
  // Issue 9 defect 1: the $GOTO block's slot was reused by the scan, so the label compared
  // against changed under it (heap-use-after-free) and N20 was taken for N10.
  const std::string text = "%p\nG00 X0 Y0 Z0\n$GOTO N10\n" + repeat("P2 = 1\n", 2047) +
                           "$GOTO N20\nN10: G01 X1 F100\nN20: G01 X2 F100\nM30\n";
  const auto r = test::run(text);
  CHECK(r.error_id.empty());
  CHECK(visited(r) == std::vector<int>{1, 2});
}

TEST_CASE("a backward $GOTO over 2048 blocks lands on its own label") {
  const std::string text = "%p\nG00 X0 Y0 Z0\nP1 = 0\nN10: G01 X1 F100\nP1 = P1 + 1\n" +
                           repeat("P2 = 1\n", 2050) + "$IF P1 < 3 $GOTO N10\nG01 X2\nM30\n";
  const auto r = test::run(text);
  CHECK(r.error_id.empty());
  CHECK(visited(r) == std::vector<int>{1, 1, 1, 2});
}

// A program of labelled segments in random file order, each jumping to a random next
// segment after a random amount of filler (up to 3 cache sizes), with $IF/$ELSE branches and
// $WHILE loops around the fillers. The expectation is computed by walking the same graph.
struct JumpProgram {
  std::string text;
  std::vector<int> expected;
};

JumpProgram make_jump_program(std::mt19937& rng) {
  const int segments = 2 + static_cast<int>(rng() % 6);
  const int limit = 5 + static_cast<int>(rng() % 20);
  std::vector<int> next(static_cast<std::size_t>(segments));
  for (auto& n : next)
    n = static_cast<int>(rng() % static_cast<unsigned>(segments));
  std::vector<int> order(static_cast<std::size_t>(segments));
  for (int i = 0; i < segments; ++i)
    order[static_cast<std::size_t>(i)] = i;
  std::shuffle(order.begin(), order.end(), rng);
  const auto filler = [&rng] {
    const std::size_t n = rng() % 3 == 0 ? rng() % 6200 : rng() % 40;
    return repeat("P2 = P2 + 1\n", n);
  };

  std::string t =
      "%p\nG00 X0 Y0 Z0\nP1 = 0\nP2 = 0\n$GOTO N" + std::to_string(100 + order[0]) + "\n";
  for (int i : order) {
    const std::string label = std::to_string(100 + i);
    t += "N" + label + ": G01 X" + std::to_string(i + 1) + " F100\n";
    t += "P1 = P1 + 1\n$IF P1 > " + std::to_string(limit) + " $GOTO N99\n";
    switch (rng() % 3) {
      case 0:
        t += filler();
        break;
      case 1:  // both branches are skipped over as often as taken
        t += "$IF [P1 MOD 2] == 0\n" + filler() + "$ELSE\n" + filler() + "$ENDIF\n";
        break;
      default:  // a loop of two passes whose body is longer than the cache
        t += "P3 = 0\n$WHILE P3 < 2\n" + filler() + "P3 = P3 + 1\n$ENDWHILE\n";
        break;
    }
    t += "$GOTO N" + std::to_string(100 + next[static_cast<std::size_t>(i)]) + "\n";
    t += filler();
  }
  t += "N99: M30\n";

  JumpProgram p{std::move(t), {}};
  int at = order[0];
  for (int count = 1;; ++count) {
    p.expected.push_back(at + 1);
    if (count > limit) break;
    at = next[static_cast<std::size_t>(at)];
  }
  return p;
}

TEST_CASE("property: $GOTO/$IF/$WHILE across cache evictions follow the program's graph") {
  std::mt19937 rng(20261122);
  for (int round = 0; round < 40; ++round) {
    CAPTURE(round);
    const JumpProgram p = make_jump_program(rng);
    const auto r = test::run(p.text, "portal_3x", {}, 100000);
    CHECK(r.error_id == "");
    CHECK(visited(r) == p.expected);
  }
}

TEST_CASE("the block index holds one checkpoint per 256 blocks, not an entry per block") {
  const core::SourceFile file("long.nc",
                              "%t\nG00 X0 Y0 Z0\n" + repeat("G01 X1 F100\n", 300000) + "M30\n");
  Interpreter interp(file, test::machine());
  std::size_t commands = 0;
  while (interp.next())
    ++commands;
  CHECK(commands == 300002);
  CHECK(interp.footprint().indexed_blocks <= 300002 / BlockSource::kCheckpointStride + 2);
}

TEST_CASE("the $GOTO memo stays bounded however many $GOTO sites run") {
  // 70,000 forward $GOTO sites, each run once: more than the memo holds.
  std::string text = "%t\n";
  for (int i = 0; i < 70000; ++i)
    text += "$GOTO [L" + std::to_string(i) + "]\n[L" + std::to_string(i) + "] P1 = 1\n";
  const core::SourceFile file("sites.nc", text + "G01 X1 F100\nM30\n");
  Interpreter interp(file, test::machine());
  while (interp.next()) {
  }
  CHECK(interp.error() == nullptr);
  CHECK(interp.footprint().jump_memo <= 65536);
}

TEST_CASE(
    "a computed block number beyond the literal range is NC4016 (as NC1005 for N99999999999)") {
  const auto r = test::run("%t\nN[10**20] G01 X1 F100\nM30\n");
  CHECK(r.error_id == "NC4016");
  CHECK(r.error_line == 2);
  CHECK(test::run("%t\nN[-1] G01 X1 F100\nM30\n").error_id == "NC4016");
  CHECK(test::run("%t\nN[4294967295] G01 X1 F100\nM30\n").error_id.empty());
}

/// Runs `text` as a program in interp/testdata/ (next to the subroutine files there).
test::Run run_in_testdata(const std::string& text) {
  const std::string name = (test::source_root() / "interp/testdata/virtual.nc").string();
  return test::run_file(core::SourceFile(name, text), "portal_3x", {}, 100);
}

TEST_CASE("a called subroutine file with a syntax error in an unreached block is NC4306") {
  // Issue 9 defect 3: `check` said ok because only the blocks that ran were parsed.
  const auto r = run_in_testdata("%v\nG00 X0\nL sub_bad.nc\nM30\n");
  CHECK(r.error_id == "NC4306");
  CHECK(r.error_line == 3);
  CHECK(r.error_message.find("sub_bad.nc has 1 syntax error") != std::string::npos);
  // The syntax error itself is reported too, at its line in the subroutine file.
  const std::string name = (test::source_root() / "interp/testdata/virtual.nc").string();
  const core::SourceFile main(name, "%v\nL sub_bad.nc\nM30\n");
  Interpreter interp(main, test::machine());
  while (interp.next()) {
  }
  bool found = false;
  for (const auto& d : interp.diagnostics().items()) {
    if (d.file.ends_with("sub_bad.nc") && d.loc.line == 4 && d.id.rfind("NC1", 0) == 0)
      found = true;
  }
  CHECK(found);
}

TEST_CASE("L of a directory or a device says what it is (NC4301)") {
  const auto dir =
      run_in_testdata("%v\nL " + (test::source_root() / "interp").string() + "\nM30\n");
  CHECK(dir.error_id == "NC4301");
  CHECK(dir.error_message.find("is a directory") != std::string::npos);
  const auto dev = run_in_testdata("%v\nL /dev/zero\nM30\n");
  CHECK(dev.error_id == "NC4301");
  CHECK(dev.error_message.find("is a device") != std::string::npos);
  const auto missing = run_in_testdata("%v\nL no_such_file.nc\nM30\n");
  CHECK(missing.error_id == "NC4301");
  CHECK(missing.error_message.find("not found") != std::string::npos);
}

}  // namespace
}  // namespace ncsim::interp
