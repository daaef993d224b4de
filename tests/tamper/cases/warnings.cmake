# The reference 1b with a warning (a variable set but never used): the warning is shown and
# costs nothing.
set(TARGET p1b.cpp)
set(FROM "Vector6d control(Part part, const State& s, const Goal& goal) {")
set(TO "Vector6d control(Part part, const State& s, const Goal& goal) {\n  int set_but_unused = 0;\n  set_but_unused = 1;")
