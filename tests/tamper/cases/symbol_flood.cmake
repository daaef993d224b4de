# The reference 1a, with inline assembly that refers to 2000 undefined names of 40000 characters
# each (issue 47): nm's list of the names the file refers to, 80 MB, exceeds the 64 MiB the
# grader reads. The submission exceeds a bound: problem 1a earns nothing, the report names the
# file and the sizes, and no grader fault is recorded, which would buy it a second grading. The
# grader before said "the grader could not list the functions exercises/p1a.cpp refers to" and
# counted it as its own fault.
set(TARGET p1a.cpp)
string(REPEAT "x" 40000 long)
set(FROM "#include <problems/1a/contract.hpp>\n")
set(TO "${FROM}
asm(\".macro opspace_flood_ref\\n.quad opspace_flood_${long}_\\\\@\\n.endm\\n\"
    \".pushsection .data.opspace_flood,\\\"aw\\\"\\n.rept 2000\\nopspace_flood_ref\\n.endr\\n.popsection\\n\");
")
