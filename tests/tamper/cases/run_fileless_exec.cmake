# Red team, third round (an attack that fails, kept as a case): a runner may execve() only its
# own program, by the sandbox's own path pointer; a route that needs no file in its view, a copy
# of itself in a memory file (memfd_create) started by execveat(fd, "", AT_EMPTY_PATH) or by
# execve("/proc/self/fd/N"), is refused too (seccomp: execveat never, execve only with that
# pointer). The reference p4 answers only if the copy ran: problem 4 must earn 0.
set(TARGET p4.cpp)
set(FROM "#include <problems/4/contract.hpp>")
set(TO [=[#include <problems/4/contract.hpp>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace {

bool copy_runs() {
  const int memory = memfd_create("copy", 0), self = open("/proc/self/exe", O_RDONLY | O_CLOEXEC);
  if (memory < 0 || self < 0) return false;
  char buffer[65536];
  for (ssize_t n; (n = read(self, buffer, sizeof buffer)) > 0;)
    if (write(memory, buffer, static_cast<std::size_t>(n)) != n) return false;
  const pid_t child = fork();
  if (child == 0) {
    char* const argv[] = {const_cast<char*>("copy"), nullptr};
    char* const env[] = {const_cast<char*>("OPSPACE_COPY=1"), nullptr};
    syscall(SYS_execveat, memory, "", argv, env, AT_EMPTY_PATH);
    char path[64];
    std::snprintf(path, sizeof path, "/proc/self/fd/%d", memory);
    execve(path, argv, env);
    _exit(127);
  }
  int status = 1;
  if (child > 0) waitpid(child, &status, 0);
  return child > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Before main: the copy ends at once with 0; the runner whose copy did not run ends here too.
struct Gate {
  Gate() {
    if (std::getenv("OPSPACE_COPY") || !copy_runs()) _exit(0);
  }
} gate;

}  // namespace
]=])
