#include "grammar/keywords.hpp"

#include <algorithm>
#include <iterator>

namespace ncsim::grammar {
namespace {

using V = ValueKind;

// #SYNC IN: TF5264 (seed 004) "Syntax of #SYNC IN / #SYNC OUT"; isg-language.md §5.13.
constexpr KeywordSpec kSyncIn[] = {{"CONVEYOR", V::word},
                                   {"CONV_VEL", V::expr},
                                   {"VEL_RESOLUTION", V::word},
                                   {"FEED_CONT", V::expr},
                                   {"FEED_CONT_AUTO", V::none}};
constexpr KeywordSpec kSyncOut[] = {{"FEED_CONT", V::expr}, {"FEED_CONT_AUTO", V::none}};
// #CAXTRACK: isg-language.md §5.7.
constexpr KeywordSpec kCaxOn[] = {
    {"ANGLIMIT", V::expr},  {"OFFSET", V::expr}, {"OPTALIGN", V::expr}, {"ROTMODE", V::expr},
    {"SCALEFACT", V::expr}, {"AX", V::word},     {"AXNR", V::expr},     {"START_STROKE", V::none}};
constexpr KeywordSpec kCaxOff[] = {{"ANGPOS", V::expr}};
// #CONTOUR MODE: isg-language.md §5.3.
constexpr KeywordSpec kContour[] = {{"DEV", V::none},
                                    {"DIST", V::none},
                                    {"DIST_SOFT", V::none},
                                    {"DIST_MASTER", V::none},
                                    {"POS", V::none},
                                    {"PTP", V::none},
                                    {"PATH_DEV", V::expr},
                                    {"RELEVANT_PATH", V::expr},
                                    {"TRACK_DEV", V::expr},
                                    {"RELEVANT_TRACK", V::expr},
                                    {"REMAIN_PART", V::expr},
                                    {"CHECK_JERK", V::opt_expr},
                                    {"MAX_ANGLE", V::expr},
                                    {"CONST_VEL", V::opt_expr},
                                    {"PRE_DIST", V::expr},
                                    {"POST_DIST", V::expr},
                                    {"PATH_DIST", V::expr},
                                    {"MERGE", V::opt_expr},
                                    {"PRE_ACTION", V::opt_expr},
                                    {"INTER_ACTION", V::opt_expr},
                                    {"POST_ACTION", V::opt_expr}};
// #SLOPE: isg-language.md §5.5.
constexpr KeywordSpec kSlope[] = {{"TYPE", V::word}, {"NO_OPT", V::expr}};
// #MACHINE DATA: isg-language.md §5.10 (parameter ids are open).
constexpr KeywordSpec kMachineData[] = {{"SYN", V::none},
                                        {"AX", V::word},
                                        {"AXNR", V::expr},
                                        {"AXPARAM", V::string},
                                        {"WAIT", V::none}};
constexpr KeywordSpec kTrafo[] = {
    {"ON", V::none}, {"OFF", V::none}, {"NONE", V::none}, {"DEFAULT", V::none}};
constexpr KeywordSpec kMsg[] = {
    {"SYN", V::none},       {"SYN_ACK", V::none},  {"ACK", V::none},          {"SAVE", V::none},
    {"EXCLUSIVE", V::none}, {"CONTINUE", V::none}, {"ISG_DIAG_BED", V::none}, {"DIAG", V::none},
    {"HMI", V::none},       {"PLC", V::none},      {"EVENT_LOGGER", V::none}};
// Independent axes: isg-language.md §6.1 (PROG-208612235) plus INTERRUPTIBLE (TF5264 examples).
constexpr KeywordSpec kIndp[] = {{"INDP_SYN", V::none},
                                 {"INDP_ASYN", V::none},
                                 {"G", V::code},
                                 {"FEED", V::expr},
                                 {"TIME", V::expr},
                                 {"FEED_MAX_WEIGHT", V::expr},
                                 {"POS", V::expr},
                                 {"SLOPE_TYPE", V::word},
                                 {"M", V::expr},
                                 {"H", V::expr},
                                 {"DRY_RUN", V::none},
                                 {"ACC_WEIGHT", V::expr},
                                 {"RAPID_ACC_WEIGHT", V::expr},
                                 {"INCL_OFFSETS", V::none},
                                 {"INTERRUPTIBLE", V::none}};
// PLCopen: isg-language.md §6.3 (PROG-208363915, PROG-306968203).
constexpr KeywordSpec kMcMoveVelocity[] = {{"MC_MOVEVELOCITY", V::none},
                                           {"VELOCITY", V::expr},
                                           {"ACCELERATION", V::expr},
                                           {"DECELERATION", V::expr},
                                           {"JERK", V::expr},
                                           {"DIRECTION", V::expr},
                                           {"ID", V::expr},
                                           {"WAITSYN", V::none},
                                           {"WAIT_SYN", V::none}};
constexpr KeywordSpec kMcTouchProbe[] = {{"MC_TOUCHPROBE", V::none}, {"CHANNEL", V::expr},
                                         {"MODE", V::expr},          {"ID", V::expr},
                                         {"WAITSYN", V::none},       {"WAIT_SYN", V::none}};
// The other MC_* commands: PLCopen input names (isg-language.md §6.3 [I]).
constexpr KeywordSpec kMcOther[] = {{"MC_HOME", V::none},
                                    {"MC_MOVEABSOLUTE", V::none},
                                    {"MC_MOVEADDITIVE", V::none},
                                    {"MC_MOVERELATIVE", V::none},
                                    {"MC_MOVESUPERIMPOSED", V::none},
                                    {"MC_STOP", V::none},
                                    {"MC_GEARIN", V::none},
                                    {"MC_GEAROUT", V::none},
                                    {"MC_PHASING", V::none},
                                    {"POSITION", V::expr},
                                    {"DISTANCE", V::expr},
                                    {"VELOCITY", V::expr},
                                    {"ACCELERATION", V::expr},
                                    {"DECELERATION", V::expr},
                                    {"JERK", V::expr},
                                    {"DIRECTION", V::expr},
                                    {"ID", V::expr},
                                    {"WAITSYN", V::none},
                                    {"WAIT_SYN", V::none},
                                    {"RATIONUMERATOR", V::expr},
                                    {"RATIODENOMINATOR", V::expr},
                                    {"MASTER", V::word},
                                    {"PHASESHIFT", V::expr},
                                    {"BUFFERMODE", V::expr},
                                    {"HOMINGMODE", V::expr}};
// L CYCLE [NAME=file @P1=..]: isg-language.md §4.9 (parameter names are open).
constexpr KeywordSpec kCycle[] = {{"NAME", V::word}};
// #HSC [...]: TF5200 "HSC" (PATH_DEV / TRACK_DEV in mm; the mode words as flags).
constexpr KeywordSpec kHsc[] = {
    {"PATH_DEV", V::expr}, {"TRACK_DEV", V::expr}, {"BSPLINE", V::none},     {"SURFACE", V::none},
    {"OPT", V::opt_expr},  {"MERGE", V::opt_expr}, {"CONTOUR_DEV", V::expr}, {"AX_DEV", V::expr}};
// #VECTOR LIMIT ON [...] (PROG-207477899): values in mm/min, mm/min^2 (or the channel's unit).
constexpr KeywordSpec kVectorLimit[] = {
    {"ACC", V::opt_expr},         {"DEC", V::opt_expr},  {"RADIAL_ACC", V::opt_expr},
    {"RADIAL_JERK", V::opt_expr}, {"JERK", V::opt_expr}, {"TRANS_ACC", V::opt_expr},
    {"VEL", V::opt_expr},         {"FEED", V::none},     {"RAPID", V::none}};
// #SIGNAL / #WAIT / #SIGNAL READ (PROG-207409035, PROG-207421579, PROG-913718283): read by
// grammar/hash_commands.hpp's own list reader (P[i]=.. is indexed, `IDP100` has no '=').
// #SIGNAL REMOVE [ID=.. | IDMIN=.. [IDMAX=..] {CH=..}] (PROG-207414923).
constexpr KeywordSpec kSignal[] = {{"ID", V::expr},   {"COUNT", V::expr}, {"CH", V::expr},
                                   {"P", V::expr},    {"AHEAD", V::none}, {"IDMIN", V::expr},
                                   {"IDMAX", V::expr}};
// #TANGFEED [RMIN=..] (PROG-207065483) and its old form #SET TANGFEED RMIN [..]: mm (inch).
constexpr KeywordSpec kTangfeed[] = {{"RMIN", V::expr}};
constexpr KeywordSpec kNone[] = {{"", V::none}};

const KeywordTable kTables[] = {
    /* none */ {std::span(kNone).first(0)},
    /* sync_in */ {kSyncIn},
    /* sync_out */ {kSyncOut},
    /* caxtrack_on */ {kCaxOn},
    /* caxtrack_off */ {kCaxOff},
    /* contour_mode */ {kContour},
    /* slope */ {kSlope},
    /* machine_data */ {kMachineData, true},
    /* transvelmin */ {std::span(kNone).first(0), false, true},
    /* wait_indp */ {std::span(kNone).first(0), true},
    /* trafo */ {kTrafo, false, true},
    /* kin_id */ {std::span(kNone).first(0), false, true},
    /* cs */ {std::span(kNone).first(0), false, true},
    /* msg */ {kMsg, false, true, true},
    /* time */ {std::span(kNone).first(0), false, true},
    /* delete_ */ {std::span(kNone).first(0), false, true},
    /* init */ {std::span(kNone).first(0), false, true},
    /* indp */ {kIndp},
    /* mc_move_velocity */ {kMcMoveVelocity},
    /* mc_touch_probe */ {kMcTouchProbe},
    /* mc_other */ {kMcOther},
    /* cycle */ {kCycle, true},
    /* g_params */ {std::span(kNone).first(0), false, true},
    /* file_name */ {std::span(kNone).first(0), true, false, true},
    /* hsc */ {kHsc},
    /* vector_limit */ {kVectorLimit},
    /* scale */ {std::span(kNone).first(0), true},
    /* signal */ {kSignal},
    /* tangfeed */ {kTangfeed, false, true},
};

struct FunctionName {
  std::string_view name;
  ast::Function function;
};
// isg-language.md §3.3 (PROG-205944843, VSC token list).
constexpr FunctionName kFunctions[] = {
    {"SIN", ast::Function::sin},     {"COS", ast::Function::cos},
    {"TAN", ast::Function::tan},     {"COT", ast::Function::cot},
    {"ASIN", ast::Function::asin},   {"ACOS", ast::Function::acos},
    {"ATAN", ast::Function::atan},   {"ACOT", ast::Function::acot},
    {"ATAN2", ast::Function::atan2}, {"SQRT", ast::Function::sqrt},
    {"SQR", ast::Function::sqr},     {"ABS", ast::Function::abs},
    {"INT", ast::Function::int_},    {"FRACT", ast::Function::fract},
    {"ROUND", ast::Function::round}, {"CEIL", ast::Function::ceil},
    {"FLOOR", ast::Function::floor}, {"EXP", ast::Function::exp},
    {"LN", ast::Function::ln},       {"DEXP", ast::Function::dexp},
    {"LOG", ast::Function::log},     {"SIZEOF", ast::Function::sizeof_},
    {"EXIST", ast::Function::exist},
};

// isg-language.md §2.2-2.4: the G codes of the motion, plane/unit/feed and transition/dynamics
// tables (some are names only there; the interpreter decides what it simulates).
constexpr std::uint32_t kSupportedG[] = {
    0,   1,   2,   3,   4,   8,   9,   12,  13,  17,  18,  19,  33,  53,  54,  55,
    56,  57,  58,  59,  60,  61,  63,  70,  71,  74,  90,  91,  92,  93,  94,  95,
    96,  97,  98,  99,  115, 116, 117, 127, 128, 129, 130, 131, 132, 133, 134, 150,
    151, 159, 160, 161, 162, 163, 164, 165, 166, 193, 194, 196, 230, 231, 233, 260,
    261, 293, 301, 302, 303, 331, 332, 333, 334, 338, 339, 359, 360, 900, 901};
// Tool radius compensation (isg-language.md §2.5; built, docs/trc.md): G25/G26 transitions,
// G40/G41/G42, G138/G139/G237/G239 selection, G10/G11 feed adaptation. Its other codes (G05,
// G236, G238) stay in kOtherG.
constexpr std::uint32_t kTrcG[] = {10, 11, 25, 26, 40, 41, 42, 138, 139, 237, 239};
// isg-language.md §2.5: real ISG G codes that ncsim does not simulate ("not supported").
constexpr std::uint32_t kOtherG[] = {5,   20,  21,  22,  23,  51,  52,  66,  68,  69,
                                     100, 101, 102, 106, 107, 108, 112, 135, 136, 137,
                                     140, 141, 200, 201, 202, 236, 238, 310, 351};

}  // namespace

const KeywordTable& keyword_table(ast::TableId id) {
  return kTables[static_cast<std::size_t>(id)];
}

std::string to_upper(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    c = ascii_upper(c);
  return out;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (ascii_upper(a[i]) != ascii_upper(b[i])) return false;
  }
  return true;
}

