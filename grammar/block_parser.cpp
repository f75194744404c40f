#include "grammar/block_parser.hpp"

#include <cstring>
#include <type_traits>

#include "grammar/custom_rules.hpp"
#include "grammar/plain_expression.hpp"

namespace ncsim::grammar {
namespace {

namespace pegtl = tao::pegtl;
using Input = pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf>;

enum class Mode { normal, declarations, comment };

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

/// The first non-blank text of a line, or empty.
std::string_view trimmed(std::string_view line) {
  std::size_t k = 0;
  while (k < line.size() && blank(line[k]))
    ++k;
  return line.substr(k);
}

/// True when `line` (trimmed) is the command `#<a> <b>` (any case, blanks between).
bool is_command(std::string_view line, std::string_view a, std::string_view b) {
  if (line.empty() || line[0] != '#') return false;
  line = trimmed(line.substr(1));
  const std::string_view first = lex::ident(line);
  if (!iequals(first, a)) return false;
  if (b.empty()) return true;
  return iequals(lex::ident(trimmed(line.substr(first.size()))), b);
}

/// True when `text` holds only blanks and comments (`( ... )`, nested, and `;` to the end).
bool comment_only(std::string_view text) {
  std::size_t k = 0;
  for (;;) {
    while (k < text.size() && blank(text[k]))
      ++k;
    if (k == text.size() || text[k] == ';') return true;
    if (text[k] != '(') return false;
    int depth = 0;
    for (; k < text.size(); ++k) {
      if (text[k] == '(') ++depth;
      if (text[k] == ')' && --depth == 0) break;
    }
    if (k == text.size()) return false;  // unclosed: the parser reports it
    ++k;
  }
}

/// One letter of an address word the shortcut takes (address_head's letters but V, which
/// `word` tries as a variable first).
bool plain_address_letter(char c) {
  switch (ascii_upper(c)) {
    case 'M':
    case 'H':
    case 'F':
    case 'E':
    case 'S':
    case 'T':
    case 'D':
    case 'I':
    case 'J':
    case 'K':
    case 'R':
    case 'X':
    case 'Y':
    case 'Z':
    case 'A':
    case 'B':
    case 'C':
    case 'U':
    case 'W':
      return true;
    default:
      return false;
  }
}

// The plain shape, the shape of most blocks: an optional block number `N<digits>[:]`, then
// words `G<digits>`, `<letter><number>`, `<letter><sign><number>` or a letter, an optional sign
// and at once a bracketed expression of the plain shape (`X[[1.5+2]/2]`, `Y-[ABS[3]-10]`;
// grammar/plain_expression.hpp) (letter: plain_address_letter), each followed by separators or
// at once by the next word; separators are blanks and `( ... )` comments (as rules::ws reads
// them); a `;` comment may end the block. Nothing else: no `=`, other `[`, `\\`, skip level,
// label, header, statement, call or $GOTO. rules::block reads such a block through
// opt<block_number> and word_list, each G word through g_word (no `= value`; g_params matches
// empty without a `[`) and each other word through plain_address_word or (a bracketed value)
// address_word, with no other rule matching anything or acting
// (BlockParser::Impl::read_plain_block).

}  // namespace

struct BlockParser::Impl {
  const core::SourceFile& file;
  std::string_view text;
  std::size_t pos = 0;     // start of the next line
  std::uint32_t line = 1;  // its line number
  Mode mode = Mode::normal;
  core::SourceLoc mode_loc;     // the #VAR / #COMMENT BEGIN that opened the mode
  bool single_line = true;      // the current block holds no line end (see split)
  std::size_t released_at = 0;  // position of the last SourceFile::release_before
  State state;
  bool shortcut = true;  // plain blocks past rules::block (read_plain_block)

  explicit Impl(const core::SourceFile& f) : file(f), text(f.text()) {}

  void report(core::DiagnosticList& diags, core::SourceLoc loc, const char* id,
              std::string message) const {
    diags.add({core::Severity::error, file.name(), loc, id, std::move(message)});
  }

