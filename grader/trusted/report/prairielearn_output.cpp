// PrairieLearn's results.json (its external grader's format), written by nlohmann-json: the
// Gradescope writer's texts and plots (autograder_output.cpp), in PrairieLearn's fields.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <string>

#include "report/autograder_output.hpp"
#include "report/prairielearn_output.hpp"
#include "report/plot_png.hpp"
#include "report/report_html.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace {

using Json = nlohmann::ordered_json;  // keys in the order written

// Every text is written as it is, never HTML-escaped: PrairieLearn's results panel escapes
// message and output itself (an escaped "<" would show as "&lt;").
std::string dumped(const Json& json) {
  // Bytes that are not UTF-8 are replaced, never thrown on: no text can stop the file.
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// A test's one line: what failed first, or that it passed.
std::string test_message(const TestResult& r) {
  if (r.score >= r.test->points) return "passed";
  if (r.findings.empty()) return "failed";
  // Its first line, at most 200 bytes (output holds the whole): the panel's one-line summary.
  const std::string& first = r.findings.front();
  const std::size_t end = std::min(first.find('\n'), std::size_t{200});
  return end < first.size() ? first.substr(0, end) + " ..." : first;
}

// Points as the Gradescope writer writes them: a whole number without a fraction (a script reads
// them with CMake's integer math: tests/deploy/check_prairielearn.cmake), else 10 digits.
Json points(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  const double rounded = std::strtod(text, nullptr);
  if (std::isfinite(rounded) && rounded == std::floor(rounded) && std::abs(rounded) < 1e15)
    return static_cast<std::int64_t>(rounded);
  return rounded;
}

}  // namespace

void write_prairielearn(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                        const PrairieLearnSettings& settings) {
  double score = 0.0, max_score = 0.0;
  std::ostringstream message;
  Json tests = Json::array();
  for (const ProblemResult& p : problems) {
    score += p.score;
    max_score += p.max_score;
    // The student's line counts the tests shown: a hidden test's points would tell what it gave.
    const ShownScore shown = shown_score(p, settings.hidden);
    message << "Problem " << p.problem->key << ": " << format_points(shown.score) << " / "
            << format_points(shown.max_score);
    if (shown.hidden_tests > 0) {
      message << " in the tests shown (" << shown.hidden_tests << " hidden test" << (shown.hidden_tests == 1 ? "" : "s")
              << " of " << format_points(shown.hidden_points) << " points, not shown, counted in your score)";
    }
    message << "\n";
    if (!p.failure.empty()) {
      const std::size_t end = p.failure.find('\n');
      message << "  " << p.failure.substr(0, end) << "\n";
      if (end != std::string::npos) message << quote_block(p.failure.substr(end + 1), "    ");
    }
    if (!p.warnings.empty()) message << "  compiler warnings:\n" << quote_block(p.warnings, "    ");
    for (const TestResult& r : p.results) {
      if (is_hidden(p, r, settings.hidden)) continue;  // PrairieLearn has no test shown later
      Json test{{"name", p.problem->key + " " + r.test->title},
                {"description", "problem " + p.problem->key + (r.test->replay.empty() ? "" : ", a simulated run")},
                {"points", points(r.score)},
                {"max_points", points(r.test->points)},
                {"message", test_message(r)},
                {"output", feedback_beside_pictures(r, settings.seed)}};
      // A failed simulated test's runs as pictures (PrairieLearn shows images[] below the text).
      if (r.score < r.test->points && !r.not_written && !r.figures.empty()) {
        Json images = Json::array();
        for (const RunFigure& f : r.figures) {
          const std::string png = png_plot(f);  // empty in a grader built without cairo
          if (!png.empty()) images.push_back(Json{{"label", figure_caption(f)}, {"url", "data:image/png;base64," + base64(png)}});
        }
        if (!images.empty()) test["images"] = std::move(images);
      }
      tests.push_back(std::move(test));
    }
  }
  char footer[96];
  std::snprintf(footer, sizeof footer, "Graded in %.1f s (seed %llu).\n", seconds,
                static_cast<unsigned long long>(settings.seed));
  // The grade, hidden tests included: what PrairieLearn's gradebook takes, as a fraction.
  const double fraction = max_score > 0.0 ? std::clamp(score / max_score, 0.0, 1.0) : 0.0;
  Json results{{"gradable", true}, {"score", fraction}, {"message", message.str() + footer}, {"tests", std::move(tests)}};

  // Within PrairieLearn's bound, with room for the note that says what was cut.
  constexpr std::size_t kNoteRoom = 512;
  const std::size_t budget = kPrairieLearnLimit - kNoteRoom;
  std::string text = dumped(results);
  int dropped = 0;
  Json& all = results["tests"];
  // The pictures first, the last test's first: the first failures are the ones to read. As many
  // at a time as the excess needs (each costs at least its URL and label), then written again.
  while (text.size() > budget) {
    std::size_t excess = text.size() - budget;
    bool any = false;
    for (auto t = all.rbegin(); t != all.rend() && excess > 0; ++t) {
      if (!t->contains("images")) continue;
      Json& images = (*t)["images"];
      while (!images.empty() && excess > 0) {
        const Json& last = images.back();
        const std::size_t bytes = last["url"].get<std::string>().size() + last["label"].get<std::string>().size();
        excess -= std::min(excess, bytes);
        images.erase(images.size() - 1);
        ++dropped;
        any = true;
      }
      if (images.empty()) t->erase("images");
    }
    if (!any) break;  // no picture left: the texts are cut below
    text = dumped(results);
  }
  // Then every output cut to a length halved until the file fits (the points stay, whole).
  std::size_t cut_at = 0;
  for (std::size_t cap = 32 * 1024; text.size() > budget && cap >= 256; cap /= 2) {
    for (Json& t : all) {
      std::string o = t["output"].get<std::string>();
      if (o.size() > cap) t["output"] = o.substr(0, cap) + "\n[cut here]\n";
    }
    cut_at = cap;
    text = dumped(results);
  }
  if (dropped > 0 || cut_at > 0) {
    std::string note = "PrairieLearn takes at most 1 MB of results:";
    if (dropped > 0) note += " " + std::to_string(dropped) + " picture(s) left out (the last tests' first)";
    if (cut_at > 0) note += std::string(dropped > 0 ? ";" : "") + " each test's output cut at " + std::to_string(cut_at) + " bytes";
    results["message"] = results["message"].get<std::string>() + note + ".\n";
    text = dumped(results);
  }
  out << text;
}

}  // namespace opspace::grading
