/// @file class_record.hpp
/// What the class page (class_page.hpp) needs of one graded test, written into results.json as
/// the test's extra_data, machine-readable: its problem and name, the known mistake named for
/// it, whether the student's code was interrupted or the grader faulted, and each judged run
/// (the figures that draw the statistic the test judged or hold its bound; else its first
/// figure, so that every simulated test has one): the statistic's two
/// values, the bound, and both series (the figure's, at most kFigurePoints points; the
/// reference's when the grader ran it), each a string of numbers rounded to kRecordDigits
/// significant digits (a class plot is a few hundred pixels tall), so that a Gradescope export
/// alone rebuilds the page.
#pragma once

#include <nlohmann/json.hpp>

#include "report/report.hpp"

namespace opspace::grading {

/// Significant digits of a recorded series' values and times: a thousandth of the plot's span.
inline constexpr int kRecordDigits = 4;

/// The test's extra_data: {"problem", "test", "mistake", "interrupted", "grader_fault", "runs": [...]}.
/// "test" is the title (GradedTest::title), not the identity: the class page shows it, and reads it
/// from a results.json of an older grader too, which named a test by its title alone.
nlohmann::ordered_json class_record(const ProblemResult& problem, const TestResult& test);

}  // namespace opspace::grading
