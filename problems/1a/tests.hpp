/// @file problems/1a/tests.hpp
/// The identities of problem 1a's graded tests, each declared once: problems/1a/grade/graded.cpp
/// gives each test its title (what the report and results.json show); the known mistakes
/// (grade/mistakes.cpp), the library's answers (forbidden.hpp) and the handout's recorded suite
/// name a test by its identity, so that a title can be reworded in one place and a misspelt
/// name is a compile error. No secret: the handout's suite holds the titles too.
#pragma once

namespace opspace::grading::test_id::p1a {

inline constexpr char kRedundant[] = "1a.i.redundant";
inline constexpr char kMassMatrix[] = "1a.ii.mass_matrix";
inline constexpr char kJacobian[] = "1a.iii.jacobian";
inline constexpr char kPseudoInverse[] = "1a.iv.pseudo_inverse";
inline constexpr char kPseudoInverseProjector[] = "1a.iv.pseudo_inverse_projector";
inline constexpr char kWeightedInverse[] = "1a.v.weighted_inverse";
inline constexpr char kWeightedProjector[] = "1a.v.weighted_projector";
inline constexpr char kConsistentInverse[] = "1a.vi.consistent_inverse";
inline constexpr char kConsistentProjector[] = "1a.vi.consistent_projector";
inline constexpr char kFamily[] = "1a.iv-vi.family";
inline constexpr char kSharing[] = "1a.vi.sharing";

}  // namespace opspace::grading::test_id::p1a
