#include "bench/grammar_generator.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

using ncsim::bench::Dialect;
using ncsim::bench::generate_program;
using ncsim::bench::GeneratorOptions;
using ncsim::bench::ProgramGenerator;

namespace {

// A small evaluator for the words the generator writes: numbers, + - * /, [ ] grouping and
// SIN/COS/ABS (degrees), as rs274ngc and the ISG kernel read them. It reads the text only,
// so the geometry check below does not trust the generator's own bookkeeping.
class WordReader {
 public:
  explicit WordReader(std::string_view text) : text_(text) {}

  double value() {
    if (peek() == '[') return group();
    return number();
  }

 private:
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  double number() {
    std::size_t end = pos_;
    if (text_[end] == '-' || text_[end] == '+') ++end;
    while (end < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[end])) != 0 || text_[end] == '.')) {
      ++end;
    }
    const double v = std::strtod(std::string(text_.substr(pos_, end - pos_)).c_str(), nullptr);
    pos_ = end;
    return v;
  }
  double group() {
    ++pos_;  // '['
    const double v = sum();
    ++pos_;  // ']'
    return v;
  }
  double sum() {
    double v = product();
    while (peek() == '+' || peek() == '-') {
      const char op = text_[pos_++];
      const double rhs = product();
      v = op == '+' ? v + rhs : v - rhs;
    }
    return v;
  }
  double product() {
    double v = factor();
    while (peek() == '*' || peek() == '/') {
      const char op = text_[pos_++];
      const double rhs = factor();
      v = op == '*' ? v * rhs : v / rhs;
    }
    return v;
  }
  double factor() {
    const double deg = std::numbers::pi / 180.0;
    if (text_.substr(pos_, 3) == "SIN") return pos_ += 3, std::sin(group() * deg);
    if (text_.substr(pos_, 3) == "COS") return pos_ += 3, std::cos(group() * deg);
    if (text_.substr(pos_, 3) == "ABS") return pos_ += 3, std::abs(group());
    if (peek() == '[') return group();
    return number();
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

struct Words {
  std::optional<int> g;
  std::optional<double> x, y, i, j;
};

Words read_block(std::string_view line) {
  Words w;
  if (const auto c = line.find('('); c != std::string_view::npos) line = line.substr(0, c);
  std::size_t pos = 0;
  while (pos < line.size()) {
    const char address = line[pos];
    if (address == ' ') {
      ++pos;
      continue;
    }
    if (address == 'N' || address == 'F' || address == 'Z') {
      ++pos;
      while (pos < line.size() && line[pos] != ' ')
        ++pos;  // skip the word
      continue;
    }
    std::size_t end = pos + 1;
    int depth = 0;
    while (end < line.size() && (depth > 0 || line[end] != ' ')) {
      depth += line[end] == '[' ? 1 : line[end] == ']' ? -1 : 0;
      ++end;
    }
    WordReader reader(line.substr(pos + 1, end - pos - 1));
    const double v = reader.value();
    if (address == 'G') w.g = static_cast<int>(v);
    if (address == 'X') w.x = v;
    if (address == 'Y') w.y = v;
    if (address == 'I') w.i = v;
    if (address == 'J') w.j = v;
    pos = end;
  }
  return w;
}

}  // namespace

TEST_CASE("the same seed gives the same program, another seed another one") {
  const auto a = generate_program(Dialect::isg, {500, 7});
  CHECK(a == generate_program(Dialect::isg, {500, 7}));
  CHECK(a != generate_program(Dialect::isg, {500, 8}));
}

TEST_CASE("both dialects carry the same body blocks and differ only in prologue and epilogue") {
  const GeneratorOptions options{300, 3};
  const auto isg = generate_program(Dialect::isg, options);
  const auto ngc = generate_program(Dialect::rs274ngc, options);
  const auto isg_pro = ProgramGenerator::prologue(Dialect::isg);
  const auto ngc_pro = ProgramGenerator::prologue(Dialect::rs274ngc);
  const auto isg_epi = ProgramGenerator::epilogue(Dialect::isg);
  const auto ngc_epi = ProgramGenerator::epilogue(Dialect::rs274ngc);
  CHECK(isg.substr(isg_pro.size(), isg.size() - isg_pro.size() - isg_epi.size()) ==
        ngc.substr(ngc_pro.size(), ngc.size() - ngc_pro.size() - ngc_epi.size()));
  CHECK(isg.ends_with("M30\n"));
  CHECK(ngc.starts_with("%\n"));
  CHECK(ngc.ends_with("M2\n%\n"));
}

TEST_CASE("the program has the requested number of body blocks, one per line") {
  const auto text = generate_program(Dialect::isg, {1234, 1});
  const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  CHECK(lines == 1234 + 3 + 1);  // prologue 3 lines, epilogue 1
}

TEST_CASE("block numbers never exceed 99999, the rs274ngc limit") {
  ProgramGenerator generator({30'000, 5});
  std::string block;
  std::size_t numbered = 0;
  long largest = 0;
  while (generator.next(block)) {
    if (block.front() == 'N') {
      ++numbered;
      largest = std::max(largest, std::atol(block.c_str() + 1));
    }
    block.clear();
  }
  CHECK(largest <= 99999);
  CHECK(numbered > 20'000);
}

TEST_CASE("every arc has equal radii at start and end, read back from the text (seeded)") {
  // rs274ngc rejects an arc whose end radius differs from the start radius by more than
  // 0.0028 mm (and 0.1 %); the generator promises 0.0008 mm.
  for (const std::uint64_t seed : {1ULL, 2ULL, 99ULL}) {
    CAPTURE(seed);
    ProgramGenerator generator({20'000, seed});
    std::string block;
    double x = 0.0;  // [mm] position as an interpreter reading the text computes it
    double y = 0.0;  // [mm]
    std::size_t arcs = 0;
    double shortest_radius = 1e9;  // [mm]
    double shortest_chord = 1e9;   // [mm] start to end: never a full circle
    double worst = 0.0;            // [mm] largest radius difference of an arc
    double track_error = 0.0;      // [mm] text position versus the generator's own
    while (generator.next(block)) {
      const Words w = read_block(block);
      if (w.g && (*w.g == 2 || *w.g == 3)) {
        REQUIRE((w.x && w.y && w.i && w.j));
        const double cx = x + *w.i;
        const double cy = y + *w.j;
        const double r_start = std::hypot(*w.i, *w.j);
        const double r_end = std::hypot(*w.x - cx, *w.y - cy);
        worst = std::max(worst, std::abs(r_end - r_start));
        shortest_radius = std::min(shortest_radius, r_start);
        shortest_chord = std::min(shortest_chord, std::hypot(*w.x - x, *w.y - y));
        ++arcs;
      }
      if (w.x) x = *w.x;
      if (w.y) y = *w.y;
      track_error =
          std::max({track_error, std::abs(x - generator.x()), std::abs(y - generator.y())});
      block.clear();
    }
    CHECK(arcs > 5'000);
    CHECK(worst < 0.0008);
    CHECK(track_error < 1e-9);
    CHECK(shortest_radius >= 1.999);
    CHECK(shortest_chord > 0.5);
  }
}
