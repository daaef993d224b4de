#include "judge/reference_store.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "common/sha256.hpp"

namespace opspace::grading {

namespace {

// Problems graded at once (grade_problems.cpp) share the kept series and the store: every look-up and
// insertion holds this lock; a run being made does not, so two problems' runs overlap.
std::mutex& kept_lock() {
  static std::mutex lock;
  return lock;
}

std::map<std::string, Series>& kept() {
  static std::map<std::string, Series> series;
  return series;
}

std::string& store_folder() {
  static std::string folder;
  return folder;
}

bool& making() {  // set_reference_store() was called: the figures of failed tests get the reference
  static bool on = false;
  return on;
}

std::string store_file(const std::string& key) { return store_folder() + "/" + Sha256().add(key).hex() + ".txt"; }

// A stored series: one "t v" line per point, each number in full (%.17g reads back exactly).
bool read_series(const std::string& path, Series& out) {
  std::ifstream in(path);
  if (!in) return false;
  Series s;
  std::string line;
  while (std::getline(in, line)) {
    char* end = nullptr;
    const double t = std::strtod(line.c_str(), &end);
    char* rest = nullptr;
    const double v = std::strtod(end, &rest);
    if (end == line.c_str() || rest == end) return false;  // not two numbers: ignore the file
    s.t.push_back(t);
    s.v.push_back(v);
  }
  out = std::move(s);
  return !out.t.empty();
}

// Written through a file of this process's own and a rename: gradings running at once each
// write whole files, and a reader sees one or none.
void write_series(const std::string& path, const Series& s) {
  const std::string temporary = path + ".tmp" + std::to_string(getpid());
  {
    std::ofstream out(temporary);
    char line[64];
    for (std::size_t k = 0; k < s.t.size(); ++k) {
      std::snprintf(line, sizeof line, "%.17g %.17g\n", s.t[k], s.v[k]);
      out << line;
    }
    if (!out) return;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) std::filesystem::remove(temporary, ec);
}

// The series `key` from this process or the store; null if neither has it (call with the lock
// held: a std::map's elements stay where they are as others are added).
const Series* known(const std::string& key) {
  auto it = kept().find(key);
  if (it != kept().end()) return &it->second;
  Series s;
  if (store_folder().empty() || !read_series(store_file(key), s)) return nullptr;
  return &kept().emplace(key, std::move(s)).first->second;
}

}  // namespace

void set_reference_store(const std::string& folder) {
  making() = true;
  std::error_code ec;
  if (!folder.empty()) std::filesystem::create_directories(folder, ec);
  store_folder() = ec ? "" : folder;
}

const Series& reference_series(const std::string& key, const std::function<Series()>& make) {
  {
    const std::lock_guard<std::mutex> hold(kept_lock());
    if (const Series* s = known(key)) return *s;
  }
  Series run = make();  // unlocked: it may ask for another series (reference_statistic's do)
  const std::lock_guard<std::mutex> hold(kept_lock());
  const auto [it, added] = kept().emplace(key, std::move(run));
  if (added && !store_folder().empty() && !it->second.t.empty()) write_series(store_file(key), it->second);
  return it->second;
}

double reference_statistic(const std::string& key, const std::function<double()>& make) {
  // One point (0, value): the store keeps series, and a statistic is a series of one.
  return reference_series("statistic " + key, [&make] { return Series{{0.0}, {make()}}; }).v.front();
}

void attach_references(std::vector<RunFigure>& figures, bool needed) {
  for (RunFigure& figure : figures) {
    if (figure.reference_key.empty() || !figure.make_reference) continue;
    try {
      if (needed && making())
        figure.reference = reference_series(figure.reference_key, figure.make_reference);
    } catch (const std::exception&) {
      figure.reference = {};  // the grader's own run failed: the figure shows the student's alone
    }
    figure.make_reference = nullptr;  // it may hold references to the test's runs
  }
}

}  // namespace opspace::grading
