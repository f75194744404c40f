#pragma once
// Test helpers of golden/: run CSV texts built from a list of blocks.
#include <cstdint>
#include <string>
#include <vector>

namespace ncsim::golden::test {

/// A block of a synthetic run: its line and how many cycles it lasts.
struct Block {
  std::uint64_t line;
  std::uint64_t cycles;
};

/// The CSV `ncsim run` would write for `blocks` at a 1 ms cycle: X = 0.5 k, Y = 100 - 0.25 k
/// (k the cycle, from 1), and `closing` appended (e.g. "# error: ...\n").
inline std::string csv(const std::vector<Block>& blocks, const std::string& closing = "") {
  std::string s =
      "# ncsim run\n# program: p.nc\n# machine: portal_3x\n# cycle: 0.001 s\n"
      "# units: mm | deg, s\nt,line,X,Y\n";
  std::uint64_t k = 0;
  for (const Block& b : blocks) {
    for (std::uint64_t i = 0; i < b.cycles; ++i) {
      ++k;
      s += std::to_string(k) + "e-3," + std::to_string(b.line) + ',' +
           std::to_string(0.5 * static_cast<double>(k)) + ',' +
           std::to_string(100.0 - 0.25 * static_cast<double>(k)) + '\n';
    }
  }
  return s + closing;
}

}  // namespace ncsim::golden::test
