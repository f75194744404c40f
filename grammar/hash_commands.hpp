#pragma once
// grammar/hash_commands: the grammar of each `#` command (internal). isg-language.md §5; each
// command reads its mode words, then its bracket lists with the command's own keyword table.

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

template <typename Input>
bool parse_hash_command(Input& in, State& st) {
  if (in.empty() || in.peek_char() != '#') return false;
  using H = ast::HashKind;
  using T = ast::TableId;
  ast::HashCommand cmd;
  cmd.loc = st.loc(in.current());
  in.bump(1);
  in.bump(lex::blanks(lex::rest(in)));
  const char* name_at = in.current();
  const std::string_view name = lex::ident(lex::rest(in));
  if (name.empty()) st.fail(in.current(), "a # command name");
  in.bump(name.size());
  const auto set = [&](H kind, T table = T::none) {
    cmd.kind = kind;
    cmd.table = table;
    st.table = table;
    st.block->body = cmd;
  };
  const auto lists = [&](int max_lists, bool required) {
    for (int g = 0; g < max_lists; ++g) {
      skip_ws(in, st);
      if (!parse_list(in, st, static_cast<std::uint8_t>(g))) {
        if (required && g == 0) st.fail(in.current(), "'['");
        return;
      }
    }
  };
  const auto is = [&](std::string_view w) { return iequals(name, w); };

  if (is("SYNC")) {  // §5.13, seed 004 "#SYNC IN / #SYNC OUT"
    const H k = expect_mode(in, st, {"IN", "OUT", "OFF"}, {H::sync_in, H::sync_out, H::sync_off},
                            "IN, OUT or OFF after #SYNC");
    set(k, k == H::sync_in ? T::sync_in : T::sync_out);
    lists(1, false);
  } else if (is("CS") || is("BCS")) {  // §5.8
    const bool b = is("BCS");
    skip_ws(in, st);
    if (accept(in, "DEF")) {
      set(b ? H::bcs_def : H::cs_def, T::cs);
      lists(2, false);
    } else if (accept(in, "ON")) {
      set(b ? H::bcs_on : H::cs_on, T::cs);
      lists(2, false);
    } else if (accept(in, "OFF")) {
      skip_ws(in, st);
      const bool all = accept(in, "ALL");
      set(all ? (b ? H::bcs_off_all : H::cs_off_all) : (b ? H::bcs_off : H::cs_off));
    } else {
      const std::string_view w = lex::ident(lex::rest(in));
      if (!w.empty())
        st.not_supported(in.current(), "#" + std::string(name) + " " + std::string(w));
      st.fail(in.current(), "DEF, ON or OFF");
    }
  } else if (is("CAXTRACK")) {  // §5.7
    const H k = expect_mode(in, st, {"ON", "OFF"}, {H::caxtrack_on, H::caxtrack_off},
                            "ON or OFF after #CAXTRACK");
    set(k, k == H::caxtrack_on ? T::caxtrack_on : T::caxtrack_off);
    lists(1, false);
  } else if (is("SPLINE")) {  // §5.4
    skip_ws(in, st);
    if (accept(in, "TYPE")) {
      set(expect_mode(in, st, {"AKIMA", "BSPLINE"}, {H::spline_type_akima, H::spline_type_bspline},
                      "AKIMA or BSPLINE after #SPLINE TYPE"));
    } else {
      set(expect_mode(in, st, {"ON", "OFF"}, {H::spline_on, H::spline_off},
                      "TYPE, ON or OFF after #SPLINE"));
    }
  } else if (is("SET")) {  // old spellings, §5.4
    skip_ws(in, st);
    if (accept(in, "SPLINETYPE")) {
      set(expect_mode(in, st, {"AKIMA", "BSPLINE"}, {H::spline_type_akima, H::spline_type_bspline},
                      "AKIMA or BSPLINE after #SET SPLINETYPE"));
    } else if (accept(in, "SPLINE")) {
      set(expect_mode(in, st, {"ON", "OFF"}, {H::spline_on, H::spline_off},
                      "ON or OFF after #SET SPLINE"));
    } else {
      st.not_supported(name_at - 1, "#SET " + std::string(lex::ident(lex::rest(in))));
    }
  } else if (is("CONTOUR")) {  // §5.3
    skip_ws(in, st);
    if (!accept(in, "MODE")) st.fail(in.current(), "MODE after #CONTOUR");
    skip_ws(in, st);
    if (accept(in, "OFF")) {
      set(H::contour_mode_off);
    } else {
      set(accept(in, "ON") ? H::contour_mode_on : H::contour_mode, T::contour_mode);
      lists(1, false);
    }
  } else if (is("SLOPE")) {  // §5.5
    skip_ws(in, st);
    if (accept(in, "DEFAULT")) {
      set(H::slope_default);
    } else {
      set(H::slope, T::slope);
      if (!parse_list(in, st, 0)) st.fail(in.current(), "'[' or DEFAULT after #SLOPE");
    }
  } else if (is("KIN")) {  // §5.9
    skip_ws(in, st);
    if (!accept(in, "ID")) st.fail(in.current(), "ID after #KIN");
    set(H::kin_id, T::kin_id);
    lists(1, true);
  } else if (is("TRAFO")) {  // §5.9
    skip_ws(in, st);
    if (accept(in, "ON")) {
      set(H::trafo_on);
    } else if (accept(in, "OFF")) {
      set(H::trafo_off);
    } else {
      set(H::trafo_steps, T::trafo);
      if (!parse_list(in, st, 0)) st.fail(in.current(), "ON, OFF or '[' after #TRAFO");
    }
  } else if (is("MACHINE")) {  // §5.10
    skip_ws(in, st);
    if (!accept(in, "DATA")) st.fail(in.current(), "DATA after #MACHINE");
    set(H::machine_data, T::machine_data);
    skip_ws(in, st);
    const char* mode_at = in.current();
    if (accept(in, "SYN")) {  // mode word without brackets, as in DIAG-21413's example
      ast::Item item;
      item.loc = st.loc(mode_at);
      item.key = 0;
      item.keyword = std::string_view(mode_at, 3);
      st.block->items.push_back(item);
    }
    lists(2, true);
  } else if (is("MSG")) {  // §5.11
    set(H::msg, T::msg);
    const KeywordTable& table = keyword_table(T::msg);
    for (;;) {
      skip_ws(in, st);
      const std::string_view w = lex::ident(lex::rest(in));
      if (w.empty()) break;
      ast::Item item;
      item.loc = st.loc(in.current());
      item.keyword = w;
      for (std::size_t k = 0; k < table.entries.size(); ++k) {
        if (iequals(table.entries[k].name, w)) item.key = static_cast<std::uint16_t>(k);
      }
      st.block->items.push_back(item);
      in.bump(w.size());
    }
    skip_ws(in, st);
    (void)parse_list(in, st, 1);
  } else if (is("FLUSH")) {  // §5.1
    skip_ws(in, st);
    set(accept(in, "CONTINUE") ? H::flush_continue : accept(in, "WAIT") ? H::flush_wait : H::flush);
  } else if (is("TIME")) {  // §5.2
    set(H::time, T::time);
    skip_ws(in, st);
    ast::Item item;
    item.kind = ast::ItemKind::positional;
    item.loc = st.loc(in.current());
    item.value = parse_expression(in, st, "a time in seconds after #TIME");
    st.block->items.push_back(item);
  } else if (is("TRANSVELMIN")) {  // §5.6
    const H k = expect_mode(in, st, {"ON", "OFF"}, {H::transvelmin_on, H::transvelmin_off},
                            "ON or OFF after #TRANSVELMIN");
    set(k, T::transvelmin);
    if (k == H::transvelmin_on) lists(1, false);
  } else if (is("WAIT")) {  // §6.1
    skip_ws(in, st);
    if (!accept(in, "INDP")) {
      st.not_supported(name_at - 1, "#WAIT " + std::string(lex::ident(lex::rest(in))));
    }
    skip_ws(in, st);
    if (accept(in, "ALL")) {
      set(H::wait_indp_all);
    } else {
      set(H::wait_indp, T::wait_indp);
      lists(1, true);
    }
  } else if (is("DELETE") || is("INIT")) {  // §3.6, §3.5
    set(is("DELETE") ? H::delete_ : H::init, is("DELETE") ? T::delete_ : T::init);
    parse_variable_list(in, st);
  } else if (is("FILE") || is("FILENAME")) {  // P-CHAN-00160 remarks: #FILE NAME [G80="x"]
    if (is("FILE")) {
      skip_ws(in, st);
      if (!accept(in, "NAME")) st.fail(in.current(), "NAME after #FILE");
    }
    set(H::file_name, T::file_name);
    lists(1, true);
  } else if (is("HSC")) {  // TF5200 "HSC": #HSC ON [...] / #HSC OFF / #HSC [...]
    skip_ws(in, st);
    if (accept(in, "OFF")) {
      set(H::hsc_off);
    } else {
      (void)accept(in, "ON");
      set(H::hsc_on, T::hsc);
      lists(1, false);
    }
  } else if (is("VECTOR")) {  // PROG-207477899
    skip_ws(in, st);
    if (!accept(in, "LIMIT"))
      st.not_supported(name_at - 1, "#VECTOR " + std::string(lex::ident(lex::rest(in))));
    const H k = expect_mode(in, st, {"ON", "OFF"}, {H::vector_limit_on, H::vector_limit_off},
                            "ON or OFF after #VECTOR LIMIT");
    set(k, T::vector_limit);
    skip_ws(in, st);
    if (accept(in, "ALL")) {
      ast::Item item;
      item.loc = st.loc(in.current() - 3);
      item.keyword = "ALL";
      st.block->items.push_back(item);
    } else {
      lists(1, false);
    }
  } else if (is("SCALE") || is("PSET")) {  // PROG-207656459 #SCALE [ON] X2 Y2 / OFF;
    skip_ws(in, st);                       // PROG-207101835 #PSET X200 Y0
    if (is("SCALE") && accept(in, "OFF")) {
      set(H::scale_off);
    } else {
      if (is("SCALE")) (void)accept(in, "ON");
      set(is("SCALE") ? H::scale_on : H::pset, T::scale);
      for (;;) {  // axis name (letters, then digits) and its factor
        skip_ws(in, st);
        const std::string_view r = lex::rest(in);
        if (r.empty() || !lex::is_alpha(r[0])) break;
        std::size_t n = 0;
        while (n < r.size() && lex::is_alpha(r[n]))
          ++n;
        ast::Item item;
        item.kind = ast::ItemKind::keyword;
        item.loc = st.loc(in.current());
        item.keyword = r.substr(0, n);
        in.bump(n);
        skip_ws(in, st);
        if (!in.empty() && in.peek_char() == '=') in.bump(1);
        skip_ws(in, st);
        item.value = parse_expression(in, st, "a scaling factor after the axis name");
        st.block->items.push_back(item);
      }
    }
  } else if (is("MCS")) {  // PROG-208517515: #MCS ON [EX TOOL] / #MCS OFF
    skip_ws(in, st);
    if (accept(in, "OFF")) {
      set(H::mcs_off);
    } else {
      if (!accept(in, "ON")) st.fail(in.current(), "ON or OFF after #MCS");
      set(H::mcs_on);
      skip_ws(in, st);
      if (accept(in, "EX")) {
        skip_ws(in, st);
        if (!accept(in, "TOOL")) st.fail(in.current(), "TOOL after #MCS ON EX");
      }
    }
  } else if (is("CHANNEL") || is("IDENT") || is("ORI") || is("TOOL")) {
    // Commands that change neither motion nor time in ncsim's model (docs/language.md "#
    // commands"): read to the block end and shown in trace as ACCEPTED.
    set(H::accepted);
    in.bump(in.size());
  } else if (is("VAR")) {
    set(H::var);
  } else if (is("ENDVAR")) {
    set(H::endvar);
  } else if (is("COMMENT")) {  // §1.5
    set(expect_mode(in, st, {"BEGIN", "END"}, {H::comment_begin, H::comment_end},
                    "BEGIN or END after #COMMENT"));
  } else if (is("IF")) {  // §4.8
    set(H::pre_if);
    skip_ws(in, st);
    cmd.expr = parse_expression(in, st, "a condition after #IF");
  } else if (is("ELSE")) {
    set(H::pre_else);
  } else if (is("ENDIF")) {
    set(H::pre_endif);
  } else {
    st.not_supported(name_at - 1, "#" + std::string(name));
  }
  cmd.item_count = static_cast<std::uint32_t>(st.block->items.size());
  st.block->body = cmd;
  return true;
}

}  // namespace ncsim::grammar
