// interp/interpreter_cycles.cpp: cycle calls. The implicit subroutine calls G80-G89 and
// G800-G839 with their parameter lists (TF5200 PROG-206278923, the channel parameters
// P-CHAN-00160..00169 and P-CHAN-00187, `#FILE NAME`), `L CYCLE [NAME=.. @P1=..]`
// (PROG-206859019), and where a cycle's file is found (docs/interp.md "Cycles").
#include <cmath>

#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

namespace fs = std::filesystem;

/// The channel parameter that configures G `code`'s subroutine, as a user writes it.
std::string configuring_parameter(std::uint32_t code) {
  if (code >= 80 && code <= 89) {
    return "g" + std::to_string(code) + "_prog_file (P-CHAN-00" + std::to_string(160 + code - 80) +
           ")";
  }
  return "g800_prog_file[" + std::to_string(code - 800) + "] (P-CHAN-00187)";
}

/// `@P12` -> 12; 0 when `keyword` is not a cycle parameter name.
std::uint32_t at_p_number(std::string_view keyword) {
  if (keyword.size() < 3 || keyword[0] != '@' || grammar::ascii_upper(keyword[1]) != 'P') return 0;
  std::uint32_t n = 0;
  for (std::size_t k = 2; k < keyword.size(); ++k) {
    if (keyword[k] < '0' || keyword[k] > '9' || n > 100000) return 0;
    n = n * 10 + static_cast<std::uint32_t>(keyword[k] - '0');
  }
  return n;
}

}  // namespace

bool Interpreter::Impl::read_implicit_call(const ast::Block& b, const ast::Word& w) {
  if (cycle_call) {
    return fail(w.loc, "NC4308",
                "G" + std::to_string(w.code) + " after G" + std::to_string(cycle_call->g_code) +
                    ": one implicit subroutine call per block");
  }
  CycleCall c;
  c.g_code = w.code;
  c.loc = w.loc;
  // The transfer parameters are REAL expressions in a fixed order; a gap `,,` leaves one out
  // (PROG-206278923). Evaluated now, with the block's values, as a call's arguments are.
  for (std::uint32_t k = w.first_item; k < w.first_item + w.item_count && k < b.items.size(); ++k) {
    const ast::Item& it = b.items[k];
    if (it.kind == ast::ItemKind::empty) {
      c.params.emplace_back();
      continue;
    }
    auto v = eval(b, it.value);
    if (!v) return false;
    c.params.emplace_back(*v);
  }
  // A list that ends in a gap (`[1,2,]`) has no last parameter.
  while (!c.params.empty() && !c.params.back())
    c.params.pop_back();
  cycle_call = std::move(c);
  return true;
}

bool Interpreter::Impl::read_cycle_call(const ast::Block& b, const ast::Call& c) {
  CycleCall cc;
  cc.loc = c.loc;
  for (std::uint32_t k = c.first_item; k < c.first_item + c.item_count && k < b.items.size(); ++k) {
    const ast::Item& it = b.items[k];
    if (grammar::iequals(it.keyword, "NAME")) {
      cc.name = std::string(it.text);
      continue;
    }
    const std::uint32_t n = at_p_number(it.keyword);
    if (n == 0) {
      // MODAL_MOVE / MODAL_BLOCK repeat the cycle after later blocks (PROG-206859019).
      return fail(it.loc, "NC4304",
                  "not supported: " + std::string(it.keyword) +
                      " in L CYCLE (ncsim runs a cycle once, at its call)");
    }
    if (it.value == ast::kNoNode) {
      return fail(it.loc, "NC4304", std::string(it.keyword) + " needs a value (@P1=<expr>)");
    }
    if (n > 200) {
      return fail(it.loc, "20394",
                  "cycle parameter " + std::string(it.keyword) + " beyond @P200 (PROG-206859019)");
    }
    auto v = eval(b, it.value);
    if (!v) return false;
    if (cc.params.size() < n) cc.params.resize(n);
    cc.params[n - 1] = *v;
  }
  if (cc.name.empty()) return fail(c.loc, "NC4304", "L CYCLE needs NAME=<cycle file>");
  cycle_call = std::move(cc);
  return true;
}

