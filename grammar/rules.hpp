#pragma once
// grammar/rules: the PEGTL grammar of one NC block (internal to grammar/; nothing else includes
// PEGTL). Rules only: the actions that build the AST live in block_parser.cpp, the error texts
// in errors.hpp. `must<>` stands exactly at the commit points, so an error names what was
// expected there. Custom rules (nested comments, keyword tables, names) are declared here and
// matched by code in block_parser.cpp, because they need the parser state.
//
// Reference: isg-language.md §1-6; docs/language.md is the grammar as implemented.

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

namespace ncsim::grammar::rules {

namespace pegtl = tao::pegtl;
using pegtl::alnum;
using pegtl::alpha;
using pegtl::any;
using pegtl::at;
using pegtl::blank;
using pegtl::digit;
using pegtl::eof;
using pegtl::must;
using pegtl::not_at;
using pegtl::not_one;
using pegtl::one;
using pegtl::opt;
using pegtl::plus;
using pegtl::seq;
using pegtl::sor;
using pegtl::star;

// A rule matched by hand-written code (in block_parser.cpp); analysed as "may consume".
#define NCSIM_CUSTOM_RULE(name)                                                               \
  struct name {                                                                               \
    using rule_t = name;                                                                      \
    using subs_t = pegtl::empty_list;                                                         \
    template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Action, \
              template <typename...> class Control, typename Input, typename State>           \
    static bool match(Input& in, State& st);                                                  \
  }

// Lexical (isg-language.md §1)
struct ident_char : sor<alnum, one<'_'>> {};
template <typename S>
struct kw : seq<S, not_at<ident_char>> {};
#define NCSIM_KW(x) kw<TAO_PEGTL_ISTRING(x)>

NCSIM_CUSTOM_RULE(paren_comment);  // ( ... ) nested, iterative; an unclosed one runs to the end
struct line_comment : seq<one<';'>, star<any>> {};  // ; to the block end
struct continuation : seq<one<'\\'>, star<blank>, opt<one<'\r'>>, one<'\n'>> {};  // \ + EOL
// Separators between tokens. `ws` matches exactly star<sep_spec> (kept for the analysis
// test), by a loop that dispatches on the character: it runs between every two tokens.
struct sep_spec : sor<blank, paren_comment, continuation, one<'\r'>> {};
NCSIM_CUSTOM_RULE(ws);  // star<sep_spec>
struct block_end : seq<ws, opt<line_comment>, eof> {};

struct digits : plus<digit> {};
// Decimal literal: matches exactly number_spec (kept for the analysis test) and pushes its node
// with the value; hand-written so that scanning and the value conversion are one pass.
struct number_spec : sor<seq<digits, opt<one<'.'>, star<digit>>>, seq<one<'.'>, digits>> {};
NCSIM_CUSTOM_RULE(number);
struct hex_body : plus<not_one<'\'', '\n'>> {};
struct close_quote1 : one<'\''> {};
struct hex_number : seq<one<'\''>, must<hex_body, close_quote1>> {};  // '16#FA1B' '0x0ED2'
struct name : plus<ident_char> {};

struct string_body : star<sor<seq<one<'\\'>, any>, not_one<'"', '\\'>>> {};
struct close_quote2 : one<'"'> {};
struct quoted : seq<one<'"'>, string_body, must<close_quote2>> {};

// `Rule` (a star<> or opt<> of an operator tail `seq<ws, op, ...>`), tried only when the
// character after the separators can start the operator (one of `First`): otherwise `Rule`
// matches empty, as it would after trying. Every operand of an expression passes ten levels of
// precedence, each with its tail; this spares the nine attempts that cannot match.
template <typename Rule, char... First>
struct when_next {
  using rule_t = when_next;
  using subs_t = pegtl::type_list<Rule>;
  template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename Input, typename State>
  static bool match(Input& in, State& st);
};

// Expressions (isg-language.md §3; precedence in docs/language.md)
struct expression;
struct open_bracket : one<'['> {};
struct close_bracket : one<']'> {};
struct comma : one<','> {};

struct group : seq<one<'['>, ws, must<expression>, ws, must<close_bracket>> {};

NCSIM_CUSTOM_RULE(function_name);  // a name from the function table (SIN, ATAN2, ...)
struct argument : seq<expression> {};
struct call : seq<function_name, ws, must<open_bracket>, ws, must<argument>,
                  star<seq<ws, comma, ws, must<argument>>>, ws, must<close_bracket>> {};
struct constant : sor<NCSIM_KW("TRUE"), NCSIM_KW("FALSE"), NCSIM_KW("PI")> {};

// Variables: P1, PP10, @P1, V.<class>.<name> with [index] and .member tails.
struct var_p_head : seq<opt<one<'@'>>, pegtl::istring<'P'>, opt<pegtl::istring<'P'>>, digits> {};
struct var_v_head : seq<pegtl::istring<'V'>, one<'.'>, at<alpha>, name> {};
struct var_head : sor<var_p_head, var_v_head> {};
struct index_expr : seq<expression> {};
struct var_subscript : seq<one<'['>, ws, must<index_expr>, ws, must<close_bracket>> {};
struct member_name : name {};
struct var_member : seq<one<'.'>, must<member_name>> {};
struct variable : seq<var_head, star<sor<var_subscript, var_member>>> {};

struct string_operand : quoted {};
struct primary : sor<number, hex_number, group, string_operand, call, constant, variable> {};

struct operand;
struct op_power : seq<one<'*'>, one<'*'>> {};
struct power_tail : seq<ws, op_power, ws, must<operand>> {};
struct power : seq<primary, when_next<opt<power_tail>, '*'>> {};
struct unary_op : sor<one<'-'>, one<'+'>, NCSIM_KW("NOT"), NCSIM_KW("INV")> {};
struct unary : seq<unary_op, ws, must<operand>> {};
struct operand : sor<unary, power> {};  // -2**2 = -[2**2]; 2**-1 allowed; ** is right-assoc

struct op_mul : sor<seq<one<'*'>, not_at<one<'*'>>>, one<'/'>, NCSIM_KW("MOD")> {};
struct mul_tail : seq<ws, op_mul, ws, must<operand>> {};
struct product : seq<operand, when_next<star<mul_tail>, '*', '/', 'M', 'm'>> {};
struct op_add : one<'+', '-'> {};
struct add_tail : seq<ws, op_add, ws, must<product>> {};
struct sum : seq<product, when_next<star<add_tail>, '+', '-'>> {};
struct op_cmp : sor<pegtl::string<'=', '='>, pegtl::string<'!', '='>, pegtl::string<'<', '='>,
                    pegtl::string<'>', '='>, one<'<'>, one<'>'>> {};
struct cmp_tail : seq<ws, op_cmp, ws, must<sum>> {};
struct comparison : seq<sum, when_next<star<cmp_tail>, '=', '!', '<', '>'>> {};
struct op_band : seq<one<'&'>, not_at<one<'&'>>> {};
struct band_tail : seq<ws, op_band, ws, must<comparison>> {};
struct band : seq<comparison, when_next<star<band_tail>, '&'>> {};
struct op_bxor : one<'^'> {};
struct bxor_tail : seq<ws, op_bxor, ws, must<band>> {};
struct bxor : seq<band, when_next<star<bxor_tail>, '^'>> {};
struct op_bor : seq<one<'|'>, not_at<one<'|'>>> {};
struct bor_tail : seq<ws, op_bor, ws, must<bxor>> {};
struct bor : seq<bxor, when_next<star<bor_tail>, '|'>> {};
struct op_land : pegtl::string<'&', '&'> {};
struct land_tail : seq<ws, op_land, ws, must<bor>> {};
struct land : seq<bor, when_next<star<land_tail>, '&'>> {};
struct op_lxor : NCSIM_KW("XOR") {};
struct lxor_tail : seq<ws, op_lxor, ws, must<land>> {};
struct lxor : seq<land, when_next<star<lxor_tail>, 'X', 'x'>> {};
struct op_lor : pegtl::string<'|', '|'> {};
struct lor_tail : seq<ws, op_lor, ws, must<lxor>> {};
struct lor : seq<lxor, when_next<star<lor_tail>, '|'>> {};
struct expression : lor {};

// Words (isg-language.md §1.3, §1.9, §2, §3.7, §3.8, §4.9, §6)
struct sign : one<'+', '-'> {};
struct address_operand : sor<number, hex_number, group, variable, string_operand> {};
struct address_value : seq<opt<sign>, ws, must<address_operand>> {};
struct equals : seq<one<'='>, not_at<one<'='>>> {};

struct g_code : digits {};
struct g_arg : expression {};
NCSIM_CUSTOM_RULE(g_params);  // G80-G89 / G800-G839 [v1, v2,, v4]; matches empty otherwise
struct g_word : seq<pegtl::istring<'G'>, must<g_code>, opt<ws, equals, ws, must<g_arg>>, g_params> {
};

template <char L>
struct letter_head : seq<pegtl::istring<L>, not_at<ident_char>> {};
NCSIM_CUSTOM_RULE(address_head);  // M H F E S T D I J K R X Y Z A B C U V W (one letter)
struct address_word : seq<address_head, ws, opt<equals, ws>, must<address_value>> {};

// M/H functions with an additional value (PROG "M/H functions with optional additional
// information"): M200=1200, H5=-345, M52=-P2.
struct extra_value : seq<opt<sign>, ws, must<address_operand>> {};
struct mh_word : seq<address_head, ws, address_value, ws, equals, ws, must<extra_value>> {};

NCSIM_CUSTOM_RULE(axis_name_eq);  // AB= (multi-letter axis name followed by '=')
struct named_axis : seq<axis_name_eq, ws, equals, ws, must<address_value>> {};

struct assign_op : sor<equals, pegtl::string<'+', '='>, pegtl::string<'-', '='>,
                       pegtl::string<'*', '='>, pegtl::string<'/', '='>> {};
struct assign_target : seq<variable> {};
struct assign_value : expression {};
struct assignment
    : seq<at<variable, ws, assign_op>, assign_target, ws, assign_op, ws, must<assign_value>> {};

struct macro_name : quoted {};
struct macro_text : quoted {};
struct macro_equals : equals {};
struct macro_def : seq<macro_name, ws, must<macro_equals>, ws, must<macro_text>> {};

struct bare_value : sor<number, hex_number, group, variable> {};

// Calls: L name, LL name, L "macro", L V.E.x, L CYCLE [...]
NCSIM_CUSTOM_RULE(call_head);      // L or LL followed by a blank or '"'
NCSIM_CUSTOM_RULE(file_name);      // subroutine or file name
NCSIM_CUSTOM_RULE(bracket_items);  // keyword/value items of the current table, up to ']'
struct call_variable : seq<variable> {};
struct call_macro : quoted {};
struct cycle_kw : NCSIM_KW("CYCLE") {};
struct cycle_list : seq<open_bracket, bracket_items, must<close_bracket>> {};
struct cycle_call : seq<at<cycle_kw, ws, one<'['>>, cycle_kw, ws, must<cycle_list>> {};
struct call_target : sor<cycle_call, call_macro, call_variable, file_name> {};
struct subroutine_call : seq<call_head, ws, must<call_target>> {};

// Axis-bracket commands: X[INDP_SYN ...], S1 [MC_MoveVelocity ...]
NCSIM_CUSTOM_RULE(bracket_axis);  // axis or spindle name followed by '[' and a command
struct axis_command : seq<bracket_axis, ws, one<'['>, bracket_items, must<close_bracket>> {};

NCSIM_CUSTOM_RULE(misplaced_statement);  // '#' or '$' (not $GOTO) among words: always throws

// One word. `word` tries exactly the alternatives of word_spec in this order (word_spec is kept
// for the analysis test), but only those that can match the first character, and skips
// axis_command / named_axis unless the name is followed by '[' / '=': most words are `X-1.5`.
struct word_spec : sor<misplaced_statement, subroutine_call, macro_def, assignment, axis_command,
                       g_word, mh_word, named_axis, address_word, bare_value> {};
NCSIM_CUSTOM_RULE(word);

// $ control statements (isg-language.md §4)
NCSIM_CUSTOM_RULE(goto_target);  // N10, [name], V.E.x; else error 20839
struct goto_kw : seq<one<'$'>, ws, NCSIM_KW("GOTO")> {};
struct goto_stmt : seq<goto_kw, ws, goto_target> {};
struct condition : expression {};
NCSIM_CUSTOM_RULE(control_keyword);  // $IF, $ENDFOR, ... (sets the kind)
struct for_counter : seq<variable> {};
struct for_value : expression {};
struct for_equals : equals {};
struct for_header : seq<must<for_counter>, ws, must<for_equals>, ws, must<for_value>, ws,
                        must<comma>, ws, must<for_value>, opt<ws, comma, ws, must<for_value>>> {};
NCSIM_CUSTOM_RULE(control_operands);  // the operands of the keyword just read
NCSIM_CUSTOM_RULE(statement_end);     // end of block, else 20219 / NC2008 / NC2007
struct control_stmt : seq<control_keyword, control_operands, statement_end> {};

// # commands (isg-language.md §5)
NCSIM_CUSTOM_RULE(hash_command);  // '#' NAME ... (per-command grammar in block_parser.cpp)
struct hash_stmt : seq<hash_command, statement_end> {};

// Block
struct skip_level : seq<one<'/'>, opt<digits>> {};
struct block_number_expr : expression {};
struct block_number
    : seq<pegtl::istring<'N'>,
          sor<seq<digits, opt<one<':'>>>,
              seq<one<'['>, ws, must<block_number_expr>, ws, must<close_bracket>>>> {};
struct label_name : name {};
struct label : seq<one<'['>, must<label_name>, must<close_bracket>> {};
struct program_name : plus<not_one<' ', '\t', '(', ';', '\r', '\n'>> {};
// A main program's name may hold blanks (`% 1x10 dots right`, TF5200 "NC program
// structure": the name is the rest of the line; docs/language.md).
struct main_program_name : seq<program_name, star<star<blank>, program_name>> {};
struct local_header : seq<pegtl::istring<'L'>, plus<blank>, must<program_name>> {};
struct header : seq<one<'%'>, star<blank>, sor<local_header, opt<main_program_name>>> {};
struct trailing_goto : goto_stmt {};
struct words_end : seq<opt<trailing_goto>, block_end> {};
struct word_list : seq<star<word, ws>, must<words_end>> {};
struct body : sor<seq<header, must<block_end>>, control_stmt, hash_stmt, word_list> {};
struct block : seq<ws, opt<skip_level>, ws, opt<block_number>, ws, opt<label>, ws, body> {};

// Declaration lines between #VAR and #ENDVAR (isg-language.md §3.6).
struct decl_variable : seq<variable> {};
NCSIM_CUSTOM_RULE(decl_type);  // BOOLEAN, SGN08, ..., REAL64, REAL, STRING[n]
struct decl_colon : one<':'> {};
struct init_value : expression {};
struct init_list;
struct init_element : sor<init_list, init_value> {};
struct init_list : seq<one<'['>, ws, must<init_element>, star<ws, comma, ws, must<init_element>>,
                       ws, must<close_bracket>> {};
struct decl_init : sor<init_list, init_value> {};
struct declaration
    : seq<ws, opt<skip_level>, ws, must<decl_variable>, ws, opt<decl_colon, ws, must<decl_type>>,
          ws, opt<equals, ws, must<decl_init>>, must<block_end>> {};

#undef NCSIM_KW

}  // namespace ncsim::grammar::rules

