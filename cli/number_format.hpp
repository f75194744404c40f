#pragma once
// cli/number_format: the command's numbers are core/number_text's (num, json_num, human,
// seconds), named here for the cli's files.

#include "core/number_text.hpp"

namespace ncsim::cli {

using core::human;
using core::json_num;
using core::num;
using core::seconds;

}  // namespace ncsim::cli
