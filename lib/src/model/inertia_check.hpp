/// @file inertia_check.hpp
/// What both readers of a Model (urdf_build.cpp, model_text.cpp) require of a body's rotational
/// inertia about its centre of mass.
#pragma once

#include <Eigen/Core>
#include <string>

namespace opspace::detail {

/// Why I cannot be a rotational inertia, or "" if it can. I must be finite, symmetric and
/// positive semi-definite (zero stays allowed: massless frames, point masses), each to
/// 1e-12 of max(1, the largest |entry|). The answer completes "inertia that is ...":
/// "not finite", "not symmetric", "not positive semi-definite (eigenvalues a b c)".
std::string inertia_defect(const Eigen::Matrix3d& I);

}  // namespace opspace::detail
