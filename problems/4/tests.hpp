/// @file problems/4/tests.hpp
/// The identities of problem 4's graded tests, each declared once: problems/4/grade/graded.cpp
/// gives each test its title (what the report and results.json show); the known mistakes
/// (grade/mistakes.cpp), the library's answers (forbidden.hpp) and the handout's recorded suite
/// name a test by its identity, so that a title can be reworded in one place and a misspelt
/// name is a compile error. No secret: the handout's suite holds the titles too.
#pragma once

namespace opspace::grading::test_id::p4 {

inline constexpr char kRank[] = "4.i.rank";
inline constexpr char kDirections[] = "4.ii.directions";
inline constexpr char kDirectionLeft[] = "4.iii.direction_left";
inline constexpr char kStraightUpTypes[] = "4.iv.straight_up_types";
inline constexpr char kTypesElsewhere[] = "4.iv.types_elsewhere";
inline constexpr char kLaw[] = "4.v.law";
inline constexpr char kSimAlongZ0[] = "4.v.sim.along_z0";
inline constexpr char kSimAlongY0[] = "4.v.sim.along_y0";

}  // namespace opspace::grading::test_id::p4
