// The line page: the line's series decimated with the belt and each channel's lanes, the
// channels' run data embedded, no data string can close its script element, byte-identical.

#include "report/line_page.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "report/html.hpp"

namespace {

using namespace ncsim::report;

ReportData channel_data(const std::string& program) {
  ReportData d;
  d.program = program;
  d.machine = "portal_3x";
  d.t_cycle = 0.001;
  d.axes = {"X"};
  d.time.t = {0.001};
  d.time.series.assign(7, {1.0});
  d.path_dims = 1;
  d.verdict.axes.resize(1);
  return d;
}

LineReportData sample() {
  LineRecorder r(2, true);
  const std::array<LaneState, 2> a{LaneState::running, LaneState::waiting};
  const std::array<LaneState, 2> b{LaneState::ended, LaneState::running};
  r.add(0.001, 0.3, 300.0, a);
  r.add(0.002, 0.6, 300.0, b);
  return r.finish("line</script>.toml", "two <b>robots</b>",
                  R"({"line":"x</script>","channels":[],"workpieces":{"fates":[]}})",
                  {channel_data("a.nc"), channel_data("b.nc")});
}

std::string page(const LineReportData& d) {
  std::ostringstream os;
  write_line_html(d, os);
  return os.str();
}

TEST_CASE("the line recorder keeps the belt and each channel's running and waiting lanes") {
  const LineReportData d = sample();
  REQUIRE(d.time.series.size() == 6);
  CHECK(d.belt);
  CHECK(d.time.series[1].front() == 300.0);
  // Channel 1 ran then ended; channel 2 waited then ran.
  CHECK(d.time.series[2] == std::vector<double>{1.0, 0.0});
  CHECK(d.time.series[3] == std::vector<double>{0.0, 0.0});
  CHECK(d.time.series[4] == std::vector<double>{0.0, 1.0});
  CHECK(d.time.series[5] == std::vector<double>{1.0, 0.0});
  const std::array<LaneState, 1> one{LaneState::running};
  LineRecorder wrong(2, true);
  CHECK_THROWS_AS(wrong.add(0.001, 0.0, 0.0, one), std::invalid_argument);
}

TEST_CASE("a line without a belt has no belt values") {
  LineRecorder r(1, false);
  const std::array<LaneState, 1> one{LaneState::running};
  r.add(0.001, 5.0, 6.0, one);
  const LineReportData d = r.finish("l.toml", "", "{}", {channel_data("a.nc")});
  CHECK_FALSE(d.belt);
  CHECK(std::isnan(d.time.series[0].front()));
  CHECK(page(d).find("\"belt\":false,") != std::string::npos);
}

TEST_CASE("the line page embeds the summary and every channel's run data, script-safe") {
  const std::string p = page(sample());
  std::size_t closes = 0;
  for (std::size_t at = p.find("</script"); at != std::string::npos;
       at = p.find("</script", at + 1))
    ++closes;
  CHECK(closes == 4);  // error capture, data, uPlot, page
  CHECK(p.find("<title>ncsim line report: line&lt;/script&gt;.toml</title>") != std::string::npos);
  CHECK(p.find(R"("kind":"line")") != std::string::npos);
  CHECK(p.find(R"("summary":{"line":"x\u003c/script\u003e","channels":[])") != std::string::npos);
  CHECK(p.find(R"("runs":[{"program":"a.nc",)") != std::string::npos);
  CHECK(p.find(R"(},{"program":"b.nc",)") != std::string::npos);
  CHECK(page(sample()) == p);
}

}  // namespace
