/// @file problems/4/grade/analysis.hpp
/// Problem 4's analysis, questions i-iv (analysis.cpp), and what its graded files share; graded.cpp
/// adds question v's law and runs.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "opspace/model/model.hpp"

#include "judge/grading.hpp"

namespace opspace::grading::p4_graded {

const Model& rrr();                         ///< robots/rrr.urdf, loaded once
std::string deg(const Eigen::Vector3d& q);  ///< "theta = (0.0, 90.0, 0.0) deg"
std::vector<GradedTest> analysis_tests();   ///< questions i-iv, in the report's order

}  // namespace opspace::grading::p4_graded
