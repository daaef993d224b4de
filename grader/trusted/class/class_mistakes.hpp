/// @file class_mistakes.hpp
/// The known mistakes a class made, ranked: the class page's first section and mistakes.csv
/// (class_page.hpp) read them from here.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "class/class_results.hpp"

namespace opspace::grading {

/// One named mistake of a problem, with the students who made it and the tests it cost.
struct MistakeRow {
  std::string problem, mistake;
  std::vector<std::size_t> students;  ///< indices into the class's students, each once
  std::map<std::string, int> tests;   ///< test (test_key): how many students it cost
};

/// A test's name with its problem's key in front: "1b ii. in simulation ...".
std::string test_key(const ClassTest& t);

/// The named mistakes, the most made first (then by problem and name): a student counts once.
std::vector<MistakeRow> ranked_mistakes(const std::vector<ClassStudent>& students);

}  // namespace opspace::grading
