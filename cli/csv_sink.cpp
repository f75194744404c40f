#include "cli/csv_sink.hpp"

#include <cerrno>

#include "cli/number_format.hpp"

namespace ncsim::cli {

void write_tech(const channel::Channel& channel, CsvSink& csv) {
  static constexpr char kLetter[] = {'M', 'H', 'S', 'T', 'D'};
  for (const channel::TechOutput& o : channel.tech_outputs()) {
    std::string s = "# tech t=" + num(o.t) + " line=" + std::to_string(o.line);
    if (o.file != 0) s += " file=" + std::to_string(o.file);
    s += ' ';
    s += kLetter[static_cast<std::size_t>(o.kind)];
    s += num(o.value);
    if (o.extra) s += '=' + num(*o.extra);
    s += '\n';
    csv.text(s);
  }
}

}  // namespace ncsim::cli
