/// @file problems/1b/tests.hpp
/// The identities of problem 1b's graded tests, each declared once: problems/1b/grade/graded.cpp
/// gives each test its title (what the report and results.json show); the known mistakes
/// (grade/mistakes.cpp), the library's answers (forbidden.hpp) and the handout's recorded suite
/// name a test by its identity, so that a title can be reworded in one place and a misspelt
/// name is a compile error. No secret: the handout's suite holds the titles too.
#pragma once

namespace opspace::grading::test_id::p1b {

inline constexpr char kLawPart1[] = "1b.ii.law.part1";
inline constexpr char kLawWithoutDamping[] = "1b.ii.law.no_damping";
inline constexpr char kLawPart2[] = "1b.iii.law.part2";
inline constexpr char kLawPart3[] = "1b.iv.law.part3";
inline constexpr char kSimPart1[] = "1b.ii.sim.part1";
inline constexpr char kSimPart3[] = "1b.iv.sim.part3";
inline constexpr char kSimDriftRatio[] = "1b.iii.sim.drift_ratio";

}  // namespace opspace::grading::test_id::p1b
