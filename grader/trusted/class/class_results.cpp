#include "class/class_results.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace opspace::grading {

namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

double number(const Json& j, const char* key, double otherwise = std::numeric_limits<double>::quiet_NaN()) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : otherwise;
}

std::string string(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : "";
}

bool flag(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_boolean() && it->get<bool>();
}

// NaN (no number: a bound not set, a gap in a run) or a number the page can draw.
bool drawable(double v) { return std::isnan(v) || std::abs(v) <= kLargestNumber; }

// A refused number as the note shows it ("1e+306").
std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// What the page refused of one results.json: the first few notes, then how many more (a file
// can hold any number of them).
struct Refusals {
  static constexpr std::size_t kShown = 3;
  std::vector<std::string> notes;
  std::size_t more = 0;
  void note(const std::string& what) {
    if (notes.size() < kShown) notes.push_back(what);
    else ++more;
  }
  std::vector<std::string> done() {
    if (more > 0) notes.push_back("and " + std::to_string(more) + " more refused");
    return std::move(notes);
  }
};

// "0 0.004 ..." (class_record.cpp) as numbers; `bad` the first word refused: unreadable,
// infinite, beyond kLargestNumber, or "nan" where no gap may be (`gaps` false: a time).
std::vector<double> numbers(const std::string& text, bool gaps, std::string& bad) {
  std::vector<double> out;
  std::istringstream in(text);
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    const bool read = end != word.c_str() && *end == '\0';
    if (read && (std::isnan(v) ? gaps : std::abs(v) <= kLargestNumber)) {
      out.push_back(v);
    } else {
      // A few characters of the word, the file's: enough to find it.
      if (bad.empty()) bad = "'" + word.substr(0, 24) + (read && !std::isnan(v) ? "' beyond +-" + shown(kLargestNumber) : "' not a number");
      out.push_back(std::numeric_limits<double>::quiet_NaN());
    }
  }
  return out;
}

Series series(const Json& j, const char* t, const char* v, std::string& bad) {
  std::string bad_t, bad_v;
  Series s{numbers(string(j, t), false, bad_t), numbers(string(j, v), true, bad_v)};
  if (bad.empty() && !bad_t.empty()) bad = "a time " + bad_t;
  if (bad.empty() && !bad_v.empty()) bad = "a value " + bad_v;
  const std::size_t n = std::min(s.t.size(), s.v.size());
  s.t.resize(n), s.v.resize(n);
  return s;
}

// The run of `j`; `bad` says what of it the page refuses ("" when nothing).
ClassRun run(const Json& j, std::string& bad) {
  ClassRun r;
  r.statistic = string(j, "statistic"), r.quantity = string(j, "quantity"), r.unit = string(j, "unit");
  r.judged = string(j, "judged");
  r.unit_scale = number(j, "unit_scale", 1.0), r.bound = number(j, "bound"), r.upper = !j.contains("upper") || flag(j, "upper");
  r.judged_from = number(j, "judged_from", 0.0), r.yours = number(j, "yours"), r.reference = number(j, "reference");
  r.student = series(j, "t", "v", bad);
  r.reference_series = series(j, "reference_t", "reference_v", bad);
  if (bad.empty() && !(std::abs(r.unit_scale) >= 1.0 / kLargestUnitScale && std::abs(r.unit_scale) <= kLargestUnitScale))
    bad = "its unit's factor " + shown(r.unit_scale) + " not within a factor " + shown(kLargestUnitScale) + " of 1";
  for (const auto& [what, v] : {std::pair<const char*, double>{"its bound", r.bound}, {"its judged start", r.judged_from},
                                {"its judged value", r.yours}, {"the reference's judged value", r.reference}})
    if (bad.empty() && !drawable(v)) bad = what + (" " + shown(v)) + " beyond +-" + shown(kLargestNumber);
  return r;
}

// j[key] as a score: 0 when absent, and when not a number or beyond kLargestNumber (noted as
// `whose`; a stored result read from YAML can hold .nan).
double score(const Json& j, const char* key, const std::string& whose, Refusals& refused) {
  const double v = number(j, key, 0.0);
  if (!std::isnan(v) && drawable(v)) return v;
  refused.note(whose + (whose.empty() ? "its " : ": its ") + key + " " + shown(v) + " refused (" +
               (std::isnan(v) ? std::string("not a number") : "beyond +-" + shown(kLargestNumber)) + "), counted 0");
  return 0.0;
}

// results.json's texts are HTML-escaped (student_text.hpp): a tag's text as written.
std::string unescaped(std::string s) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}}) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
  }
  return s;
}

