// Every known mistake, problem by problem.
#include "judge/mistakes.hpp"

namespace opspace::grading {

std::vector<Mistake> mistakes(const std::string& key) {
#define OPSPACE_MISTAKES_OF(k) \
  if (key == #k) return mistakes_##k();
  OPSPACE_PROBLEM_KEYS(OPSPACE_MISTAKES_OF)
#undef OPSPACE_MISTAKES_OF
  return {};
}

std::vector<Mistake> all_mistakes() {
  std::vector<Mistake> all;
#define OPSPACE_APPEND_MISTAKES(k) \
  for (Mistake& m : mistakes_##k()) all.push_back(std::move(m));
  OPSPACE_PROBLEM_KEYS(OPSPACE_APPEND_MISTAKES)
#undef OPSPACE_APPEND_MISTAKES
  return all;
}

}  // namespace opspace::grading
