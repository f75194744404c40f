#include <doctest/doctest.h>

#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/rules.hpp"

namespace ncsim::grammar {

TEST_CASE("the grammar has no rule that can loop without consuming input") {
  CHECK(tao::pegtl::analyze<rules::block>(-1) == 0);
  CHECK(tao::pegtl::analyze<rules::declaration>(-1) == 0);
  // ws, number and word are matched by hand (custom_rules_hot.hpp); the PEG rules they
  // implement are analysed here, where the analysis can see inside them.
  CHECK(tao::pegtl::analyze<tao::pegtl::star<rules::sep_spec>>(-1) == 0);
  CHECK(tao::pegtl::analyze<rules::number_spec>(-1) == 0);
  CHECK(tao::pegtl::analyze<tao::pegtl::star<rules::word_spec, rules::sep_spec>>(-1) == 0);
}

}  // namespace ncsim::grammar
