// machines/tech_sync: the channel list's technology functions, read into ChannelParams::tech
// (docs/interp.md "Technology functions").
//
// Inputs: the validated channel list. Outputs: TechTable (synchronisation type and execution
// time per M / H number, the S and T functions) and diagnostics.
// Method: a synchronisation value is a TF5200 constant or its hex value (P-CHAN-00041's table:
// NO_SYNCH 0x0, MOS 0x1, MVS_SVS 0x2, MVS_SNS 0x4, MNS_SNS 0x8), optionally joined with
// PLC_INFO (0x00020000, the spindle's "inform the PLC") or BWD_SYNCH / FWD_SYNCH (0x00400000 /
// 0x00800000: backward motion, which ncsim has none of), which change nothing here. The other
// types (MNE_SNS, the late MVS_SLM / MVS_SLP, MOS_TS, the pre-output MEP_ / MET_ types,
// FAW_SYNCH) are NC3013 `not supported` at their line, as is a value with two base types.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "machines/loader_detail.hpp"

namespace ncsim::machines::detail {
namespace {

constexpr std::uint32_t kPlcInfo = 0x00020000;
constexpr std::uint32_t kBackward = 0x00400000;
constexpr std::uint32_t kForward = 0x00800000;
constexpr std::uint32_t kNoEffect = kPlcInfo | kBackward | kForward;

struct Named {
  std::string_view name;
  std::uint32_t bits;
};
constexpr Named kNames[] = {
    {"NO_SYNCH", 0x0}, {"MOS", 0x1},           {"MVS_SVS", 0x2},         {"MVS_SNS", 0x4},
    {"MNS_SNS", 0x8},  {"PLC_INFO", kPlcInfo}, {"BWD_SYNCH", kBackward}, {"FWD_SYNCH", kForward}};
constexpr std::string_view kUnsupported[] = {"MNE_SNS", "MVS_SLM", "MVS_SLP", "MOS_TS",   "MEP_SVS",
                                             "MET_SVS", "MEP_MOS", "MET_MOS", "FAW_SYNCH"};

// The bits of a value: hex, or names joined by '|'; nullopt with `why` set when not usable.
std::optional<std::uint32_t> parse_bits(const std::string& text, std::string& why) {
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    const std::optional<double> v = parse_integer(text);
    if (!v || *v > 4294967295.0) {
      why =
          "expects a synchronisation type or a hex value of at most 8 digits, found '" + text + "'";
      return std::nullopt;
    }
    return static_cast<std::uint32_t>(*v);
  }
  std::uint32_t bits = 0;
  for (const std::string& name : split_flags(text)) {
    bool found = false;
    for (const Named& n : kNames)
      if (n.name == name) {
        bits |= n.bits;
        found = true;
      }
    if (found) continue;
    for (std::string_view u : kUnsupported)
      if (u == name) {
        why = "not supported: synchronisation type " + name +
              " (ncsim runs NO_SYNCH, MOS, MVS_SVS, MVS_SNS and MNS_SNS)";
        return std::nullopt;
      }
    why = "unknown synchronisation type '" + name +
          "' (NO_SYNCH, MOS, MVS_SVS, MVS_SNS, MNS_SNS, or a hex value)";
    return std::nullopt;
  }
  return bits;
}

std::optional<TechSync> to_sync(std::uint32_t bits, std::string& why) {
  const std::uint32_t base = bits & ~kNoEffect;
  switch (base) {
    case 0x0:
      return TechSync::none;
    case 0x1:
      return TechSync::mos;
    case 0x2:
      return TechSync::mvs_svs;
    case 0x4:
      return TechSync::mvs_sns;
    case 0x8:
      return TechSync::mns_sns;
    default:
      break;
  }
  why = "not supported: synchronisation bits " + hex_text(base) +
        " (ncsim runs one of NO_SYNCH 0x0, MOS 0x1, MVS_SVS 0x2, MVS_SNS 0x4, MNS_SNS 0x8, with "
        "PLC_INFO / BWD_SYNCH / FWD_SYNCH)";
  return std::nullopt;
}

// The index of a one-index key ("m_synch[12]" -> 12).
std::uint32_t index_of(const std::string& key) {
  const std::size_t open = key.find('[');
  return static_cast<std::uint32_t>(std::stoul(key.substr(open + 1)));
}

void read_sync(const ListValues& v, const StoredValue& e, TechFunction& f,
               core::DiagnosticList& diagnostics) {
  std::string why;
  std::optional<TechSync> sync;
  if (const auto bits = parse_bits(e.text, why)) sync = to_sync(*bits, why);
  if (!sync) {
    diagnostics.add(make_diag(core::Severity::error, v.file(), e.loc,
                              why.rfind("not supported", 0) == 0 ? "NC3013" : "NC3003",
                              param_ref(e.key, ListKind::channel) + ": " + why));
    return;
  }
  f.sync = *sync;
}

}  // namespace

void read_tech_table(ChannelParams& ch, const ListValues& v, core::DiagnosticList& diagnostics) {
  TechTable& t = ch.tech;
  for (const StoredValue* e : v.matching("m_synch[]"))  // P-CHAN-00041
    read_sync(v, *e, t.m[index_of(e->key)], diagnostics);
  for (const StoredValue* e : v.matching("h_synch[]"))  // P-CHAN-00027
    read_sync(v, *e, t.h[index_of(e->key)], diagnostics);
  for (const StoredValue* e : v.matching("spindel[].s_synch"))  // P-CHAN-00081
    read_sync(v, *e, t.s, diagnostics);
  if (const StoredValue* e = v.find("tool.synch")) read_sync(v, *e, t.t, diagnostics);  // 00086
  for (const StoredValue* e : v.matching("ncsim.m_duration[]"))  // NCSIM-CHAN-650
    t.m[index_of(e->key)].duration = v.internal(e->key);
  for (const StoredValue* e : v.matching("ncsim.h_duration[]"))  // NCSIM-CHAN-651
    t.h[index_of(e->key)].duration = v.internal(e->key);
  t.s.duration = v.internal("ncsim.s_duration");  // NCSIM-CHAN-652
  t.t.duration = v.internal("ncsim.t_duration");  // NCSIM-CHAN-653
}

}  // namespace ncsim::machines::detail