  /// Splits off the next block: one line, plus the following lines while a line ends in `\`
  /// outside comments (§1.3). Returns [begin, end) without the line end; advances pos/line.
  /// `no_line_end` is set when the block text certainly holds no line end.
  std::pair<std::size_t, std::size_t> split(std::uint32_t& lines, bool& no_line_end) {
    // Fast path: a line without any `\` can neither continue nor hide a line end in a string.
    const char* const data = text.data();
    const void* const lf = std::memchr(data + pos, '\n', text.size() - pos);
    const std::size_t line_end =
        lf != nullptr ? static_cast<std::size_t>(static_cast<const char*>(lf) - data) : text.size();
    if (std::memchr(data + pos, '\\', line_end - pos) == nullptr) {
      const std::size_t begin = pos;
      lines = 1;
      no_line_end = true;
      pos = line_end < text.size() ? line_end + 1 : text.size();
      std::size_t end = line_end;
      if (end > begin && text[end - 1] == '\r') --end;
      return {begin, end};
    }
    no_line_end = false;
    return split_slow(lines);
  }

  std::pair<std::size_t, std::size_t> split_slow(std::uint32_t& lines) {
    const std::size_t begin = pos;
    lines = 1;
    for (;;) {
      std::size_t p = pos;
      int depth = 0;
      bool comment = false;
      bool quote = false;
      std::size_t last = std::string_view::npos;  // last non-blank outside comments
      while (p < text.size() && text[p] != '\n') {
        const char c = text[p];
        if (comment) {
        } else if (quote) {
          if (c == '\\')
            ++p;
          else if (c == '"')
            quote = false;
        } else if (depth > 0) {
          if (c == '(')
            ++depth;
          else if (c == ')')
            --depth;
        } else if (c == '(') {
          depth = 1;
        } else if (c == ';') {
          comment = true;
        } else if (c == '"') {
          quote = true;
        } else if (!blank(c)) {
          last = p;
        }
        ++p;
      }
      const std::size_t line_end = std::min(p, text.size());
      pos = line_end < text.size() ? line_end + 1 : text.size();
      const bool more = !comment && depth == 0 && last != std::string_view::npos &&
                        text[last] == '\\' && pos < text.size();
      if (!more) {
        std::size_t end = line_end;
        if (end > begin && text[end - 1] == '\r') --end;
        return {begin, end};
      }
      ++lines;
    }
  }

  /// What rules::block does on a block of the plain shape (above), without trying
  /// its alternatives: separators, the block number (Action<rules::block_number>), each G word
  /// as g_word (Action<rules::g_code>, Action<rules::g_word>) and each other word as
  /// plain_address_word (Action<rules::word> has nothing to do without a call), then
  /// Action<rules::word_list>. The shape is checked as the block is read, each word before its
  /// actions: false where the block leaves the plain shape (the caller then discards what was
  /// done and reads the block through rules::block).
  bool read_plain_block(Input& in) {
    // the plain shape's separators: blanks and ( ) comments (rules::ws reads them the same way)
    const auto separators = [&] {
      const char* p = in.current();
      const char* const e = in.end();
      while (p < e) {
        if (blank(*p)) {
          ++p;
        } else if (*p == '(') {
          p = lex::paren_comment_end(p, e);
        } else {
          break;
        }
      }
      in.bump(static_cast<std::size_t>(p - in.current()));
    };
    // The digits at in.current() + skip, and how many there are.
    const auto digits_after = [&](std::size_t skip) {
      std::size_t n = skip;
      while (n < in.size() && lex::is_digit(in.peek_char(n)))
        ++n;
      return n;
    };
    separators();
    if (!in.empty() && ascii_upper(in.peek_char()) == 'N') {
      std::size_t n = digits_after(1);
      if (n == 1) return false;
      if (n < in.size() && in.peek_char(n) == ':') ++n;
      const char* const begin = in.current();
      in.bump(n);
      detail::add_block_number(state, begin, std::string_view(begin, n));
      separators();
    }
    while (!in.empty() && in.peek_char() != ';') {
      const char letter = ascii_upper(in.peek_char());
      if (letter == 'G') {
        const std::size_t n = digits_after(1);
        if (n == 1) return false;
        const char* const begin = in.current();
        state.g_code = detail::parse_uint(std::string_view(begin + 1, n - 1));
        in.bump(n);
        detail::add_g_word(state, begin, std::string_view(begin, n));
      } else if (!plain_address_letter(letter) ||
                 !(plain_address_word<pegtl::apply_mode::action, Action, Control>(in, state) ||
                   read_bracket_word(in))) {
        return false;  // plain_address_word and read_bracket_word read or do nothing
      }
      separators();
    }
    Action<rules::word_list>::apply(in, state);
    return true;
  }

