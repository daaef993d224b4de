// The grader's reading of a runner's answers (grader/trusted/run/runner_process.hpp): an answer is
// taken from the byte stream, however the runner cut it into writes, and only as
// check_answer allows; garbage, a partial answer and a runner that ends are failures in words
// for the student. The runner here is tests/grader/fake_runner.cpp, which echoes a request's
// arguments as its value (so the value expected is the arguments sent), started without the
// sandbox (isolate off): what is tested is the reading, not the sandbox.
#include <doctest/doctest.h>

#include <chrono>
#include <string>
#include <vector>

#include "run/runner_process.hpp"

namespace grading = opspace::grading;
namespace protocol = opspace::protocol;

namespace {

grading::RunnerConfig fake(const std::string& mode) {
  grading::RunnerConfig config;
  config.binary = OPSPACE_FAKE_RUNNER;
  config.work_dir = "/";
  config.isolate = false;
  config.env = {"OPSPACE_FAKE_RUNNER=" + mode};
  return config;
}

// `size` bytes numbered from `first`: an echo of them is told apart from any other bytes.
std::vector<unsigned char> arguments(std::size_t size, unsigned first) {
  std::vector<unsigned char> bytes(size);
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<unsigned char>(first + i);
  return bytes;
}

// A test of `seconds` of CPU time; the grader waits up to kWaitFactor times that.
void begin(grading::RunnerProcess& runner, double seconds) {
  runner.begin_test(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                           std::chrono::duration<double>(seconds)),
                    seconds);
}

std::string failure_of(grading::RunnerProcess& runner, const std::vector<unsigned char>& args) {
  try {
    runner.call(protocol::Function::kP1aMassMatrix, args, args.size());
  } catch (const grading::RunnerFailure& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("answers written whole are read, one after another, each the request's own") {
  grading::RunnerProcess runner(fake("whole"));
  begin(runner, 10.0);
  // 32 bytes (a 2x2 matrix of doubles, mass_matrix's value), then sizes around the pipe's
  // atomic write (4096) and past one pipe's capacity (64 KiB less the header).
  for (const std::size_t size : {std::size_t{32}, std::size_t{4080}, std::size_t{4081}, std::size_t{protocol::kMaxPayload}}) {
    const std::vector<unsigned char> args = arguments(size, static_cast<unsigned>(size));
    CHECK(runner.call(protocol::Function::kP1aMassMatrix, args, size) == args);
  }
  runner.end_test();
  CHECK(runner.failure().empty());
  CHECK(runner.starts() == 1);
}

TEST_CASE("an answer cut into many writes, a few bytes each, is read whole") {
  grading::RunnerProcess runner(fake("split"));
  begin(runner, 10.0);
  for (unsigned call = 0; call < 3; ++call) {
    const std::vector<unsigned char> args = arguments(32, 7 * call);
    CHECK(runner.call(protocol::Function::kP1aMassMatrix, args, args.size()) == args);
  }
  runner.end_test();
  CHECK(runner.failure().empty());
}

TEST_CASE("bytes written after an answer are the next answer's, and rejected there") {
  // Read with the first answer's payload in one read, the 16 trailing bytes stay ahead of the
  // second answer, as they would in the pipe: the second call reads them as its header.
  grading::RunnerProcess runner(fake("trailing"));
  begin(runner, 10.0);
  const std::vector<unsigned char> args = arguments(32, 1);
  CHECK(runner.call(protocol::Function::kP1aMassMatrix, args, args.size()) == args);
  CHECK(failure_of(runner, args) == "your code wrote something that is not an answer on the grader's channel");
  runner.end_test();
}

TEST_CASE("garbage instead of an answer fails the test, and the next test starts a new runner") {
  grading::RunnerProcess runner(fake("garbage"));
  begin(runner, 10.0);
  CHECK(failure_of(runner, arguments(32, 1)) == "your code wrote something that is not an answer on the grader's channel");
  runner.end_test();
  begin(runner, 10.0);
  CHECK(failure_of(runner, arguments(32, 1)) == "your code wrote something that is not an answer on the grader's channel");
  runner.end_test();
  CHECK(runner.starts() == 2);
}

TEST_CASE("a partial answer, then silence, fails at the deadline") {
  grading::RunnerProcess runner(fake("partial"));
  // 0.1 s of CPU time, waited for up to kWaitFactor (5) times that: 0.5 s.
  begin(runner, 0.1);
  const auto start = std::chrono::steady_clock::now();
  const std::string failure = failure_of(runner, arguments(32, 1));
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(failure.rfind("your code did not answer within 0.5 s of waiting", 0) == 0);
  CHECK(waited >= 0.5);
  runner.end_test();
}

TEST_CASE("a runner that ends without answering is said to have ended") {
  grading::RunnerProcess runner(fake("exit"));
  begin(runner, 10.0);
  CHECK(failure_of(runner, arguments(32, 1)) ==
        "your code ended the program before answering (exit code 0: an exit() call?)");
  runner.end_test();
}
