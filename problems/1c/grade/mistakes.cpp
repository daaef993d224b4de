// Known mistakes of problem 1c, each a change of one term of the law it wraps (the reference or
// the grader's oracle). The simulated test checks the law at every tick (law_pin.hpp), so each
// costs both tests.
#include "mistakes.hpp"

namespace opspace::grading {

std::vector<Mistake> mistakes_1c() {
  const std::string law = "i. the law is Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)";
  const std::string sim = "ii. in simulation the tip stays within 15 cm of x_d";
  using hw2::p1c::Goal;
  using hw2::p1c::State;
  using hw2::p1c::Vector6d;
  return {
      {"the joint damping of problem 1b's PART1 kept",
       "this law has no A (-kvj dq): the null space is left undamped",
       [](Hw2Api& api) {
         api.p1c.control = [law_fn = api.p1c.control](const State& s, const Goal& g) -> Vector6d {
           return law_fn(s, g) + s.A * (-g.kvj * s.dq);
         };
       },
       {law, sim}},
      {"gravity at the tip (p) left out",
       "F = Lambda_v (-kpx (x - x_d) - kvx dx) + p: without p the tip sags",
       [](Hw2Api& api) {
         api.p1c.control = [law_fn = api.p1c.control](const State& s, const Goal& g) -> Vector6d {
           return law_fn(s, g) - s.Jv.transpose() * s.p;
         };
       },
       {law, sim}},
  };
}

}  // namespace opspace::grading
