# The reference 1b, which also includes a file beside its contract by the contract's kind of name:
# <problems/1b/tests.hpp>, which includes nothing and would compile anywhere. The sandboxed
# compiler finds the contract by its repository path in the contracts' copies (CMakeLists.txt),
# which hold the contracts alone, never the rest of a problem's folder, public or secret (grade/):
# the include does not compile and problem 1b earns nothing. Seen to earn full marks with
# problems/1b/tests.hpp copied beside the contract's copy, as a staging of the whole folder would.
set(TARGET p1b.cpp)
set(FROM "#include <problems/1b/contract.hpp>\n")
set(TO "${FROM}#include <problems/1b/tests.hpp>\n")
