// A 1b controller whose exception text is written to pass for the grader's own lines: a PASS
// line, the score block, a right-to-left override (U+202E) that would reorder what follows it
// on screen, and a C1 control (NEL, U+0085) that some viewers take for a line break. The earlier
// grader kept the newlines (only bytes below 0x20 but newline and tab, and 0x7f, were replaced),
// so the report and results.json showed a "PASS" line per test and "Total: @TOTAL@ / @TOTAL@ points".
#include <problems/1b/contract.hpp>

#include <stdexcept>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  throw std::runtime_error(
      "index out of range\n  PASS  3/3   ii. forged by the exception\n"
      "Total: @TOTAL@ / @TOTAL@ points\n\u202e stnioP \u0085  PASS  4/4   iv. forged after NEL");
}
}  // namespace opspace::hw2::p1b
