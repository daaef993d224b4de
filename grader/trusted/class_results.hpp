/// @file class_results.hpp
/// A class's grades as the class page reads them (class_page.hpp): one results.json per
/// student, as hw2-grade --gradescope writes it (each test's extra_data: class_record.hpp) and
/// scripts/regrade completes it (deploy/results.cmake). Nothing else is read, so that the page
/// of a course graded on Gradescope is built from the results it exports.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "grading.hpp"

namespace opspace::grading {

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
  std::vector<ClassTest> tests;
};

/// The student `name` of a results.json's text `json` (an invalid text: not graded, saying so).
ClassStudent read_student(const std::string& name, const std::string& json);

/// Every student of `folder`: each subfolder holding a results.json (named after the
/// subfolder; its report.txt, if any, is the report) and each other *.json file (named after
/// the file), in the byte order of their names. Throws std::runtime_error if `folder` cannot be read.
std::vector<ClassStudent> read_class(const std::string& folder);

}  // namespace opspace::grading
