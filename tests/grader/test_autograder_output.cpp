// results.json (grader/trusted/autograder_output.cpp, written by nlohmann-json), read back
// with nlohmann-json: valid JSON whatever the texts hold, and the numbers as before.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "grader.hpp"

namespace grading = opspace::grading;

TEST_CASE("results.json is valid JSON, keeps every text and writes scores as before") {
  grading::Problem problem;
  problem.key = "1a";
  problem.tests.push_back({"i. the \"first\" test", 3.0, "a hint", {}});
  problem.tests.push_back({"ii. the second test", 3.0, "another hint", {}});
  grading::ProblemResult result;
  result.problem = &problem;
  result.score = 4.5;
  result.max_score = 6.0;
  grading::TestResult passed;
  passed.test = &problem.tests[0];
  passed.score = 3.0;
  grading::TestResult half;
  half.test = &problem.tests[1];
  half.score = 1.5;
  // JSON's escapes (quote, backslash, newline, tab, a C0 byte), and bytes that are not UTF-8,
  // which no path should let through (student_text.hpp escapes a student's) but which must not
  // stop the file from being written.
  const std::string escapes = "a \"quoted\" C:\\path\twith\x01 control";
  half.findings = {escapes, "bad bytes \xff\xfe here"};
  result.results = {passed, half};

  std::ostringstream out;
  grading::write_gradescope(out, {result}, 2.0 / 3.0, {"second"});
  const nlohmann::json json = nlohmann::json::parse(out.str());  // throws on invalid JSON

  // Whole points stay integers: deploy/scores.cmake and tests/tamper/run_case.cmake read them
  // with CMake, whose math() is integer-only.
  CHECK(json.at("score").is_number_float());
  CHECK(json.at("score").get<double>() == 4.5);
  CHECK(json.at("max_score").is_number_integer());
  CHECK(json.at("max_score").get<int>() == 6);
  // 2/3 s with 10 significant digits, as the stream's precision(10) wrote it.
  CHECK(json.at("execution_time").get<double>() == 0.6666666667);
  CHECK(json.at("visibility") == "visible");
  const nlohmann::json& tests = json.at("tests");
  REQUIRE(tests.size() == 2);
  CHECK(tests[0].at("name") == "1a i. the \"first\" test");
  CHECK(tests[0].at("score").is_number_integer());
  CHECK(tests[0].at("status") == "passed");
  CHECK(tests[0].at("visibility") == "visible");
  CHECK(tests[1].at("score").get<double>() == 1.5);
  CHECK(tests[1].at("status") == "failed");
  CHECK(tests[1].at("visibility") == "hidden");
  const std::string output = tests[1].at("output");
  CHECK(output.find("- " + escapes + "\n") != std::string::npos);
  // Each byte that is not UTF-8 is replaced by U+FFFD (EF BF BD).
  CHECK(output.find("bad bytes \xef\xbf\xbd\xef\xbf\xbd here") != std::string::npos);
  CHECK(output.find("hint: another hint") != std::string::npos);
}
