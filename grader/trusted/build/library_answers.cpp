#include "build/library_answers.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

#include "problem_forbidden.hpp"

namespace opspace::grading {

namespace {

bool is_hex(const std::string& word) {
  return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
}

// The length of the operator's name at s[i] ("operator<<", "operator()"), or 0 if none starts
// there. Its '<', '>' and '(' are not template brackets or a parameter list.
std::size_t operator_length(const std::string& s, std::size_t i) {
  static const std::string kOperator = "operator";
  if (s.compare(i, kOperator.size(), kOperator) != 0) return 0;
  if (i > 0 && s[i - 1] != ':' && s[i - 1] != ' ') return 0;
  const std::size_t after = i + kOperator.size();
  if (after < s.size() && (std::isalnum(static_cast<unsigned char>(s[after])) || s[after] == '_')) return 0;
  for (const char* token : {"()", "[]", "<<=", ">>=", "<=>", "->*", "<<", ">>", "<=", ">=", "->", "<", ">"}) {
    const std::string t = token;
    if (s.compare(after, t.size(), t) == 0) return kOperator.size() + t.size();
  }
  return kOperator.size();
}

}  // namespace

std::vector<Oracle> oracles(const std::string& key) {
  // Every problem: the scenarios compute the reference's quantities and laws. Then the problems
  // whose answers the library holds besides.
  std::vector<Oracle> out = {{"opspace::scenarios::", "the scenarios' own trajectories and control laws", {}}};
  // Generated from problems.txt: each problem folder's forbidden.hpp, where it has one.
#define OPSPACE_ORACLES_ENTRY(key, problem) {key, forbidden::problem},
  static const std::map<std::string, std::vector<Oracle> (*)()> kProblemOracles = {OPSPACE_PROBLEM_FORBIDDEN(OPSPACE_ORACLES_ENTRY)};
#undef OPSPACE_ORACLES_ENTRY
  if (const auto found = kProblemOracles.find(key); found != kProblemOracles.end()) {
    for (Oracle& o : found->second()) out.push_back(std::move(o));
  }
  return out;
}

std::string owner_name(const std::string& s) {
  static const std::string kAnonymous = "(anonymous namespace)";
  // The text outside template brackets, up to the parameter list.
  std::string kept;
  int depth = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (depth == 0) {
      if (const std::size_t n = operator_length(s, i)) {
        kept += s.substr(i, n);
        i += n - 1;
        continue;
      }
      if (s.compare(i, kAnonymous.size(), kAnonymous) == 0) {
        kept += "{anonymous}";
        i += kAnonymous.size() - 1;
        continue;
      }
    }
    const char c = s[i];
    if (c == '<') ++depth;
    else if (c == '>') depth = std::max(0, depth - 1);
    else if (depth == 0 && c == '(') break;
    else if (depth == 0) kept += c;
  }
  // The last word: a return type and "vtable for ", "guard variable for " come before it.
  while (!kept.empty() && kept.back() == ' ') kept.pop_back();
  const std::size_t space = kept.rfind(' ');
  return space == std::string::npos ? kept : kept.substr(space + 1);
}

std::vector<std::string> symbol_names(const std::string& nm_output) {
  // POSIX format: "NAME TYPE [VALUE [SIZE]]", where a demangled NAME may hold spaces.
  std::vector<std::string> out;
  std::istringstream in(nm_output);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> words;
    std::istringstream split(line);
    for (std::string w; split >> w;) words.push_back(w);
    const std::size_t n = words.size();
    std::size_t fields = 0;  // TYPE and what follows it
    if (n >= 4 && words[n - 3].size() == 1 && is_hex(words[n - 2]) && is_hex(words[n - 1])) fields = 3;
    else if (n >= 3 && words[n - 2].size() == 1 && is_hex(words[n - 1])) fields = 2;
    else if (n >= 2 && words[n - 1].size() == 1) fields = 1;
    if (fields == 0) continue;
    std::string name;
    for (std::size_t k = 0; k + fields < n; ++k) name += (k ? " " : "") + words[k];
    out.push_back(name);
  }
  return out;
}

bool belongs_to(const std::string& owner, const Oracle& oracle) {
  const std::string& name = oracle.name;
  if (name.size() >= 2 && name.compare(name.size() - 2, 2, "::") == 0) return owner.rfind(name, 0) == 0;
  return owner == name || owner.rfind(name + "::", 0) == 0;
}

std::vector<std::string> answers_among(const std::string& key, const std::vector<std::string>& symbols) {
  const std::vector<Oracle> forbidden = oracles(key);
  std::vector<std::string> out;
  for (const std::string& symbol : symbols) {
    const std::string owner = owner_name(symbol);
    const bool answer = std::any_of(forbidden.begin(), forbidden.end(), [&](const Oracle& o) { return belongs_to(owner, o); });
    if (answer && std::find(out.begin(), out.end(), owner) == out.end()) out.push_back(owner);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace opspace::grading
