#pragma once
// grammar/hash_commands: the grammar of each `#` command (internal). isg-language.md §5; each
// command reads its mode words, then its bracket lists with the command's own keyword table.
//
// parse_hash_command reads `#` and the command's name, then hands the rest of the block to the
// family's reader in kHashCommands (one function per command family). A reader sets the
// command's kind and keyword table (HashReader::set) and appends its items to the block; errors
// throw from State (fail, not_supported) at the position they name.

#include <algorithm>
#include <array>

#include "grammar/custom_rules.hpp"

namespace ncsim::grammar {

template <typename Input>
ast::HashKind expect_mode(Input& in, State& st, std::initializer_list<std::string_view> words,
                          std::initializer_list<ast::HashKind> kinds, const char* expected) {
  skip_ws(in, st);
  auto kind = kinds.begin();
  for (const std::string_view w : words) {
    if (accept(in, w)) return *kind;
    ++kind;
  }
  st.fail(in.current(), expected);
}

template <typename Input>
void parse_variable_list(Input& in, State& st) {
  for (;;) {
    skip_ws(in, st);
    if (in.empty() || in.peek_char() == ';') return;
    ast::Item item;
    item.kind = ast::ItemKind::positional;
    item.loc = st.loc(in.current());
    if (!match_rule<rules::variable>(in, st)) st.fail(in.current(), "a variable (V.x.NAME)");
    item.value = st.pop();
    st.block->items.push_back(item);
    skip_ws(in, st);
    if (!in.empty() && in.peek_char() == ',') in.bump(1);
  }
}

namespace hash {

using H = ast::HashKind;
using T = ast::TableId;

/// One `#` command being read: the input after its name, the parser state, the command so far.
template <typename Input>
struct HashReader {
  Input& in;
  State& st;
  ast::HashCommand cmd;
  std::string_view name;  // the command's name as written ("SYNC")
  const char* name_at;    // where the name starts (the `#` is one before)

