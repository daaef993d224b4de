/// @file opspace/hw2/p5.hpp
/// (problems/5/contract.hpp, which the build copies where it is included: <opspace/hw2/p5.hpp>)
/// Problem 5, the layout's proof (docs/architecture.md): the task inertia of a planar 2R arm's
/// tip. Declared here, written by the student in exercises/p5.cpp, by the instructor in
/// solutions/p5.cpp.
#pragma once

#include <Eigen/Dense>  // everything a student may need: inverse(), solvers, decompositions

namespace opspace::hw2::p5 {

/// The task inertia Lambda = (J A^-1 J^T)^-1 of the tip, for the tip's Jacobian J (2x2, full
/// rank) and the joint-space mass matrix A (symmetric positive definite).
Eigen::Matrix2d task_inertia(const Eigen::Matrix2d& J, const Eigen::Matrix2d& A);

}  // namespace opspace::hw2::p5
