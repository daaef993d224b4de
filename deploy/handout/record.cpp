// hw2-record: writes the handout's visible suite (recorded.hpp). It runs every graded test of
// the real suite, in process, on the reference solutions, and records each call the test made:
// the arguments and the reference's answer. A test that calls a function many times (a
// simulation: one call per control tick) keeps kMaxCalls of them, evenly spread over the run.
// Built only in the instructor's repository (it links solutions/); scripts/handout runs it.
//
//   hw2-record OUT.txt       the suite's fixed inputs (run seed 0): the same file every time
#include <cstdio>
#include <fstream>
#include <iostream>

#include "run/functions.hpp"
#include "linked_api.hpp"
#include "protocol/codec.hpp"
#include "protocol/protocol.hpp"
#include "recorded.hpp"
#include "judge/graded_suite.hpp"

namespace {

using namespace opspace;
using protocol::Function;

constexpr std::size_t kMaxCalls = 24;

std::vector<recorded::Call>* current = nullptr;  // the calls of the test being run

// slot = the reference function, recording its arguments and answer.
template <class R, class... A>
void record(std::function<R(A...)>& slot, Function function) {
  slot = [reference = slot, function](A... args) -> R {
    protocol::Writer in;
    (protocol::put(in, args), ...);
    R answer = reference(args...);
    protocol::Writer out;
    protocol::put(out, answer);
    if (current) current->push_back({static_cast<std::uint32_t>(function), in.bytes(), out.bytes()});
    return answer;
  };
}

grading::Hw2Api recording_api() {
  grading::Hw2Api api = grading::linked_api();
  grading::for_each_function(api, [](Function function, auto& slot) { record(slot, function); });
  return api;
}

// At most kMaxCalls calls, the first and the last among them, evenly spread.
std::vector<recorded::Call> spread(std::vector<recorded::Call> calls) {
  if (calls.size() <= kMaxCalls) return calls;
  std::vector<recorded::Call> out;
  for (std::size_t i = 0; i < kMaxCalls; ++i) out.push_back(calls[i * (calls.size() - 1) / (kMaxCalls - 1)]);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: hw2-record OUT.txt\n";
    return 2;
  }
  grading::set_run_seed(0);
  grading::Hw2Api api = recording_api();
  std::vector<recorded::Problem> problems;
  bool full = true;
  for (const grading::Problem& problem : grading::graded_suite()) {
    recorded::Problem p{problem.key, problem.title, {}};
    for (const grading::GradedTest& test : problem.tests) {
      std::vector<recorded::Call> calls;
      current = &calls;
      ++api.identity;  // no simulated run is shared between tests: each test records its own calls
      const std::vector<grading::TestResult> result = grading::run_tests({test}, api);
      current = nullptr;
      if (result.at(0).score != test.points) {
        std::cerr << "hw2-record: the reference earns " << result[0].score << " of " << test.points << " in '"
                  << problem.key << " " << test.title << "'\n";
        full = false;
      }
      if (test.id.empty() || test.id.find_first_of(" \n") != std::string::npos) {
        std::cerr << "hw2-record: '" << problem.key << " " << test.title << "' has no identity of one word\n";
        full = false;
      }
      if (calls.empty()) {
        std::cerr << "hw2-record: '" << problem.key << " " << test.title << "' called nothing\n";
        full = false;
      }
      p.tests.push_back({test.id, test.title, test.hint, test.points, spread(std::move(calls))});
    }
    std::cerr << "problem " << problem.key << ": " << p.tests.size() << " tests recorded\n";
    problems.push_back(std::move(p));
  }
  if (!full) return 1;
  const std::string path = argv[1];
  {
    std::ofstream out(path + ".tmp");
    recorded::write(out, problems);
    if (!out) {
      std::cerr << "hw2-record: cannot write " << path << "\n";
      return 1;
    }
  }
  std::rename((path + ".tmp").c_str(), path.c_str());
  std::cerr << "wrote " << path << "\n";
  return 0;
}
