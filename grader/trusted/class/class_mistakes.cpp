#include "class/class_mistakes.hpp"

#include <algorithm>
#include <utility>

namespace opspace::grading {

std::string test_key(const ClassTest& t) { return t.problem + " " + t.name; }

std::vector<MistakeRow> ranked_mistakes(const std::vector<ClassStudent>& students) {
  std::map<std::pair<std::string, std::string>, MistakeRow> rows;
  for (std::size_t i = 0; i < students.size(); ++i)
    for (const ClassTest& t : students[i].tests) {
      if (t.mistake.empty() || t.passed()) continue;
      MistakeRow& row = rows[{t.problem, t.mistake}];
      row.problem = t.problem, row.mistake = t.mistake;
      if (row.students.empty() || row.students.back() != i) row.students.push_back(i);
      ++row.tests[test_key(t)];
    }
  std::vector<MistakeRow> out;
  for (auto& [key, row] : rows) out.push_back(std::move(row));
  std::stable_sort(out.begin(), out.end(), [](const MistakeRow& a, const MistakeRow& b) { return a.students.size() > b.students.size(); });
  return out;
}

}  // namespace opspace::grading
