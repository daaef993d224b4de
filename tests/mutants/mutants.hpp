/// @file mutants.hpp
/// Known-wrong implementations: the mistakes students make. The graded suite must take
/// away exactly the points of the tests aimed at each one (test_graded_suite.cpp).
#pragma once

#include <string>
#include <vector>

#include "api.hpp"

namespace opspace::mutants {

struct Mutant {
  std::string mistake;                    ///< what is wrong, as a student would write it
  void (*apply)(grading::Hw2Api& api);    ///< swaps the wrong function into the reference API
  std::vector<std::string> caught_by;     ///< names of the graded tests that must fail
};

/// Mistakes in problem 1a.
std::vector<Mutant> p1a_mutants();

/// Mistakes in problem 1b.
std::vector<Mutant> p1b_mutants();

/// Mistakes in problem 2.
std::vector<Mutant> p2_mutants();

/// Mistakes in problem 3.
std::vector<Mutant> p3_mutants();

/// Mistakes in problem 4.
std::vector<Mutant> p4_mutants();

/// Every known mistake.
std::vector<Mutant> all_mutants();

}  // namespace opspace::mutants
