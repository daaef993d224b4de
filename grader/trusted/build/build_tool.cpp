#include "build/build_tool.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <stdexcept>

#include "sandbox/grading_group.hpp"
#include "sandbox/sandbox.hpp"

namespace opspace::grading {

ToolResult run_tool(const std::vector<std::string>& argv, const std::string& work_dir,
                    const std::vector<std::string>& visible, const BuildSettings& settings, std::size_t max_output) {
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) throw std::runtime_error("the grader could not create a pipe");
  SandboxSpec spec;
  spec.argv = argv;
  spec.env = {"PATH=/usr/bin:/bin", "LANG=C", "LC_ALL=C", "TMPDIR=/tmp"};
  spec.work_dir = work_dir;
  spec.work_dir_writable = true;
  spec.visible = visible;
  spec.account = settings.account;
  spec.isolate = settings.isolate;
  // A compiler on one exercise file: well under 2 GiB and a minute on a laptop; a template
  // explosion in a student's file stops at these, or at the grading's budget where no memory
  // group holds it (grading_group.hpp).
  spec.limits.address_space = address_space_within_budget(4ull << 30);
  spec.limits.cpu_seconds = static_cast<unsigned long long>(settings.timeout);
  spec.limits.file_size = 256ull << 20;
  spec.limits.open_files = 256;
  // RLIMIT_NPROC counts every process of the sandbox's account: with an account of the grading's
  // own, only this grading's (the compiler forks a fixed few: driver, cc1plus, as; collect2, ld;
  // the builds of up to one per core at once). A shared account (--sandbox-user) has no limit
  // here, since a concurrent grading's fork flood would keep the compiler from starting.
  spec.limits.processes = settings.account.own ? 64 : 0;
  const int null_in = open("/dev/null", O_RDONLY | O_CLOEXEC);
  spec.fds = {{0, null_in}, {1, out[1]}, {2, out[1]}};
  Sandboxed program;
  try {
    program = spawn(spec);
  } catch (...) {
    close(out[0]), close(out[1]), close(null_in);
    throw;
  }
  close(out[1]);
  close(null_in);
  ToolResult result;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(settings.timeout));
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      result.timed_out = true;
      break;
    }
    pollfd p{out[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = read(out[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    result.total += static_cast<std::size_t>(n);
    const std::size_t room = max_output - result.output.size();
    result.cut = result.cut || static_cast<std::size_t>(n) > room;
    result.output.append(buffer, std::min<std::size_t>(static_cast<std::size_t>(n), room));
  }
  close(out[0]);
  if (result.timed_out || !wait_until(program, deadline, result.status)) {
    result.timed_out = true;
    result.status = kill_all(program);
  }
  return result;
}

}  // namespace opspace::grading
