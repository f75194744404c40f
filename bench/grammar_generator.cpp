#include "bench/grammar_generator.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string_view>

namespace ncsim::bench {
namespace {

// Positions are kept in integer thousandths of a millimetre: every printed value is a multiple
// of 0.001 mm, and every expression form below evaluates (mathematically) to such a multiple,
// so the generator knows exactly where each interpreter believes the tool is.
using Milli = std::int64_t;  // [0.001 mm]

constexpr Milli kBoxHalf = 400'000;     // [0.001 mm] steer back towards the origin beyond this
constexpr Milli kRadiusMin = 2'000;     // [0.001 mm] smallest arc radius
constexpr Milli kRadiusMax = 40'000;    // [0.001 mm] largest arc radius
constexpr double kSweepMinDeg = 20.0;   // [deg] arcs never degenerate to a full circle
constexpr double kSweepMaxDeg = 160.0;  // [deg]

constexpr std::array<std::string_view, 6> kComments = {
    "(rough pass)", "(contour)", "(pocket 3)", "(next feature)", "(finish X side)", "(clear)",
};

void append_milli(std::string& out, Milli value) {
  if (value < 0) {
    out.push_back('-');
    value = -value;
  }
  out += std::to_string(value / 1000);
  auto frac = static_cast<int>(value % 1000);
  if (frac == 0) return;
  char digits[4] = {static_cast<char>('0' + frac / 100), static_cast<char>('0' + frac / 10 % 10),
                    static_cast<char>('0' + frac % 10), '\0'};
  int len = 3;
  while (digits[len - 1] == '0')
    --len;
  out.push_back('.');
  out.append(digits, static_cast<std::size_t>(len));
}

void append_word(std::string& out, char address, Milli value) {
  out.push_back(' ');
  out.push_back(address);
  append_milli(out, value);
}

Milli to_milli(double mm) {
  return static_cast<Milli>(std::llround(mm * 1000.0));
}

}  // namespace

std::uint64_t SplitMix64::next() {
  state_ += 0x9E3779B97F4A7C15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::uint32_t SplitMix64::below(std::uint32_t n) {
  return static_cast<std::uint32_t>(((next() >> 32) * static_cast<std::uint64_t>(n)) >> 32);
}

double SplitMix64::milli(std::int32_t lo_milli, std::int32_t hi_milli) {
  const auto span = static_cast<std::uint32_t>(hi_milli - lo_milli + 1);
  return static_cast<double>(lo_milli + static_cast<std::int32_t>(below(span))) / 1000.0;
}

ProgramGenerator::ProgramGenerator(GeneratorOptions options)
    : options_(options), rng_(options.seed) {}

std::string ProgramGenerator::prologue(Dialect dialect) {
  // Both start in the XY plane, absolute, metric, feed per minute, at the origin.
  if (dialect == Dialect::isg) return "%bench\nN1 G17 G90 G71 G94\nN2 G00 X0 Y0 Z0\n";
  return "%\nN1 G17 G90 G21 G94\nN2 G00 X0 Y0 Z0\n";
}

std::string ProgramGenerator::epilogue(Dialect dialect) {
  if (dialect == Dialect::isg) return "N3 M30\n";
  return "N3 M2\n%\n";
}

bool ProgramGenerator::next(std::string& out) {
  if (done_ >= options_.blocks) return false;
  const std::size_t begin = out.size();
  // Block numbers stay at or below 99990: rs274ngc rejects N > 99999; ISG accepts repeats.
  if (rng_.below(100) < 85) {
    out.push_back('N');
    out += std::to_string((done_ % 9999 + 1) * 10);
  }
  const std::uint32_t kind = rng_.below(100);
  const bool far = std::llabs(to_milli(x_)) > kBoxHalf || std::llabs(to_milli(y_)) > kBoxHalf;
  if (kind < 4) {
    out.push_back(' ');
    out += kComments[rng_.below(kComments.size())];
  } else if (kind < 14 || far) {
    linear(out, 0);
  } else if (kind < 50) {
    linear(out, 1);
  } else if (kind < 62) {
    expression_move(out);
  } else {
    arc(out);
  }
  if (kind >= 4) maybe_comment(out);
  if (out.size() > begin && out[begin] == ' ') out.erase(begin, 1);  // no N: no leading blank
  out.push_back('\n');
  ++done_;
  return true;
}

void ProgramGenerator::linear(std::string& out, int g) {
  const Milli x = to_milli(rng_.milli(-300'000, 300'000));
  const Milli y = to_milli(rng_.milli(-300'000, 300'000));
  out += g == 0 ? " G00" : " G01";
  append_word(out, 'X', x);
  append_word(out, 'Y', y);
  x_ = static_cast<double>(x) / 1000.0;
  y_ = static_cast<double>(y) / 1000.0;
  if (g == 0 || rng_.below(100) < 10) {
    const Milli z = to_milli(g == 0 ? rng_.milli(0, 50'000) : rng_.milli(-5'000, 0));
    append_word(out, 'Z', z);
    z_ = static_cast<double>(z) / 1000.0;
  }
  if (g != 0 && (!feed_set_ || rng_.below(100) < 20)) {
    out += " F";
    out += std::to_string(100 + rng_.below(4901));  // [mm/min]
    feed_set_ = true;
  }
}

void ProgramGenerator::expression_move(std::string& out) {
  // Each form evaluates to a multiple of 0.001 mm; SIN/COS take degrees in both dialects.
  out += " G01";
  const std::uint32_t form = rng_.below(3);
  const Milli a = to_milli(rng_.milli(-100'000, 100'000));
  Milli x = 0;
  out += " X[";
  if (form == 0) {  // a*2 + SIN[30] = 2a + 0.5
    append_milli(out, a);
    out += "*2+SIN[30]]";
    x = 2 * a + 500;
  } else if (form == 1) {  // a + b*COS[60] = a + b/2, b even in thousandths
    const Milli b = 2 * to_milli(rng_.milli(0, 50'000));
    append_milli(out, a);
    out.push_back('+');
    append_milli(out, b);
    out += "*COS[60]]";
    x = a + b / 2;
  } else {  // [a+b]/2 with a+b even in thousandths
    Milli b = to_milli(rng_.milli(-100'000, 100'000));
    if ((a + b) % 2 != 0) b += 1;
    out.push_back('[');
    append_milli(out, a);
    out.push_back('+');
    append_milli(out, b);
    out += "]/2]";
    x = (a + b) / 2;
  }
  const Milli y = to_milli(rng_.milli(-200'000, 200'000));
  out += " Y[ABS[";
  append_milli(out, y);
  out += "]-10]";
  x_ = static_cast<double>(x) / 1000.0;
  y_ = static_cast<double>(std::llabs(y) - 10'000) / 1000.0;
  if (!feed_set_) {
    out += " F1000";
    feed_set_ = true;
  }
}

void ProgramGenerator::arc(std::string& out) {
  const bool cw = rng_.below(2) == 0;
  // Centre relative to the start (I, J), drawn as an angle and a radius, then rounded to
  // 0.001 mm: the radius that counts is the one of the rounded centre.
  const double radius_nominal = rng_.milli(kRadiusMin, kRadiusMax);  // [mm]
  double centre_deg = rng_.milli(0, 359'999);                        // [deg]
  const double deg = std::numbers::pi / 180.0;
  const Milli i = to_milli(radius_nominal * std::cos(centre_deg * deg));
  const Milli j = to_milli(radius_nominal * std::sin(centre_deg * deg));
  const double cx = x_ + static_cast<double>(i) / 1000.0;  // [mm]
  const double cy = y_ + static_cast<double>(j) / 1000.0;  // [mm]
  const double radius = std::hypot(static_cast<double>(i), static_cast<double>(j)) / 1000.0;
  const double start = std::atan2(y_ - cy, x_ - cx);  // [rad]
  const double sweep = rng_.milli(static_cast<std::int32_t>(kSweepMinDeg * 1000),
                                  static_cast<std::int32_t>(kSweepMaxDeg * 1000)) *
                       deg;  // [rad]
  const double end = cw ? start - sweep : start + sweep;
  const Milli ex = to_milli(cx + radius * std::cos(end));
  const Milli ey = to_milli(cy + radius * std::sin(end));
  out += cw ? " G02" : " G03";
  append_word(out, 'X', ex);
  append_word(out, 'Y', ey);
  append_word(out, 'I', i);
  append_word(out, 'J', j);
  if (!feed_set_) {
    out += " F1000";
    feed_set_ = true;
  }
  x_ = static_cast<double>(ex) / 1000.0;
  y_ = static_cast<double>(ey) / 1000.0;
}

void ProgramGenerator::maybe_comment(std::string& out) {
  if (rng_.below(100) >= 15) return;
  out.push_back(' ');
  out += kComments[rng_.below(kComments.size())];
}

std::string generate_program(Dialect dialect, GeneratorOptions options) {
  std::string text = ProgramGenerator::prologue(dialect);
  text.reserve(static_cast<std::size_t>(options.blocks) * 36 + 64);
  ProgramGenerator generator(options);
  std::string block;
  while (generator.next(block)) {
    text += block;
    block.clear();
  }
  text += ProgramGenerator::epilogue(dialect);
  return text;
}

}  // namespace ncsim::bench
