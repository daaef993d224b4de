# Least privilege at each stage of a runner's build and run (docs/grader.md, "What each stage
# sees"). The reference p4, whose runner answers only if route FAULT reached what its stage must
# not: otherwise it ends before main and problem 4 earns nothing. Before the third round each
# route was open (issue 38): a problem-4 runner started the problem-1b runner lying beside it in
# one run folder (11 points); the compiler saw the library's archive, which .incbin embedded, and
# the runner ran /usr/bin/c++ to link an answer out of it (31 points).
#   other-runner  a runner sees another problem's runner (its folder, the old shared one, /tmp)
#   compiler      a runner sees a compiler, an assembler or a linker
#   exec          a runner starts another program (a shell, /usr/bin/true, the loader itself)
#   archive       a runner sees the library's archive (a build folder, the repository) or the
#                 grader's cache of runners
#   incbin        the compiler sees the library's archive (__has_include finds what .incbin
#                 would embed): in the repository, or staged beside the exercise file
#   process       a runner starts a second process (fork, vfork, clone, clone3), which would
#                 have an address space and its 1 GiB limit of its own
set(TARGET p4.cpp)
set(FROM "#include <problems/4/contract.hpp>")
set(ROUTE "${FAULT}")
string(CONFIGURE [=[#include <problems/4/contract.hpp>

#include <fcntl.h>
#include <glob.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstring>
#include <string>

namespace {

bool any(const char* pattern, const char* except = nullptr) {
  glob_t found{};
  bool hit = false;
  if (glob(pattern, 0, nullptr, &found) == 0)
    for (std::size_t i = 0; i < found.gl_pathc; ++i)
      hit = hit || !except || !std::strstr(found.gl_pathv[i], except);
  globfree(&found);
  return hit;
}

bool runs(const char* program, const char* argument) {
  const pid_t child = fork();
  if (child == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1), dup2(null, 2);
    char* const argv[] = {const_cast<char*>(program), const_cast<char*>(argument), nullptr};
    execv(program, argv);
    _exit(127);
  }
  int status = 1;
  if (child > 0) waitpid(child, &status, 0);
  return child > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// A child of the call that returned `child` ends at once; true if there was one.
bool started(long child) {
  if (child == 0) _exit(0);
  if (child > 0) waitpid(static_cast<pid_t>(child), nullptr, 0);
  return child > 0;
}

bool second_process() {
  struct { std::uint64_t flags, pidfd, child_tid, parent_tid, exit_signal, stack, stack_size, tls; } args{};
  args.exit_signal = SIGCHLD;
  return started(fork()) || started(vfork()) || started(syscall(SYS_clone, static_cast<long>(SIGCHLD), 0L, 0L, 0L, 0L)) ||
         started(syscall(SYS_clone3, &args, sizeof args));
}

bool reached(const std::string& route) {
  if (route == "process") return second_process();
  if (route == "other-runner")
    return any("../*/runner-*", "runner-4") || any("./runner-1*") || any("/tmp/opspace-runners-*/*/runner-*", "runner-4") ||
           any("/tmp/opspace-runners-*/runner-*", "runner-4");
  if (route == "compiler")
    return access("/usr/bin/c++", X_OK) == 0 || access("/usr/bin/g++", X_OK) == 0 || access("/usr/bin/gcc", X_OK) == 0 ||
           access("/usr/bin/as", X_OK) == 0 || access("/usr/bin/ld", X_OK) == 0;
  if (route == "exec")
    return runs("/bin/sh", "-c:") || runs("/usr/bin/true", "") || runs("/lib64/ld-linux-x86-64.so.2", "--version") ||
           runs("/lib/ld-linux-aarch64.so.1", "--version");
  if (route == "archive")
    return any("/tmp/opspace-build-*/*/*/libopspace_core.a") || any("/tmp/opspace-build-*/*/libopspace_core.a") ||
           any("@REPO@/build/*/lib/libopspace_core.a") || any("@REPO@/build/*/grading-cache/runner-*");
  if (route == "incbin") {
#if __has_include("@REPO@/build/release/lib/libopspace_core.a") || __has_include("@REPO@/build/asan/lib/libopspace_core.a")
    return true;
#elif __has_include("../archives/0/libopspace_core.a") || __has_include("../archives/1/libopspace_core.a")
    return true;
#elif __has_include("kit/0/libopspace_core.a") || __has_include("kit/1/libopspace_core.a") || \
    __has_include("kit/2/libopspace_core.a") || __has_include("kit/3/libopspace_core.a") ||   \
    __has_include("kit/4/libopspace_core.a") || __has_include("kit/5/libopspace_core.a") ||   \
    __has_include("kit/6/libopspace_core.a") || __has_include("kit/7/libopspace_core.a")
    return true;
#else
    return false;
#endif
  }
  return false;
}

// Before main: a runner whose route is closed ends here, before its first answer.
struct Gate {
  Gate() {
    if (!reached("@ROUTE@")) _exit(0);
  }
} gate;

}  // namespace
]=] TO @ONLY)
