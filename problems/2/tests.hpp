/// @file problems/2/tests.hpp
/// The identities of problem 2's graded tests, each declared once: problems/2/grade/graded.cpp
/// gives each test its title (what the report and results.json show); the known mistakes
/// (grade/mistakes.cpp), the library's answers (forbidden.hpp) and the handout's recorded suite
/// name a test by its identity, so that a title can be reworded in one place and a misspelt
/// name is a compile error. No secret: the handout's suite holds the titles too.
#pragma once

namespace opspace::grading::test_id::p2 {

inline constexpr char kAcceleration[] = "2.a.acceleration";
inline constexpr char kTwistAcceleration[] = "2.b.twist_acceleration";
inline constexpr char kLaw[] = "2.c.law";
inline constexpr char kSimPosition[] = "2.d.sim.position";
inline constexpr char kSimOrientation[] = "2.d.sim.orientation";
inline constexpr char kSimContinuous[] = "2.d.sim.continuous";
inline constexpr char kSimJointLimits[] = "2.d.sim.joint_limits";
inline constexpr char kSimSelfMotion[] = "2.d.sim.self_motion";

}  // namespace opspace::grading::test_id::p2
