/// @file class_results.hpp
/// A class's grades as the class page reads them (class_page.hpp): one results.json per
/// student, as hw2-grade --gradescope writes it (each test's extra_data: class_record.hpp) and
/// scripts/regrade completes it (deploy/results.cmake). Nothing else is read, so that the page
/// of a course graded on Gradescope is built from the results it exports. Every number read is
/// taken as hostile (issue 59: a run of 1e306 m, infinite once shown in mm, hung the page): one
/// the page cannot draw is refused and noted (ClassStudent::refused), costing its own row alone.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "judge/grading.hpp"

namespace opspace::grading {

/// The largest magnitude of a number of a results.json the page takes (a score, a time, a run's
/// value, a bound): a googol, far beyond any of the problems' in SI, and small enough that the
/// page's sums, spans and scalings of such numbers stay finite. A run holding a number beyond
/// it, a time not a number or a value infinite is left out of the plots; a score beyond it counts 0.
inline constexpr double kLargestNumber = 1e100;
/// A unit's factor (class_record.hpp's unit_scale; the problems' are 1, 1e3 and 180/pi) within
/// this factor of 1, or the run is left out.
inline constexpr double kLargestUnitScale = 1e6;
/// The largest results.json read (bytes): 16 times the 1 MB Gradescope takes, which the grader's
/// results.json is tested to stay under (tests/graded/check_results_page.cmake).
inline constexpr std::uintmax_t kLargestResults = std::uintmax_t{16} << 20;

/// One judged run of a simulated test (class_record.hpp's "runs"), values in SI.
struct ClassRun {
  std::string statistic, quantity, unit, judged;
  double unit_scale = 1.0;
  double bound = std::numeric_limits<double>::quiet_NaN();
  bool upper = true;
  double judged_from = 0.0;
  double yours = std::numeric_limits<double>::quiet_NaN();
  double reference = std::numeric_limits<double>::quiet_NaN();
  Series student;
  Series reference_series;  ///< empty when the grader did not run the reference for this test
};

/// One test of one student.
struct ClassTest {
  std::string problem;  ///< its problem's key
  std::string name;     ///< the test's sentence, without the key
  std::string mistake;  ///< the known mistake the grader named for it, if any
  double score = 0.0, max_score = 0.0;
  bool interrupted = false, grader_fault = false;
  bool not_built = false;  ///< its problem's file did not compile (the test is interrupted too)
  std::vector<ClassRun> runs;
  bool passed() const { return score >= max_score; }
};

/// One student's grading.
struct ClassStudent {
  std::string name;    ///< the folder (or file) name: the student's text, escaped where shown
  std::string report;  ///< the report's path relative to the class folder ("" if none)
  double score = 0.0, max_score = 0.0;
  int grader_faults = 0;
  bool unprotected = false;
  std::string not_graded;  ///< why the grading gave no tests ("" when it did)
  std::vector<std::string> refused;  ///< what of its results.json the page refused, each noted once
  /// What else needs a look: a zip of the submission refused (extra_data.submission.refused), a
  /// Gradescope export's status or score.
  std::vector<std::string> notes;
  /// The exercise files missing from the submission (graded as the stubs), and those named
  /// otherwise, as collect_submission.sh noted them (results.json's extra_data.submission).
  std::vector<std::string> missing, misnamed;
  std::vector<ClassTest> tests;
};

/// The student `name` of a results.json's text `json` (an invalid text: not graded, saying so).
ClassStudent read_student(const std::string& name, const std::string& json);

/// The same of results already read as JSON (a Gradescope export's stored ones): an object, or
/// the student is not graded, saying so.
ClassStudent read_student(const std::string& name, const nlohmann::json& results);

/// Whether `folder` holds any results read_class() reads.
bool holds_results(const std::string& folder);

/// Every student of `folder`: each subfolder holding a results.json (named after the
/// subfolder; its report.txt, if any, is the report) and each other *.json file (named after
/// the file), in the byte order of their names; a file that cannot be read is its student's row,
/// not graded, saying so. Throws std::runtime_error if `folder` cannot be read or holds no
/// results at all (a Gradescope export before its regrade: scripts/regrade).
std::vector<ClassStudent> read_class(const std::string& folder);

}  // namespace opspace::grading
