// Known mistakes of problem 1a. Each replaces one function by a wrong formula.
#include "judge/mistakes.hpp"
#include <problems/1a/tests.hpp>

namespace opspace::grading {

namespace p1a_mistakes {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

using hw2::p1a::DisplacementSplit;

}  // namespace
}  // namespace p1a_mistakes

std::vector<Mistake> mistakes_1a() {
  using namespace p1a_mistakes;
  namespace id = test_id::p1a;
  return {
      {"A without the coupling term: m2 left off the diagonal",
       "link 2 rides on link 1, so T = 1/2 m1 d1dot^2 + 1/2 m2 (d1dot + d2dot)^2 and A = [m1 + m2, m2; m2, m2]",
       [](Hw2Api& api) {
         api.p1a.mass_matrix = [](double m1, double m2) { return Eigen::Matrix2d(Eigen::Vector2d(m1 + m2, m2).asDiagonal()); };
       },
       {id::kMassMatrix}},
      {"A with m1 alone in its first entry",
       "the first entry is m1 + m2: moving d1 carries link 2 along",
       [](Hw2Api& api) {
         api.p1a.mass_matrix = [](double m1, double m2) { return (Eigen::Matrix2d() << m1, m2, m2, m2).finished(); };
       },
       {id::kMassMatrix}},
      {"J+ = J^T, without (J J^T)^-1",
       "J+ = J^T (J J^T)^-1",
       [](Hw2Api& api) { api.p1a.pseudo_inverse = [](const Eigen::RowVector2d& J) { return Eigen::Vector2d(J.transpose()); }; },
       {id::kPseudoInverse}},
      {"J# built with W where W^-1 belongs",
       "J# = W^-1 J^T (J W^-1 J^T)^-1: the inverse of the weight",
       [](Hw2Api& api) {
         api.p1a.weighted_inverse = [](const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
           const Eigen::Vector2d W_Jt = W * J.transpose();
           return Eigen::Vector2d(W_Jt / J.dot(W_Jt));
         };
       },
       {id::kWeightedInverse}},
      // J+ J is symmetric, so only the projectors of J# and Jbar reveal the transpose.
      {"the projector written as I - J^T J_inv^T",
       "the joint-space projector is I - J_inv J; I - J^T J_inv^T is its transpose, which acts on torques",
       [](Hw2Api& api) {
         api.p1a.nullspace_projector = [](const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
           return Eigen::Matrix2d(Eigen::Matrix2d::Identity() - J.transpose() * J_inv.transpose());
         };
       },
       {id::kWeightedProjector, id::kConsistentProjector}},
      // A route, not a slip: the stub's answer with the solution set's two projectors pasted in
      // for its own inputs. Each projector test asks J = [1 1] first, then random J and right
      // inverses, where the table has nothing to say.
      {"the projectors looked up for the problem set's inputs (J = [1 1] with J+ or Jbar) and left at 0 elsewhere",
       "I - J_inv J, computed from the J and the J_inv given, for any J and any right inverse",
       [](Hw2Api& api) {
         api.p1a.nullspace_projector = [](const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
           const auto is = [](const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& b) {
             return (a - b).norm() < 1e-12;
           };
           const bool problem_set_J = is(J, Eigen::RowVector2d(1, 1));
           if (problem_set_J && is(J_inv, Eigen::Vector2d(0.5, 0.5)))  // the solution set's I - J+ J
             return Eigen::Matrix2d((Eigen::Matrix2d() << 0.5, -0.5, -0.5, 0.5).finished());
           if (problem_set_J && is(J_inv, Eigen::Vector2d(0, 1)))  // the solution set's I - Jbar J
             return Eigen::Matrix2d((Eigen::Matrix2d() << 1, 0, -1, 0).finished());
           return Eigen::Matrix2d(Eigen::Matrix2d::Zero());  // the stub's answer
         };
       },
       {id::kPseudoInverseProjector,
        id::kWeightedProjector, id::kConsistentProjector}},
      {"question vi answered with J+ for both splits",
       "the second split uses Jbar = A^-1 J^T (J A^-1 J^T)^-1 with A = A(m1, m2): it moves only d2",
       [](Hw2Api& api) {
         api.p1a.split_displacement = [](double, double, double dx) {
           DisplacementSplit split;
           split.with_pseudo_inverse = Eigen::Vector2d(0.5, 0.5) * dx;
           split.with_inertia_weighted = split.with_pseudo_inverse;
           return split;
         };
       },
       {id::kSharing}},
  };
}

}  // namespace opspace::grading
