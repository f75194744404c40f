// interp/subroutines.cpp: subroutine calls, program levels and cycle calls
// (interp/subroutines.hpp).
#include "interp/subroutines.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "grammar/check.hpp"
#include "grammar/keywords.hpp"
#include "interp/interpreter_impl.hpp"

namespace ncsim::interp {
namespace {

namespace fs = std::filesystem;

/// A subroutine file name that stays in or below the program's folder: relative, no `..`
/// (Options::confine_subroutine_files).
bool is_confined_name(const std::string& name) {
  const std::filesystem::path p(name);
  if (p.has_root_path()) return false;
  return std::none_of(p.begin(), p.end(),
                      [](const std::filesystem::path& part) { return part == ".."; });
}

/// Why `path` cannot be a subroutine file (" not found", " is a directory", ...), or nothing.
std::optional<std::string> subroutine_file_problem(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return std::string(" not found");
  switch (st.type()) {
    case fs::file_type::regular:
      return std::nullopt;
    case fs::file_type::directory:
      return std::string(" is a directory, not a program file");
    case fs::file_type::character:
    case fs::file_type::block:
      return std::string(" is a device, not a program file");
    case fs::file_type::fifo:
      return std::string(" is a pipe, not a program file");
    case fs::file_type::socket:
      return std::string(" is a socket, not a program file");
    default:
      return std::string(" is not a regular file");
  }
}

/// M6 / D as the program writes it.
const char* word_name(WordCall w) {
  return w == WordCall::m6 ? "M6" : "D";
}

/// The channel parameter that configures G `code`'s subroutine, as a user writes it.
std::string configuring_parameter(std::uint32_t code) {
  if (code >= 80 && code <= 89) {
    return "g" + std::to_string(code) + "_prog_file (P-CHAN-00" + std::to_string(160 + code - 80) +
           ")";
  }
  return "g800_prog_file[" + std::to_string(code - 800) + "] (P-CHAN-00187)";
}

/// The channel parameter that configures M6's or D's subroutine.
const char* word_parameter(WordCall w) {
  return w == WordCall::m6 ? "m6_prog_file (P-CHAN-00118)" : "d_prog_file (P-CHAN-00429)";
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

bool Subroutines::find_main_start(ProgramFile& pf, std::uint16_t index) {
  // Local subroutines precede the main part (PROG-206828043); record them, skip their bodies.
  std::uint32_t k = 0;
  for (;;) {
    const ast::Block* b = pf.blocks->fetch(k, ip_.diags);
    if (b == nullptr) break;
    const auto* h = std::get_if<ast::ProgramHeader>(&b->body);
    if (h == nullptr) break;
    if (!h->local) {
      pf.main_start = k + 1;
      return true;
    }
    const std::string name = grammar::to_upper(h->name);
    pf.local_subs[name] = k;
    for (++k;; ++k) {
      const ast::Block* body = pf.blocks->fetch(k, ip_.diags);
      if (body == nullptr || is_header(body)) break;
    }
  }
  pf.main_start = k;
  (void)index;
  return true;
}

bool Subroutines::call(const ast::Block& b, const ast::Call& c) {
  std::string name;
  if (c.target == ast::CallTarget::macro) {
    const std::string* text = ip_.vars.macro(c.name);
    if (text == nullptr)
      return ip_.fail(c.loc, "NC4005", "macro \"" + std::string(c.name) + "\" is not defined");
    name = *text;
  } else if (c.target == ast::CallTarget::variable) {
    VarRef ref;
    if (!ip_.evaluator.resolve(b, c.variable, ref)) return ip_.fail_eval();
    const std::string* text = ip_.vars.read_string(ref);
    if (text == nullptr) return ip_.fail(c.loc, "NC4303", "the call needs a STRING variable");
    name = *text;
  } else {
    name = std::string(c.name);
  }
  if (c.kind == ast::CallKind::cycle) return read_cycle_call(b, c) && run_cycle_call();
  if (static_cast<int>(ip_.calls.size()) >= ip_.options.max_subroutine_depth) {
    return ip_.fail(c.loc, "NC4302",
                    "subroutine nesting deeper than " +
                        std::to_string(ip_.options.max_subroutine_depth) + " levels (call of " +
                        name + ")");
  }
  Pc target;
  std::uint32_t header = 0;
  if (c.kind == ast::CallKind::local) {
    auto& subs = ip_.files[ip_.pc.file]->local_subs;
    auto it = subs.find(grammar::to_upper(name));
    if (it == subs.end()) {
      return ip_.fail(c.loc, "NC4301",
                      "local subroutine " + name + " is not defined before the main program");
    }
    target = {ip_.pc.file, it->second + 1};
    header = it->second;
  } else {
    auto it = ip_.file_by_name.find(name);
    std::uint16_t index = 0;
    if (it == ip_.file_by_name.end()) {
      const std::filesystem::path dir =
          std::filesystem::path(ip_.files[0]->file->name()).parent_path();
      if (ip_.options.confine_subroutine_files && !is_confined_name(name)) {
        return ip_.fail(c.loc, "NC4301",
                        "global subroutine file " + name +
                            " is outside the program's folder (absolute path or '..')");
      }
      const std::filesystem::path path = dir / name;
      if (auto problem = subroutine_file_problem(path)) {
        return ip_.fail(c.loc, "NC4301", "global subroutine file " + path.string() + *problem);
      }
      auto loaded = load_global_file(name, path, c.loc);
      if (!loaded) return false;
      index = *loaded;
    } else {
      index = it->second;
    }
    target = {index, ip_.files[index]->main_start};
    header = ip_.files[index]->main_start == 0 ? 0 : ip_.files[index]->main_start - 1;
  }
  enter_level(target, header);
  return true;
}

std::optional<std::uint16_t> Subroutines::load_global_file(const std::string& key,
                                                           const std::filesystem::path& path,
                                                           core::SourceLoc at) {
  auto pf = std::make_unique<ProgramFile>();
  try {
    pf->own = std::make_unique<core::SourceFile>(core::SourceFile::load(path));
  } catch (const std::exception& e) {
    ip_.fail(at, "NC4301", e.what());
    return std::nullopt;
  }
  // A subroutine file is checked whole when it is first called, as the main program is
  // before it runs: its syntax errors are reported even in blocks never reached.
  const core::DiagnosticList syntax = grammar::check_program(*pf->own);
  if (syntax.has_errors()) {
    for (const core::Diagnostic& d : syntax.items())
      ip_.diags.add(d);
    ip_.fail(at, "NC4306",
             "global subroutine file " + path.string() + " has " +
                 std::to_string(syntax.error_count()) + " syntax error" +
                 (syntax.error_count() == 1 ? "" : "s"));
    return std::nullopt;
  }
  pf->file = pf->own.get();
  pf->blocks = std::make_unique<BlockSource>(*pf->file);
  const auto index = static_cast<std::uint16_t>(ip_.files.size());
  ip_.files.push_back(std::move(pf));
  ip_.file_by_name[key] = index;
  find_main_start(*ip_.files[index], index);
  return index;
}

void Subroutines::enter_level(Pc target, std::uint32_t header) {
  ip_.calls.push_back({ip_.pc, ip_.flow.frames().size(), ip_.unit_start});
  ip_.vars.push_level();
  ip_.pc = target;
  ip_.unit_start = header;
}

bool Subroutines::subroutine_return() {
  if (ip_.calls.empty()) return true;  // M17 in the main program: ignored
  const CallFrame f = ip_.calls.back();
  ip_.calls.pop_back();
  ip_.flow.leave_to(f.control_depth);
  ip_.vars.pop_level();
  ip_.pc = f.ret;
  ip_.unit_start = f.unit_start;
  return true;
}

std::string Subroutines::call_name(const CycleCall& c) {
  if (c.word) return word_name(*c.word);
  return c.g_code != 0 ? "G" + std::to_string(c.g_code) : "L CYCLE";
}

bool Subroutines::read_word_call(WordCall word, core::SourceLoc at, bool& called) {
  // P-CHAN-00118 / P-CHAN-00429: #FILE NAME's name until the program end, else the channel's;
  // neither: M6 is an M function and D a plain D word.
  const std::optional<std::string>& over = word_files[static_cast<std::size_t>(word)];
  const std::string& name = over                   ? *over
                            : word == WordCall::m6 ? ip_.machine.channel.m6_prog_file
                                                   : ip_.machine.channel.d_prog_file;
  called = !name.empty();
  if (!called) return true;
  if (cycle_call) {
    return ip_.fail(at, "NC4308",
                    std::string(word_name(word)) + " after " + call_name(*cycle_call) +
                        ": one implicit subroutine call per block");
  }
  CycleCall c;
  c.word = word;
  c.name = name;
  c.loc = at;
  cycle_call = std::move(c);
  return true;
}

bool Subroutines::read_implicit_call(const ast::Block& b, const ast::Word& w) {
  if (cycle_call) {
    return ip_.fail(w.loc, "NC4308",
                    "G" + std::to_string(w.code) + " after " + call_name(*cycle_call) +
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
    auto v = ip_.eval(b, it.value);
    if (!v) return false;
    c.params.emplace_back(*v);
  }
  // A list that ends in a gap (`[1,2,]`) has no last parameter.
  while (!c.params.empty() && !c.params.back())
    c.params.pop_back();
  cycle_call = std::move(c);
  return true;
}

bool Subroutines::read_cycle_call(const ast::Block& b, const ast::Call& c) {
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
      return ip_.fail(it.loc, "NC4304",
                      "not supported: " + std::string(it.keyword) +
                          " in L CYCLE (ncsim runs a cycle once, at its call)");
    }
    if (it.value == ast::kNoNode && it.text.data() != nullptr) {  // @P1="text" (PROG-206859019)
      return ip_.fail(it.loc, "NC4304",
                      "not supported: a text as cycle parameter " + std::string(it.keyword) +
                          " (ncsim's @P parameters are numbers)");
    }
    if (it.value == ast::kNoNode) {
      return ip_.fail(it.loc, "NC4304", std::string(it.keyword) + " needs a value (@P1=<expr>)");
    }
    if (n > 200) {
      return ip_.fail(
          it.loc, "20394",
          "cycle parameter " + std::string(it.keyword) + " beyond @P200 (PROG-206859019)");
    }
    auto v = ip_.eval(b, it.value);
    if (!v) return false;
    if (cc.params.size() < n) cc.params.resize(n);
    cc.params[n - 1] = *v;
  }
  if (cc.name.empty()) return ip_.fail(c.loc, "NC4304", "L CYCLE needs NAME=<cycle file>");
  cycle_call = std::move(cc);
  return true;
}

bool Subroutines::run_cycle_call() {
  CycleCall c = std::move(*cycle_call);
  cycle_call.reset();
  const std::string what = call_name(c);
  // The skipped-call warning NC4307, once per G code or cycle name (--missing-cycles skip).
  const auto skip = [&](const std::string& why) {
    if (skipped_cycles.insert(c.g_code != 0 || c.word ? what : what + " " + c.name).second) {
      ip_.warn(c.loc, "NC4307", what + " skipped (--missing-cycles skip): " + why);
    }
    ip_.blocks_without_motion = 0;
    return true;
  };
  if (c.g_code != 0) {
    // #FILE NAME [G8x="..."] until the program end, else the channel parameter (P-CHAN-00160).
    if (auto o = file_names.find(c.g_code); o != file_names.end()) {
      c.name = o->second;
    } else if (auto f = ip_.machine.channel.implicit_call_files.find(c.g_code);
               f != ip_.machine.channel.implicit_call_files.end()) {
      c.name = f->second;
    }
    if (c.name.empty()) {
      const std::string why = "no subroutine is configured for it (channel parameter " +
                              configuring_parameter(c.g_code) + ", or #FILE NAME [" + what +
                              "=\"<file>\"] in the program)";
      if (ip_.options.skip_missing_cycles) return skip(why);
      return ip_.fail(c.loc, "20131", "unknown G function " + what + ": " + why);
    }
  }
  if (static_cast<int>(ip_.calls.size()) >= ip_.options.max_subroutine_depth) {
    return ip_.fail(c.loc, "NC4302",
                    "subroutine nesting deeper than " +
                        std::to_string(ip_.options.max_subroutine_depth) + " levels (call of " +
                        c.name + ")");
  }
  // A local subroutine of that name (LL CYCLE) comes first.
  if (c.g_code == 0 && !c.word) {
    auto& subs = ip_.files[ip_.pc.file]->local_subs;
    if (auto it = subs.find(grammar::to_upper(c.name)); it != subs.end()) {
      enter_level({ip_.pc.file, it->second + 1}, it->second);
      ip_.vars.set_cycle_params(std::move(c.params));
      return true;
    }
  }
  // Where the file is looked for, in order: --cycles folders, the machine's cycles/ folder,
  // the main program's folder (docs/interp.md "Cycles").
  std::vector<fs::path> dirs = ip_.options.cycle_dirs;
  dirs.push_back(ip_.machine.folder / "cycles");
  dirs.push_back(fs::path(ip_.files[0]->file->name()).parent_path());
  if (ip_.options.confine_subroutine_files &&
      (fs::path(c.name).is_absolute() || c.name.find("..") != std::string::npos)) {
    return ip_.fail(
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
         : c.word ? std::string(" (configured by ") + word_parameter(*c.word) + " or #FILE NAME)"
                  : "") +
        "; give the folder with --cycles DIR";
    if (ip_.options.skip_missing_cycles) return skip(why);
    return ip_.fail(c.loc, "NC4301", what + " cannot be run: " + why);
  }
  const std::string key = "cycle:" + found->string();
  std::uint16_t index = 0;
  if (auto it = ip_.file_by_name.find(key); it != ip_.file_by_name.end()) {
    index = it->second;
  } else {
    auto loaded = load_global_file(key, *found, c.loc);
    if (!loaded) return false;
    index = *loaded;
  }
  const std::uint32_t start = ip_.files[index]->main_start;
  enter_level({index, start}, start == 0 ? 0 : start - 1);
  // M6 and D call "analogous to L ..." (P-CHAN-00118): a subroutine, not a cycle.
  if (!c.word) ip_.vars.set_cycle_params(std::move(c.params));
  return true;
}

bool Subroutines::hash_file_name(const ast::Block& b, const ast::HashCommand& h) {
  // #FILE NAME [G80="x.nc" G805="y.nc" M6="t.nc" D="d.nc" MSG="m.txt"] (PROG-207504523): the
  // subroutine of an implicit call until the program end (P-CHAN-00160, 00118, 00429
  // remarks); an empty name removes the override. MSG names #MSG SAVE's file, which ncsim
  // does not write (accepted, shown in trace).
  for (std::uint32_t k = 0; k < h.item_count && k < b.items.size(); ++k) {
    const ast::Item& it = b.items[k];
    const std::string_view kw = it.keyword;
    std::uint32_t code = 0;
    bool digits = kw.size() >= 2 && grammar::ascii_upper(kw[0]) == 'G';
    for (std::size_t j = 1; digits && j < kw.size(); ++j) {
      if (kw[j] < '0' || kw[j] > '9') digits = false;
      if (digits) code = code * 10 + static_cast<std::uint32_t>(kw[j] - '0');
    }
    const bool g = digits && kw.size() <= 4 && grammar::is_implicit_call_g(code);
    const bool m6 = grammar::iequals(kw, "M6");
    const bool d = grammar::iequals(kw, "D");
    if (!g && !m6 && !d && !grammar::iequals(kw, "MSG")) {
      return ip_.fail(
          it.loc, "NC4309",
          "#FILE NAME names the subroutine of G80-G89, G800-G839, M6 or D, or MSG's file, not '" +
              std::string(kw) + "'");
    }
    if (it.kind != ast::ItemKind::keyword || (it.text.empty() && it.value != ast::kNoNode)) {
      return ip_.fail(
          it.loc, "NC4309",
          std::string(kw) + " needs a quoted file name (" + std::string(kw) + "=\"x.nc\")");
    }
    const std::string name(it.text);  // empty: the channel's subroutine again
    if (g && name.empty()) file_names.erase(code);
    if (g && !name.empty()) file_names[code] = name;
    if (m6 || d) {
      std::optional<std::string>& over =
          word_files[static_cast<std::size_t>(m6 ? WordCall::m6 : WordCall::d)];
      if (name.empty()) {
        over.reset();
      } else {
        over = name;
      }
    }
  }
  return true;
}

}  // namespace ncsim::interp
