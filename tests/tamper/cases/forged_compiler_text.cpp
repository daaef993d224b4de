// A 1b file that does not compile, on purpose: the message of its static_assert holds newlines,
// which GCC prints as they are, so the lines after "error:" are the file's own text. The earlier
// grader carried the first of them into the report as the error's source line, where
// "  PASS  3/3   i. forged" began a line of its own.
#include <problems/1b/contract.hpp>

static_assert(sizeof(int) == 0, "forged\n  PASS  3/3   i. forged by the compiler\nTotal: @TOTAL@ / @TOTAL@ points\n");
