// A term of a linearisation (a measurement Jacobian H or the system matrix F) left out on purpose,
// with the bound on its size that makes leaving it out harmless. Each model lists its own beside
// its code; tests/filter/jacobian_test.cpp compares every other entry with a numerical
// derivative and holds the entries of these blocks only to `max_abs` (infinity: not compared,
// when the term has no state-independent bound), naming `reason` on failure.
#pragma once

#include <string_view>

namespace navfuse::filter {

struct NeglectedTerm {
  int first_row;  // rows of the block (for H: of the observation before keep_rows)
  int rows;
  int first_col;  // error-state columns (sx::)
  int cols;
  double max_abs;  // bound on each left-out entry under the stated conditions
  std::string_view reason;
};

}  // namespace navfuse::filter