  /// A word of the plain shape whose value is a bracketed expression, `X[[63.607+33.715]/2]`,
  /// `Y-[ABS[1]-10]`: the letter (plain_address_letter), an optional sign and at once a group
  /// that read_plain_group takes. What rules::word does on it: axis_command does not match
  /// (bracket_axis wants a command keyword after the `[`; the plain shape starts with a number,
  /// '[', a sign or a function name, none of which is one), so address_word reads it:
  /// address_head, sign, address_operand's group, then address_value's and address_word's
  /// actions. False, with nothing read or done, on any other shape.
  bool read_bracket_word(Input& in) {
    const char* const value = in.current() + 1;  // after the one-letter head
    const char* const e = in.end();
    if (value >= e) return false;
    const char sign = *value == '-' || *value == '+' ? *value : '\0';
    const char* const open = sign != '\0' ? value + 1 : value;
    if (open >= e || *open != '[') return false;
    const char* const close = read_plain_group(open, e, state);
    if (close == nullptr) return false;
    // matches: every plain_address_letter is an address_head letter
    rules::address_head::match<pegtl::apply_mode::action, pegtl::rewind_mode::dontcare, Action,
                               Control>(in, state);
    state.sign = sign;  // Action<rules::sign>, or no sign
    in.bump(static_cast<std::size_t>(close - value));
    state.end_address_value(state.loc(value));  // Action<rules::address_value>
    state.add_address_word();                   // Action<rules::address_word>
    return true;
  }

  /// The plain-shape shortcut for `out` (read_plain_block); false, with `out` and the state as
  /// before it, when the block is not of that shape or the shortcut stopped at an error: the
  /// whole grammar reads it then and reports the error itself.
  bool read_plain(ast::Block& out, Input& in, bool multiline) {
    try {
      if (read_plain_block(in)) return true;
    } catch (const ParseFailure&) {
    }
    out.words.clear();
    out.exprs.clear();
    out.number.reset();
    state.reset(out, out.text.data(), out.text.data() + out.text.size(), out.loc, multiline);
    in.restart();
    return false;
  }

  template <typename Rule>
  void parse(ast::Block& out, core::DiagnosticList& diags) {
    const bool multiline = !single_line && out.text.find('\n') != std::string_view::npos;
    state.reset(out, out.text.data(), out.text.data() + out.text.size(), out.loc, multiline);
    Input in(out.text.data(), out.text.data() + out.text.size(), "");
    try {
      if constexpr (std::is_same_v<Rule, rules::block>) {
        if (shortcut && read_plain(out, in, multiline)) return;
      }
      if (!pegtl::parse<Rule, Action, Control>(in, state)) {
        throw ParseFailure{in.current(), "NC1001", "a block", {}};
      }
    } catch (const ParseFailure& f) {
      out.has_error = true;
      std::string message = f.message;
      if (message.empty()) {
        message = std::string("expected ") + f.expected + ", found " +
                  lex::describe(f.at, out.text.data() + out.text.size());
      }
      report(diags, state.loc(f.at), f.id, std::move(message));
    }
  }

