// One problem per child process: a crash, a hang or an exception in student code costs only
// that problem. The child writes one line per finished test on a pipe:
//   <test index> <score> <number of findings>\n  then each finding on its own line
// (newlines inside a finding are replaced by spaces).
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "grader.hpp"

namespace opspace::grading {

namespace {

void write_all(int fd, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = write(fd, data, left);
    if (n <= 0) return;
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

[[noreturn]] void child(const Problem& problem, const Hw2Api& api, int fd) {
  for (std::size_t i = 0; i < problem.tests.size(); ++i) {
    const std::vector<GradedTest> one{problem.tests[i]};
    const TestResult r = run_tests(one, api).front();
    std::ostringstream line;
    line.precision(17);
    line << i << " " << r.score << " " << r.findings.size() << "\n";
    for (const std::string& f : r.findings) line << one_line(f) << "\n";
    write_all(fd, line.str());
  }
  close(fd);
  _exit(0);
}

// Parses the child's lines into `out` (tests not reported keep score 0, no findings).
std::size_t parse(const std::string& text, ProblemResult& out) {
  std::istringstream in(text);
  std::size_t reported = 0, index = 0, count = 0;
  double score = 0.0;
  std::string header;
  while (std::getline(in, header)) {
    std::istringstream h(header);
    if (!(h >> index >> score >> count) || index >= out.results.size()) break;
    TestResult& r = out.results[index];
    r.score = score;
    r.findings.clear();
    std::string finding;
    for (std::size_t k = 0; k < count && std::getline(in, finding); ++k) r.findings.push_back(finding);
    reported = std::max(reported, index + 1);
  }
  return reported;
}

std::string describe_status(int status, bool timed_out, double timeout) {
  char buffer[160];
  if (timed_out) {
    std::snprintf(buffer, sizeof buffer, "did not finish in %g s and was stopped (an endless loop?)", timeout);
  } else if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    std::snprintf(buffer, sizeof buffer, "crashed: %s (signal %d)%s", strsignal(sig), sig,
                  sig == SIGSEGV ? ", e.g. an out-of-range index or a bad pointer" : "");
  } else {
    std::snprintf(buffer, sizeof buffer, "exited with code %d before finishing",
                  WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  return buffer;
}

}  // namespace

ProblemResult grade_isolated(const Problem& problem, const Hw2Api& api, double timeout) {
  ProblemResult out;
  out.problem = &problem;
  for (const GradedTest& t : problem.tests) {
    out.results.push_back(TestResult{&t, 0.0, {}});
    out.max_score += t.points;
  }

  int fds[2];
  if (pipe(fds) != 0) return grade(problem, api);  // no pipe: grade in this process
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return grade(problem, api);
  }
  if (pid == 0) {
    close(fds[0]);
    child(problem, api, fds[1]);
  }
  close(fds[1]);

  // Read until the child closes the pipe or the time is up.
  std::string text;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0) break;
    if (ready == 0) continue;
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);

  const std::size_t reported = parse(text, out);
  const bool clean = !timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!clean || reported < out.results.size()) {
    const std::string what = "problem " + problem.key + " " + describe_status(status, timed_out, timeout);
    out.failure = what;
    for (std::size_t i = reported; i < out.results.size(); ++i) {
      out.results[i].findings = {i == reported ? what + " during this test"
                                               : "not run: " + what + " in an earlier test"};
    }
  }
  for (const TestResult& r : out.results) out.score += r.score;
  return out;
}

}  // namespace opspace::grading
