/// @file oracles.hpp
/// The grader's own answers, the ones its tests compare with: the problem set's laws written
/// out from the library's quantities (p1b.cpp ... p4.cpp), and the whole set gathered as a
/// Hw2Api (reference.cpp). The catalogue of mistakes (mistakes.hpp) replays a student's inputs
/// through this api with one mistake made, to name the mistake a student made.
#pragma once

#include "api.hpp"

namespace opspace::grading::oracle {

/// Problem 1b: the torque of `part` (problems/1b/graded.cpp).
hw2::p1b::Vector6d law_1b(hw2::p1b::Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& goal);
/// Problem 2(c): the tracking law (p2.cpp).
hw2::p2::Vector7d law_2(const hw2::p2::State& s, const hw2::p2::Goal& goal);
/// Problem 3(a): Omega and Omega-bar (p3.cpp).
hw2::p3::Matrix6d omega();
hw2::p3::Matrix6d omega_bar();
/// Problem 3(b): the unified motion and force law (p3.cpp).
hw2::p3::Vector7d law_3(const hw2::p3::State& s, const hw2::p3::Goal& goal);
/// Problem 4(v): the law with each target's potential (p4.cpp).
Eigen::Vector3d law_4(hw2::p4::Target target, const hw2::p4::State& s, const hw2::p4::Goal& goal);

/// Every function of the problem set, answered by the grader's oracles. Identity 2.
Hw2Api reference_api();

}  // namespace opspace::grading::oracle
