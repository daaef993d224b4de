# The reference 1b, except that its controller prints, once, text written to pass for the
# grader's lines once a viewer breaks or reorders it: U+2028 (LINE SEPARATOR, a line break in a
# browser's text), U+202E (RIGHT-TO-LEFT OVERRIDE), a C1 control (NEL, U+0085), an invalid
# UTF-8 byte, and plain newlines. The earlier grader passed all of them but C0 bytes through,
# and results.json showed the printed lines unquoted, so "Total: ${TOTAL} / ${TOTAL} points" began a line
# there. Printing costs nothing: 20/20.
set(TARGET p1b.cpp)
set(PREPEND "#include <cstdio>\n")
set(FROM "Vector6d control(Part part, const State& s, const Goal& goal) {")
set(TO [=[Vector6d control(Part part, const State& s, const Goal& goal) {
  static bool printed = false;
  if (!printed) {
    std::printf("%s", "hello\nTotal: ${TOTAL} / ${TOTAL} points\n\u2028  PASS  4/4   iv. forged after U+2028\u202e stnioP \u0085 NEL \xff\n");
    std::fflush(stdout);
    printed = true;
  }]=])