  bool next(ast::Block& out, core::DiagnosticList& diags) {
    if (pos == 0 && text.substr(0, 3) == "\xEF\xBB\xBF") {
      // Decision (docs/language.md): a UTF-8 byte order mark is skipped with a note.
      pos = 3;
      diags.add({core::Severity::note,
                 file.name(),
                 {1, 1},
                 "NC1006",
                 "the file starts with a UTF-8 byte order mark; ncsim skips it (columns of "
                 "line 1 count its 3 bytes)"});
    }
    for (;;) {
      if (pos >= text.size()) {
        if (mode == Mode::comment) {
          report(diags, mode_loc, "NC2016", "#COMMENT BEGIN is not closed by #COMMENT END");
        } else if (mode == Mode::declarations) {
          report(diags, mode_loc, "NC2016", "#VAR is not closed by #ENDVAR");
        }
        mode = Mode::normal;
        return false;
      }
      const std::uint32_t first_line = line;
      std::uint32_t lines = 1;
      const auto [begin, end] = split(lines, single_line);
      line += lines;
      if (begin >= released_at + core::SourceFile::kKeepBehind) {
        file.release_before(begin);
        released_at = begin;
      }
      const std::string_view block_text = text.substr(begin, end - begin);
      const std::string_view head = trimmed(block_text);
      if (mode == Mode::comment) {
        if (!is_command(head, "COMMENT", "END")) continue;
      }
      if (head.empty() || head[0] == ';') continue;

      out.clear();
      out.loc = {first_line, 1};
      out.offset = begin;
      out.text = block_text;
      if (block_text.size() > kMaxBlockLength) {
        // Decision (docs/language.md): a comment-only line is no block, whatever its length,
        // with `( ... )` as with `;`.
        if (comment_only(block_text)) continue;
        out.has_error = true;
        report(diags, file.loc_of(begin + kMaxBlockLength), "NC1003",
               "block longer than " + std::to_string(kMaxBlockLength) + " characters (" +
                   std::to_string(block_text.size()) + ")");
        return true;
      }

      if (mode == Mode::declarations && head[0] != '#') {
        const bool variable =
            (head.size() > 1 && (head[0] == 'V' || head[0] == 'v') && head[1] == '.') ||
            head[0] == '/';
        if (variable) {
          parse<rules::declaration>(out, diags);
          return true;
        }
        report(diags, mode_loc, "NC2016", "#VAR is not closed by #ENDVAR");
        mode = Mode::normal;
      }

      parse<rules::block>(out, diags);
      if (const auto* h = std::get_if<ast::HashCommand>(&out.body)) {
        switch (h->kind) {
          case ast::HashKind::comment_begin:
            mode = Mode::comment;
            mode_loc = h->loc;
            break;
          case ast::HashKind::comment_end:
            if (mode != Mode::comment) {
              report(diags, h->loc, "NC2016", "#COMMENT END without #COMMENT BEGIN");
            }
            mode = Mode::normal;
            break;
          case ast::HashKind::var:
            if (mode == Mode::declarations) {
              report(diags, mode_loc, "NC2016", "#VAR is not closed by #ENDVAR");
            }
            mode = Mode::declarations;
            mode_loc = h->loc;
            break;
          case ast::HashKind::endvar:
            if (mode != Mode::declarations) {
              report(diags, h->loc, "NC2016", "#ENDVAR without #VAR");
            }
            mode = Mode::normal;
            break;
          default:
            if (mode == Mode::declarations) {
              report(diags, mode_loc, "NC2016", "#VAR is not closed by #ENDVAR");
              mode = Mode::normal;
            }
            break;
        }
      }
      if (!out.has_error && std::holds_alternative<ast::Empty>(out.body) && out.words.empty() &&
          !out.skip && !out.number && !out.label && !out.call && out.axis_commands.empty() &&
          !out.trailing_goto) {
        continue;  // a comment-only line
      }
      return true;
    }
  }
};

BlockParser::BlockParser(const core::SourceFile& file)
    : file_(file), impl_(std::make_unique<Impl>(file)) {}

BlockParser::~BlockParser() = default;

bool BlockParser::next(ast::Block& out, core::DiagnosticList& diags) {
  return impl_->next(out, diags);
}

void BlockParser::use_shortcut(bool on) {
  impl_->shortcut = on;
}

BlockParser::Position BlockParser::position() const {
  return {impl_->pos, impl_->line, static_cast<std::uint8_t>(impl_->mode), impl_->mode_loc};
}

void BlockParser::seek(const Position& at) {
  impl_->pos = at.offset;
  impl_->line = at.line;
  impl_->mode = static_cast<Mode>(at.mode);
  impl_->mode_loc = at.mode_loc;
  impl_->released_at = at.offset;
}

}  // namespace ncsim::grammar
