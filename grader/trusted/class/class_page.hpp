/// @file class_page.hpp
/// The class page (scripts/regrade writes OUT/class.html; hw2-class builds it from any folder
/// of results.json files): one offline file, no script, no request. At the top the students
/// whose grading needs a look (not graded, the grader's own faults, graded without the sandbox,
/// a file missing or misnamed, a file that did not compile, tests interrupted); then the known mistakes ranked by how many students made them, each with
/// its students and the tests it cost; per judged run of each simulated test, small multiples:
/// every student's run over the reference's with the bound, one plot per named mistake in its
/// colour; per problem the scores' distribution and each test's pass rate; every student's
/// total. The counts travel
/// in a JSON block (id "class-data") and data- attributes that the tests read. Every text the
/// students' side wrote (their names) is escaped.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "class/class_results.hpp"

namespace opspace::grading {

/// How the students are named: by their folder's name (linked to their report), or numbered in
/// order, with no name or link anywhere (a page to show in a lecture).
struct ClassPageOptions {
  bool anonymous = false;
  std::string source;  ///< what the results are, said at the top ("": each student's results.json)
};

void write_class_page(std::ostream& out, const std::vector<ClassStudent>& students, const ClassPageOptions& options);

/// The known mistakes, most made first: rank, problem, mistake, students (how many), tests (the
/// tests it cost), who (the students, "; " between): every field quoted, and one that a
/// spreadsheet would read as a formula (= + - @) behind a ' (as deploy/scores.cmake writes the
/// gradebook).
void write_mistakes_csv(std::ostream& out, const std::vector<ClassStudent>& students, const ClassPageOptions& options);

}  // namespace opspace::grading
