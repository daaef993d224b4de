/// @file problems.hpp
/// The problems and their student functions, as X-macros: a problem's functions are listed in
/// one table (functions_p1a.hpp ... functions_p4.hpp) and the problems here, once. Everything
/// that names every function is derived from these rows, never written again:
///   - the protocol's codes (protocol.hpp: Function, kFunctions);
///   - the grader's slots (trusted/api.hpp: Hw2Api) and trusted/functions.hpp's
///     for_each_function, problem_of and function_name, which the remote api, the answers'
///     sizes and decoding, the diagnosis, the handout's record and replay and the fuzz target
///     walk;
///   - each runner's dispatch (untrusted/serve.hpp: OPSPACE_RUNNER_DISPATCH);
///   - the functions linked into our own test programs (tests/graded/linked_api.hpp) and the
///     grader's own answers (tests/graded/reference.cpp).
/// A row missing from a table fails to compile where its function is used by name (a graded
/// test, a mistake, the reference); a function missing from a contract, or from the reference,
/// fails to compile in the code derived from its row. A problem's codes must carry its byte:
/// checked at compile time (protocol.hpp).
#pragma once

#include "functions_p1a.hpp"
#include "functions_p1b.hpp"
#include "functions_p2.hpp"
#include "functions_p3.hpp"
#include "functions_p4.hpp"

/// P(arg, problem, Problem, key, byte, FUNCTIONS) for each problem, in the suite's order: the
/// contract's namespace (hw2::problem, and the problem's member of Hw2Api), the name of its
/// slots' struct (ProblemApi), its key (as the report and the command line write it), the high
/// byte of its codes and its table. `arg` is handed to every P unchanged, so that a P can pass
/// it on to FUNCTIONS (as OPSPACE_FUNCTIONS does).
#define OPSPACE_PROBLEMS(P, arg)                      \
  P(arg, p1a, P1a, "1a", 0x1a, OPSPACE_P1A_FUNCTIONS) \
  P(arg, p1b, P1b, "1b", 0x1b, OPSPACE_P1B_FUNCTIONS) \
  P(arg, p2, P2, "2", 0x02, OPSPACE_P2_FUNCTIONS)     \
  P(arg, p3, P3, "3", 0x03, OPSPACE_P3_FUNCTIONS)     \
  P(arg, p4, P4, "4", 0x04, OPSPACE_P4_FUNCTIONS)

/// F(problem, code, Code, name) for every function of every problem, problem by problem.
#define OPSPACE_FUNCTIONS(F) OPSPACE_PROBLEMS(OPSPACE_FUNCTIONS_OF_PROBLEM, F)
#define OPSPACE_FUNCTIONS_OF_PROBLEM(F, problem, Problem, key, byte, FUNCTIONS) FUNCTIONS(F)
