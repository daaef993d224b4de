#include "class_results.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
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

// "0 0.004 ..." (class_record.cpp) as numbers; "nan" and anything unreadable as NaN.
std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    out.push_back(end != word.c_str() && *end == '\0' ? v : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

Series series(const Json& j, const char* t, const char* v) {
  Series s{numbers(string(j, t)), numbers(string(j, v))};
  const std::size_t n = std::min(s.t.size(), s.v.size());
  s.t.resize(n), s.v.resize(n);
  return s;
}

ClassRun run(const Json& j) {
  ClassRun r;
  r.statistic = string(j, "statistic"), r.quantity = string(j, "quantity"), r.unit = string(j, "unit");
  r.judged = string(j, "judged");
  r.unit_scale = number(j, "unit_scale", 1.0), r.bound = number(j, "bound"), r.upper = !j.contains("upper") || flag(j, "upper");
  r.judged_from = number(j, "judged_from", 0.0), r.yours = number(j, "yours"), r.reference = number(j, "reference");
  r.student = series(j, "t", "v");
  r.reference_series = series(j, "reference_t", "reference_v");
  return r;
}

// results.json's texts are HTML-escaped (student_text.hpp): a tag's text as written.
std::string unescaped(std::string s) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}}) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
  }
  return s;
}

ClassTest test(const Json& j) {
  ClassTest t;
  t.score = number(j, "score", 0.0), t.max_score = number(j, "max_score", 0.0);
  const Json extra = j.value("extra_data", Json::object());
  if (extra.is_object() && extra.contains("problem")) {
    t.problem = string(extra, "problem"), t.name = string(extra, "test"), t.mistake = string(extra, "mistake");
    t.interrupted = flag(extra, "interrupted"), t.grader_fault = flag(extra, "grader_fault");
    if (extra.contains("runs") && extra["runs"].is_array())
      for (const Json& r : extra["runs"]) t.runs.push_back(run(r));
    return t;
  }
  // A results.json written before the test's extra_data: its name and tags say the rest.
  const std::string name = unescaped(string(j, "name"));
  const std::size_t space = name.find(' ');
  t.problem = name.substr(0, space), t.name = space == std::string::npos ? "" : name.substr(space + 1);
  if (j.contains("tags") && j["tags"].is_array())
    for (const Json& tag : j["tags"])
      if (tag.is_string() && tag.get<std::string>().rfind("mistake: ", 0) == 0) t.mistake = unescaped(tag.get<std::string>().substr(9));
  return t;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

ClassStudent read_student(const std::string& name, const std::string& text) {
  ClassStudent s;
  s.name = name;
  const Json j = Json::parse(text, nullptr, false);
  if (!j.is_object()) {
    s.not_graded = "its results.json is not valid JSON";
    return s;
  }
  s.score = number(j, "score", 0.0), s.max_score = number(j, "max_score", 0.0);
  const Json extra = j.value("extra_data", Json::object());
  if (extra.is_object()) {
    s.not_graded = string(extra, "not_graded");
    const Json grader = extra.value("grader", Json::object());
    if (grader.is_object()) s.grader_faults = static_cast<int>(number(grader, "grader_faults", 0.0)), s.unprotected = flag(grader, "unprotected");
  }
  if (j.contains("tests") && j["tests"].is_array())
    for (const Json& t : j["tests"])
      if (t.is_object()) s.tests.push_back(test(t));
  if (s.tests.empty() && s.not_graded.empty()) s.not_graded = "its results.json holds no test";
  return s;
}

std::vector<ClassStudent> read_class(const std::string& folder) {
  std::vector<std::pair<std::string, fs::path>> found;  // name, results.json
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (e.is_directory() && fs::is_regular_file(e.path() / "results.json")) found.emplace_back(name, e.path() / "results.json");
    else if (e.is_regular_file() && e.path().extension() == ".json") found.emplace_back(e.path().stem().string(), e.path());
  }
  if (ec) throw std::runtime_error("cannot read " + folder + ": " + ec.message());
  std::sort(found.begin(), found.end());
  std::vector<ClassStudent> students;
  for (const auto& [name, path] : found) {
    students.push_back(read_student(name, read_text(path)));
    if (path.filename() == "results.json" && fs::is_regular_file(path.parent_path() / "report.txt"))
      students.back().report = name + "/report.txt";
  }
  return students;
}

}  // namespace opspace::grading
