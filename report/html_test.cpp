// The page: self-contained (uPlot inlined, no URL loaded), byte-identical for the same data,
// and no data string can close its script element.

#include "report/html.hpp"

#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "report/assets.hpp"

namespace {

using namespace ncsim::report;

ReportData sample() {
  ReportData d;
  d.program = "a</script><b>.nc";
  d.machine = "m\"1";
  d.t_cycle = 0.001;
  d.axes = {"X", "Y"};
  d.time.t = {0.001, 0.002};
  d.time.series.assign(12, {1.0, 2.0});
  d.path_dims = 2;
  d.path_mcs = {0, 0, 1, 1};
  d.error = "p.nc:3:1: error: run-time error </script>";
  d.outcome = "error";
  d.verdict.axes.resize(2);
  return d;
}

std::string page(const ReportData& d) {
  std::ostringstream os;
  write_html(d, os);
  return os.str();
}

TEST_CASE("the page inlines uPlot and loads nothing from elsewhere") {
  const std::string p = page(sample());
  CHECK(uplot_js().size() > 10000);
  CHECK(p.find(std::string(uplot_js().substr(0, 200))) != std::string::npos);
  CHECK(p.find(std::string(uplot_css().substr(0, 100))) != std::string::npos);
  CHECK(p.find("src=") == std::string::npos);
  CHECK(p.find("href=") == std::string::npos);
  CHECK(p.find("<link") == std::string::npos);
  CHECK(p.find("@import") == std::string::npos);
  CHECK(p.find("url(") == std::string::npos);
  CHECK(p.find("fetch(") == std::string::npos);
  CHECK(p.find("uPlot " + std::string(uplot_version())) != std::string::npos);
}

TEST_CASE("data strings cannot close the script element; reruns are byte-identical") {
  const std::string p = page(sample());
  // One closing tag per script element: error capture, data, uPlot, page.
  std::size_t closes = 0;
  for (std::size_t at = p.find("</script"); at != std::string::npos;
       at = p.find("</script", at + 1))
    ++closes;
  CHECK(closes == 4);
  CHECK(p.find("<title>ncsim report: a&lt;/script&gt;&lt;b&gt;.nc</title>") != std::string::npos);
  CHECK(page(sample()) == p);
}

TEST_CASE("json_quote escapes quotes, control characters and markup") {
  CHECK(json_quote("a\"b\\c\n<&>") == "\"a\\\"b\\\\c\\u000a\\u003c\\u0026\\u003e\"");
}

}  // namespace
