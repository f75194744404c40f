#pragma once
// report/assets: the files the report page inlines, embedded at build time (report/CMakeLists:
// uPlot's dist files from report/web/node_modules, installed by scripts/deps.sh `npm ci`; the
// page's own page.js / page.css).
// Outputs: the text of each file. Invariants: none contains "</script" or "</style" (checked
// when the sources are generated; the build fails otherwise).

#include <string_view>

namespace ncsim::report {

std::string_view uplot_js() noexcept;       ///< uPlot.iife.min.js
std::string_view uplot_css() noexcept;      ///< uPlot.min.css
std::string_view page_js() noexcept;        ///< report/page.js
std::string_view page_css() noexcept;       ///< report/page.css
std::string_view uplot_version() noexcept;  ///< the pinned uPlot version (report/web/package.json)

}  // namespace ncsim::report
