// Problem 1c's run (problems/1c/run/scenario.hpp).
#include <problems/1c/run/scenario.hpp>

#include <utility>

namespace opspace::scenarios::p1c {

using hw2::p1b::Part;

Scenario scenario(Controller control) {
  return Scenario(Part::kTipPdWithoutJointDamping,
                  [control = std::move(control)](Part, const hw2::p1c::State& s, const hw2::p1c::Goal& goal) {
                    return control(s, goal);
                  });
}

Result run(Controller control, const RunOptions& options) {
  return scenarios::run(scenario(std::move(control)), options);
}

}  // namespace opspace::scenarios::p1c
