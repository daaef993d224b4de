// Attack: define the grader's own functions, hoping to replace them at link time.
#include <problems/1b/contract.hpp>

#include <string>
#include <vector>

namespace opspace::grading {
struct Check;
struct Problem;
double full_marks() { return @TOTAL@.0; }
void become_subreaper() {}
std::string sanitize(const std::string& text, unsigned long, unsigned long) { return text; }
int grader_main(int, char**, const std::string&) { return 0; }
}  // namespace opspace::grading

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) { return Vector6d::Zero(); }
}  // namespace opspace::hw2::p1b
