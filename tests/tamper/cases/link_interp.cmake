# Red team, third round (an attack that fails, kept as a case): the runner's view holds the loader
# its ELF names (PT_INTERP, runtime_files.cpp), so an object file that brings its own .interp
# section naming the library's archive would have the grader show that archive to the runner.
# With --gc-sections the linker drops the object's .interp (nothing refers to it); without it, the
# linker's own loader name comes first and the kernel and the grader both read the name up to its
# first NUL. Either way the runner's loader stays the system's and the archive stays unseen.
# The reference p4 answers only if the archive is visible at run time: problem 4 must earn 0.
set(TARGET p4.cpp)
set(FROM "#include <problems/4/contract.hpp>")
set(archives "${REPO}/build/release/lib/libopspace_core.a;${REPO}/build/asan/lib/libopspace_core.a;${REPO}/build/debug/lib/libopspace_core.a")
set(TO "#include <problems/4/contract.hpp>

#include <unistd.h>

")
foreach(archive IN LISTS archives)
  string(APPEND TO "asm(\".pushsection .interp,\\\"a\\\",@progbits\\n.asciz \\\"${archive}\\\"\\n.popsection\");\n")
endforeach()
string(APPEND TO "
namespace {

bool archive_visible() {
")
foreach(archive IN LISTS archives)
  string(APPEND TO "  if (access(\"${archive}\", R_OK) == 0) return true;\n")
endforeach()
string(APPEND TO "  return false;
}

// Before main: a runner that does not see the archive ends here, before its first answer.
struct Gate {
  Gate() {
    if (!archive_visible()) _exit(0);
  }
} gate;

}  // namespace
")