namespace tao::pegtl {
#define NCSIM_ANALYZE_CUSTOM(r) \
  template <typename Name>      \
  struct analyze_traits<Name, ncsim::grammar::rules::r> : analyze_any_traits<> {}
NCSIM_ANALYZE_CUSTOM(paren_comment);
NCSIM_ANALYZE_CUSTOM(number);
NCSIM_ANALYZE_CUSTOM(word);
NCSIM_ANALYZE_CUSTOM(function_name);
NCSIM_ANALYZE_CUSTOM(address_head);
NCSIM_ANALYZE_CUSTOM(axis_name_eq);
template <typename Name>
struct analyze_traits<Name, ncsim::grammar::rules::g_params> : analyze_opt_traits<> {};
NCSIM_ANALYZE_CUSTOM(call_head);
NCSIM_ANALYZE_CUSTOM(file_name);
NCSIM_ANALYZE_CUSTOM(bracket_axis);
NCSIM_ANALYZE_CUSTOM(misplaced_statement);
NCSIM_ANALYZE_CUSTOM(goto_target);
NCSIM_ANALYZE_CUSTOM(control_keyword);
NCSIM_ANALYZE_CUSTOM(decl_type);
NCSIM_ANALYZE_CUSTOM(hash_command);
template <typename Name>
struct analyze_traits<Name, ncsim::grammar::rules::ws> : analyze_opt_traits<> {};
template <typename Name, typename Rule, char... First>
struct analyze_traits<Name, ncsim::grammar::rules::when_next<Rule, First...>>
    : analyze_opt_traits<Rule> {};
template <typename Name>
struct analyze_traits<Name, ncsim::grammar::rules::bracket_items> : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, ncsim::grammar::rules::control_operands> : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, ncsim::grammar::rules::statement_end> : analyze_opt_traits<> {};
#undef NCSIM_ANALYZE_CUSTOM
}  // namespace tao::pegtl