  bool is(std::string_view w) const { return iequals(name, w); }
  void ws() { skip_ws(in, st); }
  bool word(std::string_view w) { return accept(in, w); }
  /// The next word, for a "not supported" text.
  std::string next_word() const { return std::string(lex::ident(lex::rest(in))); }
  void set(H kind, T table = T::none) {
    cmd.kind = kind;
    cmd.table = table;
    st.table = table;
    st.block->body = cmd;
  }
  /// Up to `max_lists` bracket lists (groups 0, 1, ...); `required`: the first one must be there.
  void lists(int max_lists, bool required) {
    for (int g = 0; g < max_lists; ++g) {
      ws();
      if (!parse_list(in, st, static_cast<std::uint8_t>(g))) {
        if (required && g == 0) st.fail(in.current(), "'['");
        return;
      }
    }
  }
  /// An item with a keyword and no value (`SYN` of #MACHINE DATA, `ALL` of #VECTOR LIMIT).
  void keyword_item(const char* at, std::string_view keyword, std::uint16_t key) {
    ast::Item item;
    item.loc = st.loc(at);
    item.key = key;
    item.keyword = keyword;
    st.block->items.push_back(item);
  }
};

template <typename Input>
void read_sync(HashReader<Input>& r) {  // §5.13, seed 004 "#SYNC IN / #SYNC OUT"
  const H k = expect_mode(r.in, r.st, {"IN", "OUT", "OFF"}, {H::sync_in, H::sync_out, H::sync_off},
                          "IN, OUT or OFF after #SYNC");
  r.set(k, k == H::sync_in ? T::sync_in : T::sync_out);
  r.lists(1, false);
}

template <typename Input>
void read_cs(HashReader<Input>& r) {  // §5.8: #CS and #BCS
  const bool b = r.is("BCS");
  r.ws();
  if (r.word("DEF")) {
    r.set(b ? H::bcs_def : H::cs_def, T::cs);
    r.lists(2, false);
  } else if (r.word("ON")) {
    r.set(b ? H::bcs_on : H::cs_on, T::cs);
    r.lists(2, false);
  } else if (r.word("OFF")) {
    r.ws();
    const bool all = r.word("ALL");
    r.set(all ? (b ? H::bcs_off_all : H::cs_off_all) : (b ? H::bcs_off : H::cs_off));
  } else {
    const std::string w = r.next_word();
    if (!w.empty()) r.st.not_supported(r.in.current(), "#" + std::string(r.name) + " " + w);
    r.st.fail(r.in.current(), "DEF, ON or OFF");
  }
}

template <typename Input>
void read_caxtrack(HashReader<Input>& r) {  // §5.7
  const H k = expect_mode(r.in, r.st, {"ON", "OFF"}, {H::caxtrack_on, H::caxtrack_off},
                          "ON or OFF after #CAXTRACK");
  r.set(k, k == H::caxtrack_on ? T::caxtrack_on : T::caxtrack_off);
  r.lists(1, false);
}

template <typename Input>
void read_spline_type(HashReader<Input>& r, const char* expected) {
  r.set(expect_mode(r.in, r.st, {"AKIMA", "BSPLINE"},
                    {H::spline_type_akima, H::spline_type_bspline}, expected));
}

template <typename Input>
void read_spline(HashReader<Input>& r) {  // §5.4
  r.ws();
  if (r.word("TYPE")) return read_spline_type(r, "AKIMA or BSPLINE after #SPLINE TYPE");
  r.set(expect_mode(r.in, r.st, {"ON", "OFF"}, {H::spline_on, H::spline_off},
                    "TYPE, ON or OFF after #SPLINE"));
}

template <typename Input>
void read_set(HashReader<Input>& r) {  // old spellings, §5.4
  r.ws();
  if (r.word("SPLINETYPE")) return read_spline_type(r, "AKIMA or BSPLINE after #SET SPLINETYPE");
  if (r.word("TANGFEED")) {  // the old #SET TANGFEED RMIN [..] (PROG-207065483)
    r.ws();
    if (!r.word("RMIN")) r.st.fail(r.in.current(), "RMIN after #SET TANGFEED");
    r.set(H::tangfeed, T::tangfeed);
    return r.lists(1, true);
  }
  if (!r.word("SPLINE")) r.st.not_supported(r.name_at - 1, "#SET " + r.next_word());
  r.set(expect_mode(r.in, r.st, {"ON", "OFF"}, {H::spline_on, H::spline_off},
                    "ON or OFF after #SET SPLINE"));
}

template <typename Input>
void read_contour(HashReader<Input>& r) {  // §5.3
  r.ws();
  if (!r.word("MODE")) r.st.fail(r.in.current(), "MODE after #CONTOUR");
  r.ws();
  if (r.word("OFF")) return r.set(H::contour_mode_off);
  r.set(r.word("ON") ? H::contour_mode_on : H::contour_mode, T::contour_mode);
  r.lists(1, false);
}

template <typename Input>
void read_slope(HashReader<Input>& r) {  // §5.5
  r.ws();
  if (r.word("DEFAULT")) return r.set(H::slope_default);
  r.set(H::slope, T::slope);
  if (!parse_list(r.in, r.st, 0)) r.st.fail(r.in.current(), "'[' or DEFAULT after #SLOPE");
}

template <typename Input>
void read_kin(HashReader<Input>& r) {  // §5.9
  r.ws();
  if (!r.word("ID")) r.st.fail(r.in.current(), "ID after #KIN");
  r.set(H::kin_id, T::kin_id);
  r.lists(1, true);
}

template <typename Input>
void read_trafo(HashReader<Input>& r) {  // §5.9
  r.ws();
  if (r.word("ON")) return r.set(H::trafo_on);
  if (r.word("OFF")) return r.set(H::trafo_off);
  r.set(H::trafo_steps, T::trafo);
  if (!parse_list(r.in, r.st, 0)) r.st.fail(r.in.current(), "ON, OFF or '[' after #TRAFO");
}

template <typename Input>
void read_machine(HashReader<Input>& r) {  // §5.10
  r.ws();
  if (!r.word("DATA")) r.st.fail(r.in.current(), "DATA after #MACHINE");
  r.set(H::machine_data, T::machine_data);
  r.ws();
  const char* mode_at = r.in.current();
  if (r.word("SYN")) {  // mode word without brackets, as in DIAG-21413's example
    r.keyword_item(mode_at, std::string_view(mode_at, 3), 0);
  }
  r.lists(2, true);
}

template <typename Input>
void read_msg(HashReader<Input>& r) {  // §5.11
  r.set(H::msg, T::msg);
  const KeywordTable& table = keyword_table(T::msg);
  for (;;) {
    r.ws();
    const std::string_view w = lex::ident(lex::rest(r.in));
    if (w.empty()) break;
    ast::Item item;
    item.loc = r.st.loc(r.in.current());
    item.keyword = w;
    for (std::size_t k = 0; k < table.entries.size(); ++k) {
      if (iequals(table.entries[k].name, w)) item.key = static_cast<std::uint16_t>(k);
    }
    r.st.block->items.push_back(item);
    r.in.bump(w.size());
  }
  r.ws();
  (void)parse_list(r.in, r.st, 1);
}

template <typename Input>
void read_flush(HashReader<Input>& r) {  // §5.1
  r.ws();
  r.set(r.word("CONTINUE") ? H::flush_continue : r.word("WAIT") ? H::flush_wait : H::flush);
}

template <typename Input>
void read_time(HashReader<Input>& r) {  // §5.2
  r.set(H::time, T::time);
  r.ws();
  ast::Item item;
  item.kind = ast::ItemKind::positional;
  item.loc = r.st.loc(r.in.current());
  item.value = parse_expression(r.in, r.st, "a time in seconds after #TIME");
  r.st.block->items.push_back(item);
}

template <typename Input>
void read_transvelmin(HashReader<Input>& r) {  // §5.6
  const H k = expect_mode(r.in, r.st, {"ON", "OFF"}, {H::transvelmin_on, H::transvelmin_off},
                          "ON or OFF after #TRANSVELMIN");
  r.set(k, T::transvelmin);
  if (k == H::transvelmin_on) r.lists(1, false);
}

/// The bracket list of #SIGNAL, #WAIT and #SIGNAL READ (PROG-207409035, PROG-207421579,
/// PROG-913718283): `ID=..` (also `ID4711`, `IDP100`), `COUNT=..`, `CH=..` (repeated),
/// `P[<idx>] = <value>`, `AHEAD`. Without '[' after the command (and its mode) the manual's
/// 20998. The items keep their keyword; P's index is Item::index, its right-hand side the value.
template <typename Input>
void read_signal_list(HashReader<Input>& r, H kind, const char* command) {
  r.set(kind, T::signal);
  r.ws();
  if (r.in.empty() || r.in.peek_char() != '[') {
    r.st.fail_message(r.in.current(), "20998",
                      std::string("after ") + command +
                          " the keyword SYN or an open bracket '[' must follow, found " +
                          lex::describe(r.in.current(), r.in.current() + r.in.size()));
  }
  r.in.bump(1);
  r.st.group = 0;
  const KeywordTable& table = keyword_table(T::signal);
  for (;;) {
    r.ws();
    if (r.in.empty()) r.st.fail(r.in.current(), "']'");
    if (r.in.peek_char() == ']') break;
    const char* at = r.in.current();
    const std::string_view rest = lex::rest(r.in);
    ast::Item item;
    item.loc = r.st.loc(at);
    item.kind = ast::ItemKind::keyword;
    if (lex::ident(rest).size() == 5 && iequals(lex::ident(rest), "AHEAD")) {
      r.st.not_supported(at, std::string(command) +
                                 " ... AHEAD (the manual's text on it was not "
                                 "retrieved; docs/lines.md)");
    }
    // A keyword is a prefix: its value may follow without '=' (ID4711, IDP100, CH2).
    std::size_t key = ast::kUnknownKeyword;
    for (std::size_t k = 0; k < table.entries.size(); ++k) {
      const std::string_view name = table.entries[k].name;
      if (rest.size() >= name.size() && iequals(rest.substr(0, name.size()), name) &&
          (key == ast::kUnknownKeyword || name.size() > table.entries[key].name.size()))
        key = k;
    }
    const bool indexed = key != ast::kUnknownKeyword && table.entries[key].name == "P";
    if (key == ast::kUnknownKeyword || table.entries[key].value == ValueKind::none ||
        (indexed && rest.substr(1).substr(lex::blanks(rest.substr(1))).substr(0, 1) != "[")) {
      r.st.fail(at, "ID=.., COUNT=.., P[<index>]=.., CH=.., IDMIN=.., IDMAX=.. or ']'");
    }
    item.key = static_cast<std::uint16_t>(key);
    item.keyword = rest.substr(0, table.entries[key].name.size());
    r.in.bump(item.keyword.size());
    r.ws();
    if (indexed) {
      r.in.bump(1);  // '['
      item.index = parse_expression(r.in, r.st, "a signal parameter index after 'P['");
      r.ws();
      if (r.in.empty() || r.in.peek_char() != ']') r.st.fail(r.in.current(), "']'");
      r.in.bump(1);
      r.ws();
      if (r.in.empty() || r.in.peek_char() != '=') r.st.fail(r.in.current(), "'=' after P[..]");
    }
    if (!r.in.empty() && r.in.peek_char() == '=') r.in.bump(1);
    r.ws();
    item.value = parse_expression(r.in, r.st, "a value after the keyword");
    r.st.block->items.push_back(item);
  }
  r.in.bump(1);  // ']'
}

/// #SIGNAL [SYN] [..], #SIGNAL READ [..], #SIGNAL REMOVE [SYN] [..] (PROG-207409035,
/// PROG-913718283, PROG-207414923).
template <typename Input>
void read_signal(HashReader<Input>& r) {
  r.ws();
  const char* mode_at = r.in.current();
  if (r.word("READ")) {
    r.ws();
    if (r.word("SYN")) {
      r.st.fail_message(mode_at, "NC1010",
                        "#SIGNAL READ SYN is not permitted: #SIGNAL READ works at interpreter "
                        "level only (PROG-913718283)");
    }
    return read_signal_list(r, H::signal_read, "#SIGNAL READ");
  }
  if (r.word("REMOVE")) {  // PROG-207414923
    r.ws();
    if (r.word("SYN")) return read_signal_list(r, H::signal_remove_syn, "#SIGNAL REMOVE SYN");
    return read_signal_list(r, H::signal_remove, "#SIGNAL REMOVE");
  }
  if (r.word("SYN")) return read_signal_list(r, H::signal_syn, "#SIGNAL SYN");
  read_signal_list(r, H::signal, "#SIGNAL");
}

template <typename Input>
void read_wait(HashReader<Input>& r) {  // §6.1; #WAIT [SYN] [..] PROG-207421579
  r.ws();
  if (r.word("SYN")) return read_signal_list(r, H::wait_signal_syn, "#WAIT SYN");
  if (!r.in.empty() && r.in.peek_char() == '[') return read_signal_list(r, H::wait_signal, "#WAIT");
  if (!r.word("INDP")) {
    if (r.next_word().empty()) read_signal_list(r, H::wait_signal, "#WAIT");  // 20998
    r.st.not_supported(r.name_at - 1, "#WAIT " + r.next_word());
  }
  r.ws();
  if (r.word("ALL")) return r.set(H::wait_indp_all);
  r.set(H::wait_indp, T::wait_indp);
  r.lists(1, true);
}

template <typename Input>
void read_variables(HashReader<Input>& r) {  // #DELETE §3.6, #INIT §3.5
  const bool del = r.is("DELETE");
  r.set(del ? H::delete_ : H::init, del ? T::delete_ : T::init);
  parse_variable_list(r.in, r.st);
}

template <typename Input>
void read_file_name(HashReader<Input>& r) {  // P-CHAN-00160 remarks: #FILE NAME [G80="x"]
  if (r.is("FILE")) {
    r.ws();
    if (!r.word("NAME")) r.st.fail(r.in.current(), "NAME after #FILE");
  }
  r.set(H::file_name, T::file_name);
  r.lists(1, true);
}

template <typename Input>
void read_hsc(HashReader<Input>& r) {  // TF5200 "HSC": #HSC ON [...] / #HSC OFF / #HSC [...]
  r.ws();
  if (r.word("OFF")) return r.set(H::hsc_off);
  (void)r.word("ON");
  r.set(H::hsc_on, T::hsc);
  r.lists(1, false);
}

template <typename Input>
void read_tangfeed(HashReader<Input>& r) {  // #TANGFEED [RMIN=..] PROG-207065483
  r.set(H::tangfeed, T::tangfeed);
  r.lists(1, false);
}

template <typename Input>
void read_vector(HashReader<Input>& r) {  // PROG-207477899
  r.ws();
  if (!r.word("LIMIT")) r.st.not_supported(r.name_at - 1, "#VECTOR " + r.next_word());
  const H k = expect_mode(r.in, r.st, {"ON", "OFF"}, {H::vector_limit_on, H::vector_limit_off},
                          "ON or OFF after #VECTOR LIMIT");
  r.set(k, T::vector_limit);
  r.ws();
  if (r.word("ALL")) return r.keyword_item(r.in.current() - 3, "ALL", ast::kUnknownKeyword);
  r.lists(1, false);
}

// PROG-207656459 #SCALE [ON] X2 Y2 / OFF; PROG-207101835 #PSET X200 Y0
template <typename Input>
void read_scale(HashReader<Input>& r) {
  r.ws();
  const bool scale = r.is("SCALE");
  if (scale && r.word("OFF")) return r.set(H::scale_off);
  if (scale) (void)r.word("ON");
  r.set(scale ? H::scale_on : H::pset, T::scale);
  for (;;) {  // axis name (letters, then digits) and its factor
    r.ws();
    const std::string_view rest = lex::rest(r.in);
    if (rest.empty() || !lex::is_alpha(rest[0])) break;
    std::size_t n = 0;
    while (n < rest.size() && lex::is_alpha(rest[n]))
      ++n;
    ast::Item item;
    item.kind = ast::ItemKind::keyword;
    item.loc = r.st.loc(r.in.current());
    item.keyword = rest.substr(0, n);
    r.in.bump(n);
    r.ws();
    if (!r.in.empty() && r.in.peek_char() == '=') r.in.bump(1);
    r.ws();
    item.value = parse_expression(r.in, r.st, "a scaling factor after the axis name");
    r.st.block->items.push_back(item);
  }
}

/// PROG-208525707 "Auxiliary functions for coordinate transformation (#WCS TO MCS, #MCS TO
/// WCS)": the kinematic transformation's backward (forward) calculation of a point, for 5-axis
/// and non-Cartesian machines, whose result the program then approaches itself; only with
/// #TRAFO OFF and #CS OFF (else the manual's 21236). ncsim does not build it (docs/interp.md
/// "Offsets, scaling and path limits"): refused at the `#` with the reason.
template <typename Input>
[[noreturn]] void refuse_coordinate_calculation(HashReader<Input>& r, std::string_view from,
                                                bool to) {
  r.ws();
  const std::string dest = r.next_word();
  const std::string command = "#" + std::string(from) + (to ? " TO " + dest : "");
  if (!to || (!iequals(dest, "MCS") && !iequals(dest, "WCS")) || iequals(dest, from))
    r.st.not_supported(r.name_at - 1, command);
  r.st.not_supported(r.name_at - 1,
                     command +
                         " (PROG-208525707: a kinematic transformation's calculation of a "
                         "point between workpiece and machine coordinates, for 5-axis and "
                         "non-Cartesian machines; ncsim does not model its result variables, "
                         "so the program's moves to the result could not run)");
}

template <typename Input>
void read_wcs(HashReader<Input>& r) {  // PROG-208525707: #WCS TO MCS
  r.ws();
  refuse_coordinate_calculation(r, "WCS", r.word("TO"));
}

template <typename Input>
void read_mcs(HashReader<Input>& r) {  // PROG-208517515: #MCS ON [EX TOOL] / #MCS OFF
  r.ws();
  if (r.word("OFF")) return r.set(H::mcs_off);
  if (r.word("TO")) refuse_coordinate_calculation(r, "MCS", true);  // PROG-208525707
  if (!r.word("ON")) r.st.fail(r.in.current(), "ON or OFF after #MCS");
  r.set(H::mcs_on);
  r.ws();
  if (!r.word("EX")) return;
  r.ws();
  if (!r.word("TOOL")) r.st.fail(r.in.current(), "TOOL after #MCS ON EX");
}

// Commands that change neither motion nor time in ncsim's model (docs/language.md "#
// commands"): read to the block end and shown in trace as ACCEPTED.
template <typename Input>
void read_accepted(HashReader<Input>& r) {
  r.set(H::accepted);
  r.in.bump(r.in.size());
}

template <typename Input>
void read_comment(HashReader<Input>& r) {  // §1.5
  r.set(expect_mode(r.in, r.st, {"BEGIN", "END"}, {H::comment_begin, H::comment_end},
                    "BEGIN or END after #COMMENT"));
}

template <typename Input>
void read_pre_if(HashReader<Input>& r) {  // §4.8
  r.set(H::pre_if);
  r.ws();
  r.cmd.expr = parse_expression(r.in, r.st, "a condition after #IF");
}

/// A command's name and its reader; without a reader the name alone is the command (`kind`).
template <typename Input>
struct Entry {
  std::string_view name;
  void (*read)(HashReader<Input>&);
  H kind = H::flush;
};

template <typename Input>
inline constexpr std::array<Entry<Input>, 38> kHashCommands{{
    {"SYNC", read_sync<Input>},
    {"CS", read_cs<Input>},
    {"BCS", read_cs<Input>},
    {"CAXTRACK", read_caxtrack<Input>},
    {"SPLINE", read_spline<Input>},
    {"SET", read_set<Input>},
    {"CONTOUR", read_contour<Input>},
    {"SLOPE", read_slope<Input>},
    {"KIN", read_kin<Input>},
    {"TRAFO", read_trafo<Input>},
    {"MACHINE", read_machine<Input>},
    {"MSG", read_msg<Input>},
    {"FLUSH", read_flush<Input>},
    {"TIME", read_time<Input>},
    {"TRANSVELMIN", read_transvelmin<Input>},
    {"WAIT", read_wait<Input>},
    {"SIGNAL", read_signal<Input>},
    {"DELETE", read_variables<Input>},
    {"INIT", read_variables<Input>},
    {"FILE", read_file_name<Input>},
    {"FILENAME", read_file_name<Input>},
    {"HSC", read_hsc<Input>},
    {"VECTOR", read_vector<Input>},
    {"TANGFEED", read_tangfeed<Input>},
    {"SCALE", read_scale<Input>},
    {"PSET", read_scale<Input>},
    {"MCS", read_mcs<Input>},
    {"WCS", read_wcs<Input>},
    {"CHANNEL", read_accepted<Input>},
    {"IDENT", read_accepted<Input>},
    {"ORI", read_accepted<Input>},
    {"TOOL", read_accepted<Input>},
    {"VAR", nullptr, H::var},
    {"ENDVAR", nullptr, H::endvar},
    {"COMMENT", read_comment<Input>},
    {"IF", read_pre_if<Input>},
    {"ELSE", nullptr, H::pre_else},
    {"ENDIF", nullptr, H::pre_endif},
}};

}  // namespace hash

template <typename Input>
bool parse_hash_command(Input& in, State& st) {
  if (in.empty() || in.peek_char() != '#') return false;
  ast::HashCommand cmd;
  cmd.loc = st.loc(in.current());
  in.bump(1);
  in.bump(lex::blanks(lex::rest(in)));
  const char* name_at = in.current();
  const std::string_view name = lex::ident(lex::rest(in));
  if (name.empty()) st.fail(in.current(), "a # command name");
  in.bump(name.size());
  hash::HashReader<Input> r{in, st, cmd, name, name_at};
  const auto& table = hash::kHashCommands<Input>;
  const auto* entry = std::find_if(table.begin(), table.end(),
                                   [&](const hash::Entry<Input>& e) { return r.is(e.name); });
  if (entry == table.end()) st.not_supported(name_at - 1, "#" + std::string(name));
  if (entry->read != nullptr) {
    entry->read(r);
  } else {
    r.set(entry->kind);
  }
  r.cmd.item_count = static_cast<std::uint32_t>(st.block->items.size());
  st.block->body = r.cmd;
  return true;
}

}  // namespace ncsim::grammar
