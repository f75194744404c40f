// cli/workpiece_report: the time per workpiece in `ncsim time` (see the header).

#include "cli/workpiece_report.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <string>

#include "cli/number_format.hpp"

namespace ncsim::cli {

WorkpieceReport::WorkpieceReport(bool json) : json_(json), spool_(std::tmpfile()) {
  if (!spool_) throw std::runtime_error("cannot create a temporary file for the workpiece rows");
}

void WorkpieceReport::on_row(const audit::WorkpieceCycle& r) {
  std::string s;
  if (json_) {
    if (rows_ != 0) s += ',';
    audit::append_json(s, r);
  } else {
    s = "workpiece " + std::to_string(r.index);
    if (r.workpiece != 0) s += " [#" + std::to_string(r.workpiece) + "]";
    s += ": waiting " + human(r.waiting) + " s, catch-up " + human(r.catch_up) + " s, machining " +
         human(r.machining) + " s, desync " + human(r.desync) + " s, off belt " +
         human(r.off_belt) + " s, total " + human(r.total) + " s" +
         (r.complete ? "" : " (incomplete)") + "\n";
  }
  ++rows_;
  if (!failed_ && std::fwrite(s.data(), 1, s.size(), spool_.get()) != s.size()) failed_ = true;
}

bool WorkpieceReport::finish(const audit::WorkpieceSummary& w, std::ostream& out) {
  if (w.workpieces == 0) return !failed_;
  if (json_) out << ",\"workpieces\":[";
  if (!failed_ && std::fflush(spool_.get()) == 0 && std::fseek(spool_.get(), 0, SEEK_SET) == 0) {
    std::array<char, 4096> buf{};
    std::size_t n = 0;
    while ((n = std::fread(buf.data(), 1, buf.size(), spool_.get())) > 0)
      out.write(buf.data(), static_cast<std::streamsize>(n));
    if (std::ferror(spool_.get())) failed_ = true;
  } else {
    failed_ = true;
  }
  if (json_) {
    out << "],\"workpiece_summary\":";
    std::string summary;
    audit::append_json(summary, w);
    out << summary;
  } else {
    out << "workpieces: " << w.complete << " complete of " << w.workpieces << "; lead-in "
        << human(w.lead_in) << " s; waiting " << human(w.sum.waiting) << " s, catch-up "
        << human(w.sum.catch_up) << " s, machining " << human(w.sum.machining) << " s, desync "
        << human(w.sum.desync) << " s, off belt " << human(w.sum.off_belt) << " s";
    if (w.complete > 0)
      out << "; per workpiece " << human(w.total_min) << " to " << human(w.total_max) << " s; "
          << human(w.per_minute) << " per minute";
    out << '\n';
  }
  return !failed_;
}

}  // namespace ncsim::cli
