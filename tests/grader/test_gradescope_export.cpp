// A Gradescope export's stored results (grader/trusted/class/gradescope_export.hpp): each entry's
// :results: read as JSON, Psych's scalars typed as YAML writes them (a quoted '2' stays a text, a
// plain 2 is a number, .inf and 1e999 are infinite for the page to refuse), and an entry beyond the
// bounds (an alias bomb, a nesting too deep) refused alone, the file and the other entries kept.
// tests/deploy/class_page_stored.sh draws such an export with hw2-class.
#include <doctest/doctest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "class/gradescope_export.hpp"

namespace grading = opspace::grading;

namespace {

// The entries of a metadata file holding `yaml`.
std::vector<grading::StoredSubmission> stored(const std::string& yaml) {
  const std::string path = "/tmp/opspace-test-gradescope-export-" + std::to_string(::getpid()) + ".yml";
  std::ofstream(path) << yaml;
  std::vector<grading::StoredSubmission> out;
  try {
    out = grading::read_stored_results(path);
  } catch (...) {
    std::remove(path.c_str());
    throw;
  }
  std::remove(path.c_str());
  return out;
}

}  // namespace

TEST_CASE("stored results: Psych's scalars keep their YAML types, symbol keys read as plain ones") {
  const auto s = stored(
      "submission_1:\n"
      "  :submitters:\n  - :name: Ann\n"
      "  :score: 4.5\n  :status: processed\n"
      "  :results:\n"
      "    :score: 4.5\n"
      "    tests:\n"
      "    - {name: 2 i. a test, number: '1.1', score: 2, max_score: 1e999, problem: '2', key: 1b, t: 0 1 2,\n"
      "       inf: .inf, nan: .nan, none: ~, yes: true, empty: ''}\n");
  REQUIRE(s.size() == 1);
  CHECK(s[0].score == 4.5);
  CHECK(s[0].status == "processed");
  REQUIRE(s[0].refused.empty());
  const nlohmann::json& r = s[0].results;
  CHECK(r["score"] == 4.5);  // ":score" inside read as "score"
  const nlohmann::json& t = r["tests"][0];
  CHECK(t["number"] == "1.1");  // quoted: a text
  CHECK(t["problem"] == "2");
  CHECK(t["score"] == 2.0);  // plain: a number
  CHECK(t["key"] == "1b");
  CHECK(t["t"] == "0 1 2");
  CHECK(std::isinf(t["max_score"].get<double>()));  // beyond a double: infinite, for the page to refuse
  CHECK(std::isinf(t["inf"].get<double>()));
  CHECK(std::isnan(t["nan"].get<double>()));
  CHECK(t["none"].is_null());
  CHECK(t["yes"] == true);
  CHECK(t["empty"] == "");
}

TEST_CASE("stored results: an alias bomb and a nesting too deep cost their own entry, promptly") {
  std::string bomb = "    a: &a [x, x, x, x, x, x, x, x, x, x]\n";
  for (char level = 'b'; level <= 'i'; ++level)  // 10^9 values once every alias is followed
    bomb += std::string("    ") + level + ": &" + level + " [" + [&] {
      std::string refs;
      for (int k = 0; k < 10; ++k) refs += std::string(k ? ", *" : "*") + static_cast<char>(level - 1);
      return refs;
    }() + "]\n";
  std::string deep(40, '[');  // 40: beyond the 32 levels read
  deep += "x" + std::string(40, ']');
  const auto start = std::chrono::steady_clock::now();
  const auto s = stored("submission_1:\n  :results:\n" + bomb + "submission_2:\n  :results: " + deep +
                        "\nsubmission_3:\n  :results: {score: 1}\n");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(s.size() == 3);
  CHECK(s[0].has_results);
  CHECK(s[0].refused.find("more than 1048576 values") != std::string::npos);
  CHECK(s[0].results.is_null());
  CHECK(s[1].refused.find("nested more than 32 deep") != std::string::npos);
  CHECK(s[2].refused.empty());
  CHECK(s[2].results["score"] == 1.0);
  // The bound is 2^20 values: walked in well under a second here (the sanitizers included); 10 s
  // leaves room for a loaded machine, and 10^9 values would take minutes.
  CHECK(seconds < 10.0);
}
