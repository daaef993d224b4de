// Every known mistake, problem by problem.
#include "mistakes.hpp"

namespace opspace::grading {

std::vector<Mistake> mistakes(const std::string& key) {
  if (key == "1a") return mistakes_1a();
  if (key == "1b") return mistakes_1b();
  if (key == "2") return mistakes_2();
  if (key == "3") return mistakes_3();
  if (key == "4") return mistakes_4();
  return {};
}

std::vector<Mistake> all_mistakes() {
  std::vector<Mistake> all;
  for (const char* key : {"1a", "1b", "2", "3", "4"}) {
    for (Mistake& m : mistakes(key)) all.push_back(std::move(m));
  }
  return all;
}

}  // namespace opspace::grading
