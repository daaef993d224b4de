/// @file scenarios/graded.hpp
/// What the graded simulated tests (tests/graded/p1b.cpp ... p4.cpp) share with the programs'
/// replay of one of them (hw2-p1 3 --test NAME --seed N): the duration each test's run lasts
/// and the series its checks read, sample by sample. The grader plots these series (the report's
/// figures); a program replaying a test prints their final values, which match the figure's to
/// round-off because both come from these functions applied to the same scenario's run.
/// The scenarios are the problem set's and draw no random input: every seed gives the same run.
#pragma once

#include <problems/1b/scenario.hpp>
#include <problems/2/scenario.hpp>
#include <problems/3/scenario.hpp>
#include <problems/4/scenario.hpp>

namespace opspace::scenarios {

/// Simulated seconds of each graded run: p1b::kDefaultDuration (one period of q_d), p2's and
/// p3's kDefaultDuration (two periods of x_d), p4::kDuration.
double graded_duration(const std::string& problem);

namespace p1b {
double tip_error(const Sample& s);  ///< |x - x_d| (m), x_d the scenario's fixed target
double q2_error(const Sample& s);   ///< |q2 - q2_d| (rad)
}  // namespace p1b

namespace p2 {
double position_error(const Sample& s);     ///< |x_p - x_pd| (m)
double orientation_angle(const Sample& s);  ///< the angle of R R_d^T (rad)
double lambda_dot_lambda_d(const Sample& s);  ///< lambda . lambda_d: lambda flips where it would cross 0
}  // namespace p2

namespace p3 {
double force_error(const Sample& s);       ///< |F_x - kPushForce| (N)
double tilt_angle(const Sample& s);        ///< the tool's tilt against the plane (rad)
double yz_error(const Sample& s);          ///< |(y - y_d, z - z_d)| (m)
double rotation_x_error(const Sample& s);  ///< |delta_phi_x| (rad)
double push(const Sample& s);              ///< F_x (N): the tool touches the plane while it is above 0
}  // namespace p3

namespace p4 {
/// |x - x_d| (m) toward `target`'s x_d.
double tip_error(hw2::p4::Target target, const Sample& s);
}  // namespace p4

}  // namespace opspace::scenarios
