/// @file serve.hpp
/// The untrusted side: a runner is one problem's exercise file plus this loop. It evaluates
/// the student's functions on the arguments the grader sends and returns the raw values; it
/// decides nothing. Everything here runs in the sandbox, as the student's code does.
#pragma once

#include <tuple>
#include <type_traits>

#include "protocol/codec.hpp"
#include "protocol/protocol.hpp"

namespace opspace::runner {

/// Decodes the arguments of `fn` from `in`, calls it, encodes its value into `out`.
template <class R, class... A>
void serve(R (*fn)(A...), protocol::Reader& in, protocol::Writer& out) {
  std::tuple<std::decay_t<A>...> args;
  std::apply([&in](auto&... a) { (protocol::get(in, a), ...); }, args);
  in.finish();
  protocol::put(out, std::apply(fn, args));
}

/// This runner's problem: evaluates `function` (false if it is not one of this problem's).
/// Defined once per problem (problems/1a/serve.cpp, ...), by OPSPACE_RUNNER_DISPATCH.
bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out);

}  // namespace opspace::runner

/// Defines dispatch (inside namespace opspace::runner) for the problem whose table is FUNCTIONS
/// (e.g. OPSPACE_P1A_FUNCTIONS, problems/1a/functions.hpp): one case per row, serving the
/// contract's function of that name. It names only this problem's functions: a runner links
/// one exercise file.
#define OPSPACE_RUNNER_DISPATCH(FUNCTIONS)                                                 \
  bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out) { \
    switch (function) {                                                                    \
      FUNCTIONS(OPSPACE_SERVE_CASE)                                                        \
      default: return false;                                                               \
    }                                                                                      \
  }
#define OPSPACE_SERVE_CASE(problem, code, Code, name) \
  case protocol::Function::Code:                      \
    serve(&hw2::problem::name, in, out);              \
    return true;
