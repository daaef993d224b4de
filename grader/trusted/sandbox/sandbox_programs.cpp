// The programs the sandbox started, until they and everything they started are gone. The
// grader is a child subreaper (become_subreaper()): what a program detaches (setsid, a double
// fork) is re-parented to the grader instead of init, so that kill_all() and wait_until() can
// find it among the grader's children that are not live programs, and kill and reap it. Also
// the words for how a program ended (describe_wait_status()).
#include <dirent.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "sandbox/sandbox_plan.hpp"

namespace opspace::grading {

namespace sandbox_internal {

// The grader builds several runners at once (threads): spawn(), the waits and the search for
// orphans share the list of live programs under this lock, so that a program just started by
// one thread is never taken for an orphan by another.
std::mutex& programs_lock() {
  static std::mutex lock;
  return lock;
}

std::set<pid_t>& live_programs() {
  static std::set<pid_t> programs;
  return programs;
}

void forget(pid_t pid) {
  const std::lock_guard<std::mutex> hold(programs_lock());
  live_programs().erase(pid);
}

}  // namespace sandbox_internal

namespace {

using sandbox_internal::forget;
using sandbox_internal::live_programs;
using sandbox_internal::programs_lock;

// The processes whose parent is the grader and which are not its live programs (call with
// the lock held).
std::vector<pid_t> orphans() {
  std::vector<pid_t> out;
  DIR* proc = opendir("/proc");
  if (!proc) return out;
  const pid_t self = getpid();
  while (const dirent* entry = readdir(proc)) {
    const pid_t pid = static_cast<pid_t>(std::atoi(entry->d_name));
    if (pid <= 0 || live_programs().count(pid)) continue;
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/stat", static_cast<int>(pid));
    FILE* file = std::fopen(path, "r");
    if (!file) continue;
    char line[512] = {};
    const bool read = std::fgets(line, sizeof line, file) != nullptr;
    std::fclose(file);
    if (!read) continue;
    // "pid (comm) state ppid ...": comm may hold spaces and parentheses, so read after the last ')'.
    const char* close = std::strrchr(line, ')');
    char state = 0;
    int ppid = 0;
    if (close && std::sscanf(close + 1, " %c %d", &state, &ppid) == 2 && ppid == self) out.push_back(pid);
  }
  closedir(proc);
  return out;
}

// Kills and reaps every process re-parented to the grader that is not a live program of its
// own: what sandboxed programs left behind (detached, double-forked).
void reap_orphans() {
  const std::lock_guard<std::mutex> hold(programs_lock());
  for (int round = 0; round < 1000; ++round) {
    const std::vector<pid_t> stray = orphans();
    for (pid_t pid : stray) kill(pid, SIGKILL);
    for (pid_t pid : stray) waitpid(pid, nullptr, 0);
    if (stray.empty()) return;
  }
}

}  // namespace

void become_subreaper() {
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  signal(SIGPIPE, SIG_IGN);
}

std::string describe_wait_status(int status) {
  char buffer[160];
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    std::snprintf(buffer, sizeof buffer, "crashed: %s (signal %d)%s", strsignal(sig), sig,
                  sig == SIGSEGV ? ", e.g. an out-of-range index or a bad pointer"
                  : sig == SIGXCPU ? ": it used up its CPU time"
                  : sig == SIGXFSZ ? ": it wrote a file larger than allowed"
                                   : "");
  } else if (WIFEXITED(status)) {
    std::snprintf(buffer, sizeof buffer, "exited with code %d", WEXITSTATUS(status));
  } else {
    std::snprintf(buffer, sizeof buffer, "ended with status %d", status);
  }
  return buffer;
}

bool wait_until(const Sandboxed& program, std::chrono::steady_clock::time_point deadline, int& status) {
  auto pause = std::chrono::microseconds(100);
  for (;;) {
    const pid_t done = waitpid(program.pid, &status, WNOHANG);
    if (done == program.pid || (done < 0 && errno == ECHILD)) {
      forget(program.pid);
      reap_orphans();
      return true;
    }
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
}

void kill_live_programs() {
  const std::lock_guard<std::mutex> hold(programs_lock());
  for (const pid_t pid : live_programs()) {
    kill(-pid, SIGKILL);  // it called setsid(): its group is its own
    kill(pid, SIGKILL);
  }
}

int kill_all(const Sandboxed& program) {
  int status = 0;
  bool live = false;
  {
    const std::lock_guard<std::mutex> hold(programs_lock());
    live = live_programs().count(program.pid) > 0;
  }
  if (live) {
    kill(program.pid, SIGKILL);
    while (waitpid(program.pid, &status, 0) < 0 && errno == EINTR) {
    }
    forget(program.pid);
  }
  reap_orphans();
  return status;
}

}  // namespace opspace::grading