bool Interpreter::Impl::run_cycle_call() {
  CycleCall c = std::move(*cycle_call);
  cycle_call.reset();
  const std::string what = c.g_code != 0 ? "G" + std::to_string(c.g_code) : "L CYCLE";
  // The skipped-call warning NC4307, once per G code or cycle name (--missing-cycles skip).
  const auto skip = [&](const std::string& why) {
    if (skipped_cycles.insert(c.g_code != 0 ? what : what + " " + c.name).second) {
      warn(c.loc, "NC4307", what + " skipped (--missing-cycles skip): " + why);
    }
    blocks_without_motion = 0;
    return true;
  };
  if (c.g_code != 0) {
    // #FILE NAME [G8x="..."] until the program end, else the channel parameter (P-CHAN-00160).
    if (auto o = file_names.find(c.g_code); o != file_names.end()) {
      c.name = o->second;
    } else if (auto f = machine.channel.implicit_call_files.find(c.g_code);
               f != machine.channel.implicit_call_files.end()) {
      c.name = f->second;
    }
    if (c.name.empty()) {
      const std::string why = "no subroutine is configured for it (channel parameter " +
                              configuring_parameter(c.g_code) + ", or #FILE NAME [" + what +
                              "=\"<file>\"] in the program)";
      if (options.skip_missing_cycles) return skip(why);
      return fail(c.loc, "20131", "unknown G function " + what + ": " + why);
    }
  }
  if (static_cast<int>(calls.size()) >= options.max_subroutine_depth) {
    return fail(c.loc, "NC4302",
                "subroutine nesting deeper than " + std::to_string(options.max_subroutine_depth) +
                    " levels (call of " + c.name + ")");
  }
  // A local subroutine of that name (LL CYCLE) comes first.
  if (c.g_code == 0) {
    auto& subs = files[pc.file]->local_subs;
    if (auto it = subs.find(grammar::to_upper(c.name)); it != subs.end()) {
      enter_level({pc.file, it->second + 1}, it->second);
      vars.set_cycle_params(std::move(c.params));
      return true;
    }
  }
  // Where the file is looked for, in order: --cycles folders, the machine's cycles/ folder,
  // the main program's folder (docs/interp.md "Cycles").
  std::vector<fs::path> dirs = options.cycle_dirs;
  dirs.push_back(machine.folder / "cycles");
  dirs.push_back(fs::path(files[0]->file->name()).parent_path());
  if (options.confine_subroutine_files &&
      (fs::path(c.name).is_absolute() || c.name.find("..") != std::string::npos)) {
    return fail(
        c.loc, "NC4301",
        "cycle file " + c.name + " is outside the program's folder (absolute path or '..')");
  }
  std::optional<fs::path> found;
  std::string looked;
  for (const fs::path& d : dirs) {
    const fs::path p = d.empty() ? fs::path(c.name) : d / c.name;
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) {
      found = p;
      break;
    }
    if (!looked.empty()) looked += ", ";
    looked += d.empty() ? std::string(".") : d.string();
  }
  if (!found) {
    const std::string why =
        "its file " + c.name + " is not in " + looked +
        (c.g_code != 0 ? " (configured by " + configuring_parameter(c.g_code) + " or #FILE NAME)"
                       : "") +
        "; give the folder with --cycles DIR";
    if (options.skip_missing_cycles) return skip(why);
    return fail(c.loc, "NC4301", what + " cannot be run: " + why);
  }
  const std::string key = "cycle:" + found->string();
  std::uint16_t index = 0;
  if (auto it = file_by_name.find(key); it != file_by_name.end()) {
    index = it->second;
  } else {
    auto loaded = load_global_file(key, *found, c.loc);
    if (!loaded) return false;
    index = *loaded;
  }
  const std::uint32_t start = files[index]->main_start;
  enter_level({index, start}, start == 0 ? 0 : start - 1);
  vars.set_cycle_params(std::move(c.params));
  return true;
}

bool Interpreter::Impl::hash_file_name(const ast::Block& b, const ast::HashCommand& h) {
  // #FILE NAME [G80="x.nc" G805="y.nc"]: the subroutine of an implicit call until the program
  // end (P-CHAN-00160 remarks); an empty name removes the override.
  for (std::uint32_t k = 0; k < h.item_count && k < b.items.size(); ++k) {
    const ast::Item& it = b.items[k];
    const std::string_view kw = it.keyword;
    std::uint32_t code = 0;
    bool digits = kw.size() >= 2 && grammar::ascii_upper(kw[0]) == 'G';
    for (std::size_t j = 1; digits && j < kw.size(); ++j) {
      if (kw[j] < '0' || kw[j] > '9') digits = false;
      if (digits) code = code * 10 + static_cast<std::uint32_t>(kw[j] - '0');
    }
    if (!digits || kw.size() > 4 || !grammar::is_implicit_call_g(code)) {
      return fail(
          it.loc, "NC4309",
          "#FILE NAME names the subroutine of G80-G89 or G800-G839, not '" + std::string(kw) + "'");
    }
    if (it.kind != ast::ItemKind::keyword || (it.text.empty() && it.value != ast::kNoNode)) {
      return fail(it.loc, "NC4309", std::string(kw) + " needs a quoted file name (G80=\"x.nc\")");
    }
    if (it.text.empty()) {
      file_names.erase(code);
    } else {
      file_names[code] = std::string(it.text);
    }
  }
  return true;
}

}  // namespace ncsim::interp
