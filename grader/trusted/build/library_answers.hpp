/// @file library_answers.hpp
/// The library's own answers: functions of libopspace that compute what a problem asks the
/// student to write. What decides is the linked runner, not what the student's file asks for:
/// the runner is linked with --gc-sections from a library compiled one section per function,
/// so it holds the code of exactly the library functions it can reach, by whatever route (a
/// call, a weak or aliased declaration, a mangled name in inline assembly, an allowed helper, a
/// template instance). The grader lists the runner's symbols (nm, in the sandbox) and every
/// answer among them costs the tests it answers (docs/grader.md, "The library's own answers").
/// So does every answer the student's object file refers to, of any kind (a call, a weak or
/// aliased declaration, inline assembly): the report names it even when it was not linked in.
#pragma once

#include <string>
#include <vector>

namespace opspace::grading {

/// A library answer the student must not use in one problem.
struct Oracle {
  /// A function's qualified name ("opspace::pseudo_inverse": its overloads, template
  /// instances, clones and local entities), or a namespace ending in "::" ("opspace::pp::").
  std::string name;
  std::string what;                ///< what it computes, for the report
  std::vector<std::string> tests;  ///< identities of the tests it answers (GradedTest::id; empty: all of the problem's)
};

/// The answers problem `key` forbids (docs/grader.md lists them for students).
std::vector<Oracle> oracles(const std::string& key);

/// The qualified name of the function, variable or class a demangled symbol belongs to:
/// "opspace::pseudo_inverse" for "Eigen::Matrix<double, -1, -1, 0, -1, -1>
/// opspace::pseudo_inverse(Eigen::Ref<...> const&, double) [clone .cold]", for a lambda or a
/// static variable inside it and for "opspace::f<double>(...)"; "opspace::scenarios::Watchdog"
/// for "vtable for opspace::scenarios::Watchdog". Template arguments are left out.
std::string owner_name(const std::string& demangled);

/// The demangled names of the symbols `nm -C -P` lists (of any type: defined, undefined, weak).
std::vector<std::string> symbol_names(const std::string& nm_output);

/// Whether `owner` (an owner_name) is the oracle's function or in its namespace.
bool belongs_to(const std::string& owner, const Oracle& oracle);

/// The owner names among `symbols` that belong to one of problem `key`'s oracles, each once.
std::vector<std::string> answers_among(const std::string& key, const std::vector<std::string>& symbols);

}  // namespace opspace::grading
