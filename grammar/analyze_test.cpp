#include <doctest/doctest.h>

#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/rules.hpp"

namespace ncsim::grammar {

TEST_CASE("the grammar has no rule that can loop without consuming input") {
  CHECK(tao::pegtl::analyze<rules::block>(-1) == 0);
  CHECK(tao::pegtl::analyze<rules::declaration>(-1) == 0);
}

}  // namespace ncsim::grammar
