// Attack: compile the reference solution in place of one's own.
#include "@REPO@/solutions/p1b.cpp"