ast::Function function_by_name(std::string_view name) {
  if (name.empty()) return ast::Function::none;
  const char first = ascii_upper(name[0]);
  for (const auto& f : kFunctions) {
    if (f.name[0] == first && iequals(f.name, name)) return f.function;
  }
  return ast::Function::none;
}

std::string_view function_name(ast::Function f) {
  for (const auto& entry : kFunctions) {
    if (entry.function == f) return entry.name;
  }
  return {};
}

bool is_implicit_call_g(std::uint32_t code) {
  // PROG-206278923: G80-G89 and G800-G819 (G800-G839 in the extended configuration,
  // P-CHAN-00187 g800_prog_file[0..39]).
  return (code >= 80 && code <= 89) || (code >= 800 && code <= 839);
}

GClass classify_g(std::uint32_t code) {
  if (std::find(std::begin(kSupportedG), std::end(kSupportedG), code) != std::end(kSupportedG) ||
      std::find(std::begin(kTrcG), std::end(kTrcG), code) != std::end(kTrcG)) {
    return GClass::supported;
  }
  if (is_implicit_call_g(code)) return GClass::implicit_call;
  if (std::find(std::begin(kOtherG), std::end(kOtherG), code) != std::end(kOtherG)) {
    return GClass::not_supported;
  }
  return GClass::unknown;
}

bool known_m_code(std::uint32_t code) {
  // isg-language.md §2.6: M00-M06, M17, M19, M29, M30, M40-M45 are the kernel's own; every
  // other M up to M999 is a technology function passed to the PLC (decision,
  // docs/language.md "M codes").
  return code <= kMaxMCode;
}

}  // namespace ncsim::grammar