ClassTest test(const Json& j, Refusals& refused) {
  ClassTest t;
  const Json extra = j.value("extra_data", Json::object());
  if (extra.is_object() && extra.contains("problem")) {
    t.problem = string(extra, "problem"), t.name = string(extra, "test"), t.mistake = string(extra, "mistake");
    t.interrupted = flag(extra, "interrupted"), t.grader_fault = flag(extra, "grader_fault");
    t.not_built = flag(extra, "not_built");
    t.score = score(j, "score", t.problem + " " + t.name, refused), t.max_score = score(j, "max_score", t.problem + " " + t.name, refused);
    if (extra.contains("runs") && extra["runs"].is_array())
      for (const Json& r : extra["runs"]) {
        std::string bad;
        ClassRun read = run(r, bad);
        if (bad.empty()) t.runs.push_back(std::move(read));
        else refused.note(t.problem + " " + t.name + ": its run of " + read.statistic + " refused (" + bad +
                          "), left out of the plots");
      }
    return t;
  }
  // A results.json written before the test's extra_data: its name and tags say the rest.
  const std::string name = unescaped(string(j, "name"));
  const std::size_t space = name.find(' ');
  t.problem = name.substr(0, space), t.name = space == std::string::npos ? "" : name.substr(space + 1);
  t.score = score(j, "score", name, refused), t.max_score = score(j, "max_score", name, refused);
  if (j.contains("tags") && j["tags"].is_array())
    for (const Json& tag : j["tags"])
      if (tag.is_string() && tag.get<std::string>().rfind("mistake: ", 0) == 0) t.mistake = unescaped(tag.get<std::string>().substr(9));
  return t;
}

// The file's text; throws if it cannot be read or is larger than kLargestResults.
std::string read_text(const fs::path& path) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw std::runtime_error(ec.message());
  if (size > kLargestResults)
    throw std::runtime_error(std::to_string(size >> 20) + " MiB, beyond the " + std::to_string(kLargestResults >> 20) + " MiB read");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (!(in && text << in.rdbuf())) throw std::runtime_error("it cannot be read");
  return text.str();
}

}  // namespace

ClassStudent read_student(const std::string& name, const std::string& text) {
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_object()) return read_student(name, j);
  ClassStudent s;
  s.name = name, s.not_graded = "its results.json is not valid JSON";
  return s;
}

ClassStudent read_student(const std::string& name, const Json& j) {
  ClassStudent s;
  s.name = name;
  if (!j.is_object()) {
    s.not_graded = "its results are not a JSON object";
    return s;
  }
  Refusals refused;
  s.score = score(j, "score", "", refused), s.max_score = score(j, "max_score", "", refused);
  const Json extra = j.value("extra_data", Json::object());
  if (extra.is_object()) {
    s.not_graded = string(extra, "not_graded");
    const Json grader = extra.value("grader", Json::object());
    if (grader.is_object()) {
      // A count of tests and problems: an int, and a million is beyond any suite's.
      const double faults = number(grader, "grader_faults", 0.0);
      if (faults >= 0.0 && faults <= 1e6) s.grader_faults = static_cast<int>(faults);
      else refused.note("its count of the grader's faults " + shown(faults) + " refused (not from 0 to a million)");
      s.unprotected = flag(grader, "unprotected");
    }
    // The files' notes (deploy/results.cmake): names, at most a few dozen of a bounded length.
    const Json files = extra.value("submission", Json::object());
    if (files.is_object())
      for (auto [key, into] : {std::pair<const char*, std::vector<std::string>*>{"missing", &s.missing}, {"misnamed", &s.misnamed},
                               {"refused", &s.notes}})
        if (files.contains(key) && files[key].is_array())
          for (const Json& file : files[key])
            if (file.is_string() && into->size() < 40) into->push_back(unescaped(file.get<std::string>()).substr(0, 200));
  }
  if (j.contains("tests") && j["tests"].is_array())
    for (const Json& t : j["tests"])
      if (t.is_object()) s.tests.push_back(test(t, refused));
  s.refused = refused.done();
  if (s.tests.empty() && s.not_graded.empty()) s.not_graded = "its results.json holds no test";
  return s;
}

namespace {

// Each student's name and results file in `folder` (unsorted); throws if it cannot be read.
std::vector<std::pair<std::string, fs::path>> results_in(const std::string& folder) {
  std::vector<std::pair<std::string, fs::path>> found;  // name, results.json
  std::error_code ec, entry;  // an entry that cannot be told a folder or a file is neither
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (e.is_directory(entry) && fs::exists(e.path() / "results.json", entry)) found.emplace_back(name, e.path() / "results.json");
    else if (e.is_regular_file(entry) && e.path().extension() == ".json") found.emplace_back(e.path().stem().string(), e.path());
  }
  if (ec) throw std::runtime_error("cannot read " + folder + ": " + ec.message());
  return found;
}

}  // namespace

bool holds_results(const std::string& folder) { return !results_in(folder).empty(); }

std::vector<ClassStudent> read_class(const std::string& folder) {
  std::vector<std::pair<std::string, fs::path>> found = results_in(folder);
  std::error_code entry;
  if (found.empty())
    throw std::runtime_error("no results in " + folder + ": no folder in it holds a results.json, and no NAME.json is in it "
                             "(a Gradescope export is graded first: scripts/regrade EXPORT OUT)");
  std::sort(found.begin(), found.end());
  std::vector<ClassStudent> students;
  for (const auto& [name, path] : found) {
    // A file that cannot be read, or is too large to, costs its own row, never the page.
    try {
      students.push_back(read_student(name, read_text(path)));
    } catch (const std::exception& e) {
      students.emplace_back();
      students.back().name = name, students.back().not_graded = std::string("its results.json cannot be read: ") + e.what();
    }
    if (path.filename() == "results.json" && fs::is_regular_file(path.parent_path() / "report.txt", entry))
      students.back().report = name + "/report.txt";
  }
  return students;
}

}  // namespace opspace::grading
