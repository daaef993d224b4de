#include "report/class_record.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace opspace::grading {

namespace {

using Json = nlohmann::ordered_json;

// v to kRecordDigits significant digits (nlohmann writes the shortest text that reads back);
// null where JSON has no number (NaN, infinity).
Json rounded(double v) {
  if (!std::isfinite(v)) return nullptr;
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", kRecordDigits, v);
  return std::strtod(text, nullptr);
}

// "0 0.004 0.008 ...": a series as one string of numbers (results.json is written indented, one
// array element a line: a string keeps it a line), "nan" where a value is not finite.
std::string values(const std::vector<double>& vs) {
  std::string out;
  char text[32];
  for (const double v : vs) {
    std::snprintf(text, sizeof text, "%.*g", kRecordDigits, v);
    out += (out.empty() ? "" : " ") + std::string(std::isfinite(v) ? text : "nan");
  }
  return out;
}

Json run(const RunFigure& f) {
  return Json{{"statistic", f.draws.empty() ? f.quantity : f.draws},
              {"quantity", f.quantity},
              {"unit", f.unit},
              {"unit_scale", f.unit_scale},
              {"bound", rounded(f.bound)},
              {"upper", f.upper},
              {"judged", f.judged},
              {"judged_from", f.judged_from},
              {"yours", rounded(f.verdict_yours)},
              {"reference", rounded(f.verdict_reference)},
              {"t", values(f.student.t)},
              {"v", values(f.student.v)},
              {"reference_t", values(f.reference.t)},
              {"reference_v", values(f.reference.v)}};
}

}  // namespace

Json class_record(const ProblemResult& problem, const TestResult& test) {
  Json runs = Json::array();
  for (const RunFigure& f : test.figures)
    if (!f.draws.empty() || std::isfinite(f.bound)) runs.push_back(run(f));  // a judged run
  if (runs.empty() && !test.figures.empty()) runs.push_back(run(test.figures.front()));  // what the test reads
  return Json{{"problem", problem.problem->key},
              {"test", test.test->title},
              {"mistake", test.mistake},
              {"interrupted", test.interrupted},
              {"grader_fault", test.grader_fault},
              // Its problem's file did not compile (every test then "interrupted"): the class
              // page tells the two apart.
              {"not_built", !problem.failure.empty() && !problem.grader_fault},
              {"runs", std::move(runs)}};
}

}  // namespace opspace::grading
