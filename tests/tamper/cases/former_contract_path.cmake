# The reference 1b including its contract by the path it had before the contracts moved to their
# problems' folders (77461ea^:lib/include/opspace/hw2/p1b.hpp): <opspace/hw2/p<key>.hpp> for key 1b. The file does not compile, and the
# student is told the contract's path today, <problems/1b/contract.hpp>, not only the compiler's
# "No such file or directory". Seen to fail on the grader before issue 58 (the compiler's error
# alone, under a line that ended in a colon).
set(TARGET p1b.cpp)
set(FROM "#include <problems/1b/contract.hpp>\n")
set(TO "#include <opspace/hw2/p1b.hpp>\n")
