// interp/tech_functions: see tech_functions.hpp.

#include "interp/tech_functions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ncsim::interp {
namespace {

machines::TechFunction lookup(const Tech& f, const machines::TechTable& table) {
  const auto number = [&]() { return static_cast<std::uint32_t>(std::llround(f.value)); };
  const auto in = [&](const std::map<std::uint32_t, machines::TechFunction>& m) {
    // numbers outside the lists' 0..999 (and non-integer ones) are never configured
    if (!(f.value >= 0.0 && f.value <= 999.0) || f.value != std::floor(f.value))
      return machines::TechFunction{};
    const auto it = m.find(number());
    return it == m.end() ? machines::TechFunction{} : it->second;
  };
  switch (f.kind) {
    case TechKind::m:
      return in(table.m);
    case TechKind::h:
      return in(table.h);
    case TechKind::s:
      return table.s;
    case TechKind::t:
      return table.t;
    case TechKind::d:
      break;
  }
  return machines::TechFunction{};
}

void longest(std::optional<double>& wait, double duration) {
  wait = std::max(wait.value_or(0.0), duration);
}

}  // namespace

TechWaits resolve_tech(std::vector<Tech>& functions, const machines::TechTable& table) {
  TechWaits w;
  for (Tech& f : functions) {
    const machines::TechFunction cfg = lookup(f, table);
    f.sync = cfg.sync;
    switch (cfg.sync) {
      case machines::TechSync::mvs_svs:
        longest(w.before, cfg.duration);
        break;
      case machines::TechSync::mvs_sns:
        if (cfg.duration > 0.0) longest(w.since, cfg.duration);
        break;
      case machines::TechSync::mns_sns:
        longest(w.after, cfg.duration);
        break;
      case machines::TechSync::none:
      case machines::TechSync::mos:
        break;
    }
  }
  return w;
}

}  // namespace ncsim::interp
