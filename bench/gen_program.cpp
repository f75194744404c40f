// gen_program: writes the benchmark program in both dialects from one block sequence.
//
//   gen_program --blocks 1000000 --seed 1 --nc bench.nc --ngc bench.ngc
//
// Either output may be left out. The same arguments always give the same bytes (see
// bench/grammar_generator.hpp). Exit status 0 on success, 2 on bad arguments or I/O errors.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "bench/grammar_generator.hpp"

namespace {

class Output {
 public:
  Output(const std::string& path, ncsim::bench::Dialect dialect)
      : path_(path), dialect_(dialect), out_(path, std::ios::binary | std::ios::trunc) {
    if (!out_) throw std::runtime_error("cannot open '" + path + "' for writing");
    out_ << ncsim::bench::ProgramGenerator::prologue(dialect_);
  }
  void write(const std::string& chunk) { out_.write(chunk.data(), chunk.size()); }
  void finish() {
    out_ << ncsim::bench::ProgramGenerator::epilogue(dialect_);
    out_.close();
    if (!out_) throw std::runtime_error("cannot write '" + path_ + "'");
  }

 private:
  std::string path_;
  ncsim::bench::Dialect dialect_;
  std::ofstream out_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Generate the ncsim grammar benchmark program (ISG .nc and RS274/NGC .ngc)"};
  ncsim::bench::GeneratorOptions options;
  std::string nc_path;
  std::string ngc_path;
  app.add_option("--blocks", options.blocks, "number of body blocks")->check(CLI::PositiveNumber);
  app.add_option("--seed", options.seed, "generator seed");
  app.add_option("--nc", nc_path, "ISG program to write (.nc)");
  app.add_option("--ngc", ngc_path, "RS274/NGC program to write (.ngc)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (nc_path.empty() && ngc_path.empty()) {
    std::cerr << "gen_program: give --nc FILE and/or --ngc FILE\n";
    return 2;
  }
  try {
    std::optional<Output> nc;
    std::optional<Output> ngc;
    if (!nc_path.empty()) nc.emplace(nc_path, ncsim::bench::Dialect::isg);
    if (!ngc_path.empty()) ngc.emplace(ngc_path, ncsim::bench::Dialect::rs274ngc);
    ncsim::bench::ProgramGenerator generator(options);
    std::string chunk;
    constexpr std::size_t kChunkBytes = 1 << 20;
    bool more = true;
    while (more) {
      chunk.clear();
      while (chunk.size() < kChunkBytes && (more = generator.next(chunk))) {
      }
      if (nc) nc->write(chunk);
      if (ngc) ngc->write(chunk);
    }
    if (nc) nc->finish();
    if (ngc) ngc->finish();
  } catch (const std::exception& e) {
    std::cerr << "gen_program: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
