#pragma once
// bench/grammar_generator: deterministic NC program generator for the syntax-check benchmark.
//
// Purpose: produce an N-block milling program (G00/G01/G02/G03 with I/J, F, block numbers,
// `( ... )` comments, bracketed expressions such as `X[12.5*2+SIN[30]]`) in two dialects from
// one block sequence: ISG / TwinCAT 3 CNC (`.nc`, ends with M30) and the RS274/NGC subset that
// LinuxCNC's stand-alone `rs274` interpreter accepts (`.ngc`, `%` ... `%`, ends with M2).
// Inputs: block count and seed. Outputs: the program text, block by block.
// Invariants: the same (blocks, seed) always gives the same bytes, on every compiler and
// standard library (own PRNG, own integer-to-real mapping, std::to_chars for numbers; no wall
// clock). Arcs are geometrically valid: I/J are computed from the current position as printed,
// and the end point lies on the circle within 0.0008 mm (rs274 accepts 0.0028 mm).
// The body blocks are identical in both dialects; only the prologue and epilogue differ.

#include <cstdint>
#include <string>

namespace ncsim::bench {

enum class Dialect {
  isg,       ///< ISG / TwinCAT 3 CNC: `%name`, G71 (metric), ends with M30
  rs274ngc,  ///< LinuxCNC rs274ngc: `%` lines, G21 (metric), ends with M2
};

struct GeneratorOptions {
  std::uint64_t blocks = 1000;  ///< body blocks (prologue and epilogue come on top)
  std::uint64_t seed = 1;       ///< PRNG seed
};

/// splitmix64: small, fast, portable; the sequence is fixed by the seed alone.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  /// Uniform integer in [0, n), n > 0 (multiply-shift, no modulo bias worth caring about).
  std::uint32_t below(std::uint32_t n);
  /// Uniform multiple of 0.001 in [lo, hi] (both given in thousandths).
  double milli(std::int32_t lo_milli, std::int32_t hi_milli);

 private:
  std::uint64_t state_;
};

/// Produces the body blocks one by one and remembers the tool position they lead to.
class ProgramGenerator {
 public:
  explicit ProgramGenerator(GeneratorOptions options);

  /// Lines before the first body block (with line ends).
  static std::string prologue(Dialect dialect);
  /// Lines after the last body block (with line ends).
  static std::string epilogue(Dialect dialect);

  /// Appends the next body block with its line end to `out`; false when all blocks are out.
  bool next(std::string& out);

  std::uint64_t blocks_done() const { return done_; }
  double x() const { return x_; }  ///< [mm] position after the blocks so far
  double y() const { return y_; }  ///< [mm]

 private:
  void linear(std::string& out, int g);
  void expression_move(std::string& out);
  void arc(std::string& out);
  void maybe_comment(std::string& out);

  GeneratorOptions options_;
  SplitMix64 rng_;
  std::uint64_t done_ = 0;
  double x_ = 0.0;  // [mm] current position, as the interpreter computes it
  double y_ = 0.0;  // [mm]
  double z_ = 0.0;  // [mm]
  bool feed_set_ = false;
};

/// The whole program in one string (prologue, `options.blocks` body blocks, epilogue).
std::string generate_program(Dialect dialect, GeneratorOptions options);

}  // namespace ncsim::bench
