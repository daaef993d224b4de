/// @file problems/3/tests.hpp
/// The identities of problem 3's graded tests, each declared once: problems/3/grade/graded.cpp
/// gives each test its title (what the report and results.json show); the known mistakes
/// (grade/mistakes.cpp), the library's answers (forbidden.hpp) and the handout's recorded suite
/// name a test by its identity, so that a title can be reworded in one place and a misspelt
/// name is a compile error. No secret: the handout's suite holds the titles too.
#pragma once

namespace opspace::grading::test_id::p3 {

inline constexpr char kSelection[] = "3.a.selection";
inline constexpr char kLaw[] = "3.b.law";
inline constexpr char kSimForce[] = "3.c.sim.force";
inline constexpr char kSimFlat[] = "3.c.sim.flat";
inline constexpr char kSimPosition[] = "3.c.sim.position";
inline constexpr char kSimRotation[] = "3.c.sim.rotation";
inline constexpr char kSimContact[] = "3.c.sim.contact";

}  // namespace opspace::grading::test_id::p3
