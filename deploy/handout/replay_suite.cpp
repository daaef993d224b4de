// The handout's graded suite: the real suite's tests (names, points, hints), each replaying the
// calls it made to the reference solutions, recorded by the instructor's hw2-record
// (grader/suite/visible/suite.txt): your function gets the same arguments and must give the
// same answer. Numbers, not code: this suite holds no reference implementation. The course's
// autograder grades with fresh random inputs and runs the simulations with your controller.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "run/functions.hpp"
#include "protocol/codec.hpp"
#include "protocol/protocol.hpp"
#include "recorded.hpp"
#include "judge/graded_suite.hpp"

namespace opspace::grading {

namespace {

using protocol::Function;
using recorded::Bytes;

// |computed - expected| <= kTol * max(1, |expected|), entry by entry: round-off between two
// correct ways of computing a formula is ~1e-12 relative; a wrong formula is off by far more.
constexpr double kTol = 1e-7;

// --- every value as a list of numbers, for comparing and printing ---------------------------
void flatten(double v, std::vector<double>& out) { out.push_back(v); }
void flatten(int v, std::vector<double>& out) { out.push_back(v); }
void flatten(bool v, std::vector<double>& out) { out.push_back(v ? 1.0 : 0.0); }
template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
void flatten(E v, std::vector<double>& out) {
  out.push_back(static_cast<int>(v));
}
template <int R, int C, int O>
void flatten(const Eigen::Matrix<double, R, C, O, R, C>& m, std::vector<double>& out) {
  for (int j = 0; j < C; ++j)
    for (int i = 0; i < R; ++i) out.push_back(m(i, j));
}
template <class T, std::size_t N>
void flatten(const std::array<T, N>& a, std::vector<double>& out) {
  for (const T& x : a) flatten(x, out);
}
template <class S, class = decltype(fields(std::declval<S&>(), protocol::AnyField{}, static_cast<S*>(nullptr)))>
void flatten(const S& s, std::vector<double>& out) {
  fields(s, [&out](const auto& x) { flatten(x, out); }, static_cast<S*>(nullptr));
}

std::string text(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(6);
  out << "[";
  const std::size_t shown = std::min<std::size_t>(values.size(), 12);
  for (std::size_t i = 0; i < shown; ++i) out << (i ? ", " : "") << values[i];
  if (shown < values.size()) out << ", ... (" << values.size() << " numbers)";
  return out.str() + "]";
}

template <class T>
std::vector<double> numbers(const T& value) {
  std::vector<double> out;
  flatten(value, out);
  return out;
}

// Compares an answer with the recorded one. Directions are compared as subspaces (the
// projector U U^T of their first `count` columns): any orthonormal basis, any sign, is right.
template <class T>
std::string difference(const T& expected, const T& computed) {
  const std::vector<double> e = numbers(expected), c = numbers(computed);
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (!(std::abs(c[i] - e[i]) <= kTol * std::max(1.0, std::abs(e[i]))))
      return "expected " + text(e) + ", computed " + text(c);
  }
  return "";
}
std::string difference(const hw2::p4::Directions& expected, const hw2::p4::Directions& computed) {
  if (computed.count != expected.count)
    return "expected " + std::to_string(expected.count) + " directions, computed " + std::to_string(computed.count);
  if (computed.count < 0 || computed.count > 3) return "a count outside 0..3";
  const Eigen::Matrix3d E = expected.u.leftCols(expected.count) * expected.u.leftCols(expected.count).transpose();
  const Eigen::Matrix3d C = computed.u.leftCols(computed.count) * computed.u.leftCols(computed.count).transpose();
  if ((C - E).cwiseAbs().maxCoeff() <= 1e-6) return "";
  return "they span another subspace: expected the span of " + text(numbers(Eigen::Matrix3d(expected.u))) +
         " (first " + std::to_string(expected.count) + " columns), computed " + text(numbers(Eigen::Matrix3d(computed.u)));
}

// Decodes the recorded arguments, calls `slot` (your function, in its runner) and compares the
// answer with the recorded one. Returns "" when they agree.
template <class R, class... A>
std::string replay(const std::function<R(A...)>& slot, const recorded::Call& call) {
  std::tuple<std::decay_t<A>...> args;
  protocol::Reader in(call.arguments.data(), call.arguments.size());
  std::apply([&in](auto&... a) { (protocol::get(in, a), ...); }, args);
  in.finish();
  R expected{};
  protocol::Reader answer(call.answer.data(), call.answer.size());
  protocol::get(answer, expected);
  answer.finish();
  const R computed = std::apply(slot, args);
  std::string out = difference(expected, computed);
  if (out.empty()) return out;
  std::vector<double> inputs;
  std::apply([&inputs](const auto&... a) { (flatten(a, inputs), ...); }, args);
  if (!inputs.empty() && inputs.size() <= 12) out = "for the arguments " + text(inputs) + ": " + out;
  return out;
}

std::string replay(const Hw2Api& api, const recorded::Call& call, std::string& name) {
  const auto function = static_cast<Function>(call.function);
  std::string out;
  bool known = false;
  for_each_function(api, [&](Function f, const auto& slot) {
    if (f != function) return;
    known = true;
    name = function_name(f);
    out = replay(slot, call);
  });
  if (!known) throw std::runtime_error("the visible suite names an unknown function");
  return out;
}

// The recorded suite, read once; `error` says why it could not be read.
const std::vector<recorded::Problem>& recorded_suite(std::string& error) {
  static std::string read_error;
  static const std::vector<recorded::Problem> suite = [] {
    try {
      return recorded::read(OPSPACE_VISIBLE_SUITE);
    } catch (const std::exception& e) {
      read_error = e.what();
      return std::vector<recorded::Problem>{};
    }
  }();
  error = read_error;
  return suite;
}

Problem problem(const std::string& key) {
  std::string error;
  const std::vector<recorded::Problem>& suite = recorded_suite(error);
  if (!error.empty()) {
    // A report that says what is wrong, rather than a grader that stops.
    const std::string finding = "the visible suite could not be read: " + error;
    const auto fails = [finding](const Hw2Api&, Check& check) { check.that(false, finding); };
    return {key, "problem " + key, {{"visible_suite", "the visible suite is there", 1.0, "", fails}}};
  }
  for (const recorded::Problem& r : suite) {
    if (r.key != key) continue;
    Problem p{r.key, r.title + " (visible suite: the reference's answers at recorded inputs)", {}};
    for (const recorded::Test& t : r.tests) {
      GradedTest test{t.id, t.title, t.points, t.hint, {}};
      test.body = [&t](const Hw2Api& api, Check& check) {
        for (std::size_t i = 0; i < t.calls.size(); ++i) {
          std::string name;
          const std::string wrong = replay(api, t.calls[i], name);
          if (!wrong.empty()) {
            check.that(false, name + ", recorded call " + std::to_string(i + 1) + " of " + std::to_string(t.calls.size()) +
                                  ": " + wrong);
            return;
          }
        }
      };
      p.tests.push_back(std::move(test));
    }
    return p;
  }
  const std::string finding = std::string(OPSPACE_VISIBLE_SUITE) + " has no problem " + key;
  const auto fails = [finding](const Hw2Api&, Check& check) { check.that(false, finding); };
  return {key, "problem " + key, {{"visible_suite", "the visible suite has this problem", 1.0, "", fails}}};
}

}  // namespace

#define OPSPACE_REPLAYED_PROBLEM(key) \
  Problem problem_##key() { return problem(#key); }
OPSPACE_PROBLEM_KEYS(OPSPACE_REPLAYED_PROBLEM)
#undef OPSPACE_REPLAYED_PROBLEM

std::vector<Problem> graded_suite() {
#define OPSPACE_SUITE_PROBLEM(key) problem_##key(),
  return {OPSPACE_PROBLEM_KEYS(OPSPACE_SUITE_PROBLEM)};
#undef OPSPACE_SUITE_PROBLEM
}

}  // namespace opspace::grading
