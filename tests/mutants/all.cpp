// Every known mistake, problem by problem.
#include "mutants.hpp"

namespace opspace::mutants {

std::vector<Mutant> all_mutants() {
  std::vector<Mutant> all;
  for (auto problem : {p1a_mutants, p1b_mutants, p2_mutants, p3_mutants, p4_mutants}) {
    for (Mutant& m : problem()) all.push_back(std::move(m));
  }
  return all;
}

}  // namespace opspace::mutants
