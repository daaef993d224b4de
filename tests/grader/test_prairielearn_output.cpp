// PrairieLearn's results.json (grader/trusted/report/prairielearn_output.cpp), read back with
// nlohmann-json: the fields PrairieLearn's external grader reads, the failed runs' plots as
// images, the hidden tests left out, and the 1 MB bound kept whatever the grading produced.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "report/autograder_output.hpp"
#include "report/prairielearn_output.hpp"
#include "report/plot_png.hpp"
#include "report/report_html.hpp"

namespace grading = opspace::grading;

namespace {

// A failed simulated test's figure: a run that leaves the bound, beside the reference's.
grading::RunFigure figure() {
  grading::RunFigure f;
  f.quantity = "tip error |x - x_d|";
  f.unit = "mm";
  f.unit_scale = 1e3;
  f.bound = 5e-3;
  f.judged = "its largest value after 2 s";
  f.judged_from = 2.0;
  f.student = {{0.0, 5.0, 10.0}, {2e-3, 0.3, 0.1769}};
  f.reference = {{0.0, 5.0, 10.0}, {2e-3, 4e-4, 5e-4}};
  return f;
}

// Problem 1b's first test (a formula) passed, its second (simulated, one figure) failed; problem
// 2's only test, simulated, hidden by its name ("in simulation") and failed.
struct Fixture {
  grading::Problem a, b;
  grading::ProblemResult ra, rb;
  Fixture() {
    a.key = "1b";
    a.tests.push_back({"1b.i.formula", "i. the <b>formula</b>", 3.0, "a hint", {}});
    a.tests.push_back({"1b.iv.sim", "iv. the tip holds", 5.0, "hold it", {}, "hw2-p1 3"});
    b.key = "2";
    b.tests.push_back({"2.ii.sim", "ii. in simulation it tracks", 4.0, "track it", {}, "hw2-p2 1"});
    ra.problem = &a;
    ra.results.resize(2);
    ra.results[0].test = &a.tests[0];
    ra.results[0].score = 3.0;
    ra.results[1].test = &a.tests[1];
    ra.results[1].score = 1.0;
    ra.results[1].findings = {"the tip left the bound at 2.1 s", "second finding"};
    ra.results[1].figures = {figure()};
    ra.score = 4.0;
    ra.max_score = 8.0;
    rb.problem = &b;
    rb.results.resize(1);
    rb.results[0].test = &b.tests[0];
    rb.results[0].findings = {"the secret finding of a hidden test"};
    rb.results[0].figures = {figure()};
    rb.max_score = 4.0;
  }
};

nlohmann::json written(const std::vector<grading::ProblemResult>& problems, const grading::PrairieLearnSettings& s,
                       std::size_t* size = nullptr) {
  std::ostringstream out;
  grading::write_prairielearn(out, problems, 1.5, s);
  if (size != nullptr) *size = out.str().size();
  return nlohmann::json::parse(out.str());  // throws on invalid JSON
}

}  // namespace

TEST_CASE("PrairieLearn's results.json: score in [0, 1], each test's fields, the failed run's plot as an image") {
  Fixture f;
  const nlohmann::json json = written({f.ra, f.rb}, {{}, 42});
  CHECK(json.at("gradable") == true);
  // 4 points of 12 (8 of 1b, 4 of 2): a fraction, as PrairieLearn takes it.
  CHECK(json.at("score").get<double>() == doctest::Approx(4.0 / 12.0));
  CHECK(json.at("message").get<std::string>().find("Problem 1b: 4 / 8") != std::string::npos);
  const nlohmann::json& tests = json.at("tests");
  REQUIRE(tests.size() == 3);
  for (const auto& t : tests) {
    for (const char* field : {"name", "description", "points", "max_points", "message", "output"})
      CHECK_MESSAGE(t.contains(field), field);
  }
  // Texts as the student wrote them: PrairieLearn shows them escaped itself.
  CHECK(tests[0].at("name") == "1b i. the <b>formula</b>");
  CHECK(tests[0].at("points") == 3);
  CHECK(tests[0].at("max_points") == 3);
  CHECK_FALSE(tests[0].contains("images"));  // a passed test: no picture
  CHECK(tests[1].at("points") == 1);
  CHECK(tests[1].at("max_points") == 5);
  CHECK(tests[1].at("message") == "the tip left the bound at 2.1 s");
  const std::string output = tests[1].at("output");
  CHECK(output.find("- second finding\n") != std::string::npos);
  CHECK(output.find("hint: hold it") != std::string::npos);
  CHECK(output.find("--seed 42") != std::string::npos);  // the replay of this run
  // Its one figure, as the PNG the Gradescope writer draws, with its caption as label.
  const nlohmann::json& images = tests[1].at("images");
  REQUIRE(images.size() == 1);
  CHECK(images[0].at("label") == grading::figure_caption(figure()));
  CHECK(images[0].at("url") == "data:image/png;base64," + grading::base64(grading::png_plot(figure())));
}

TEST_CASE("PrairieLearn's results.json leaves the hidden tests out and counts them in the score alone") {
  Fixture f;
  const nlohmann::json json = written({f.ra, f.rb}, {{"in simulation"}, 42});
  CHECK(json.at("score").get<double>() == doctest::Approx(4.0 / 12.0));  // the grade: every test
  const nlohmann::json& tests = json.at("tests");
  REQUIRE(tests.size() == 2);
  const std::string all = json.dump();
  CHECK(all.find("in simulation") == std::string::npos);
  CHECK(all.find("secret finding") == std::string::npos);
  // The student is told that a test of 4 points is not shown, never what it earned.
  CHECK(json.at("message").get<std::string>().find("Problem 2: 0 / 0 in the tests shown (1 hidden test of 4 points") !=
        std::string::npos);
}

TEST_CASE("PrairieLearn's results.json stays under 1 MB: pictures dropped last first, then texts cut, with a note") {
  Fixture f;
  const std::size_t picture = grading::base64(grading::png_plot(figure())).size();
  // Enough failed tests, one picture each, for their pictures alone to pass the bound by two.
  const std::size_t many = grading::kPrairieLearnLimit / picture + 2;
  grading::Problem p;
  p.key = "3";
  for (std::size_t i = 0; i < many; ++i) p.tests.push_back({"3.sim", "run " + std::to_string(i), 1.0, "h", {}, "hw2-p3 1"});
  grading::ProblemResult r;
  r.problem = &p;
  r.max_score = static_cast<double>(many);
  for (const grading::GradedTest& t : p.tests) {
    grading::TestResult tr;
    tr.test = &t;
    tr.findings = {"left the bound"};
    tr.figures = {figure()};
    r.results.push_back(tr);
  }
  std::size_t size = 0;
  nlohmann::json json = written({r}, {{}, 1}, &size);
  CHECK(size <= grading::kPrairieLearnLimit);
  CHECK(json.at("tests").front().contains("images"));  // the first tests keep theirs
  CHECK_FALSE(json.at("tests").back().contains("images"));
  CHECK(json.at("message").get<std::string>().find("picture(s) left out") != std::string::npos);

  // Texts alone over the bound: 30 tests of 64 KiB findings each (about 2 MB) are cut.
  for (grading::TestResult& tr : r.results) {
    tr.figures.clear();
    tr.findings = {std::string(64 * 1024, 'x')};
  }
  r.results.resize(30);
  json = written({r}, {{}, 1}, &size);
  CHECK(size <= grading::kPrairieLearnLimit);
  CHECK(json.at("tests").size() == 30);  // every test stays, its points with it
  CHECK(json.at("message").get<std::string>().find("cut") != std::string::npos);
}
