/// @file scenarios/scenario_check.hpp
/// What a Scenario must provide (scenarios/loop.hpp lists it), checked when Loop<Scenario> is
/// made: a missing member stops the compile with a message that names it, before the errors
/// of the code that uses it.
#pragma once

#include <type_traits>
#include <utility>

namespace opspace::scenarios::check {

// has_<name><T>: whether T has the member the expression names.
#define OPSPACE_HAS(name, ...)                                                                   \
  template <class T, class = void>                                                               \
  struct has_##name : std::false_type {};                                                        \
  template <class T>                                                                             \
  struct has_##name<T, std::void_t<decltype(__VA_ARGS__)>> : std::true_type {};                  \
  template <class T>                                                                             \
  inline constexpr bool has_##name##_v = has_##name<T>::value;

OPSPACE_HAS(observer, std::declval<typename T::Observer&>())
OPSPACE_HAS(sample, std::declval<typename T::Sample&>())
OPSPACE_HAS(summary, std::declval<typename T::Summary&>())
OPSPACE_HAS(robot_file, T::kRobotFile)
OPSPACE_HAS(graded_duration, T::kGradedDuration)
OPSPACE_HAS(settings, T::settings())
OPSPACE_HAS(what, std::declval<const T&>().what())
OPSPACE_HAS(csv_columns, T::csv_columns())
OPSPACE_HAS(t, std::declval<T&>().t)
OPSPACE_HAS(tau, std::declval<T&>().tau)
OPSPACE_HAS(time_reached, std::declval<T&>().time_reached)
OPSPACE_HAS(clamped_steps, std::declval<T&>().clamped_steps)
OPSPACE_HAS(kpx, std::declval<T&>().kpx)
OPSPACE_HAS(kvx, std::declval<T&>().kvx)
OPSPACE_HAS(kvj, std::declval<T&>().kvj)
#undef OPSPACE_HAS

/// The Sample's and Summary's members the loop writes and reads (run_closed_loop).
template <class Sample, class Summary>
constexpr bool members() {
  static_assert(has_t_v<Sample>, "a Scenario's Sample needs `double t`, the sample's time (scenarios/loop.hpp)");
  static_assert(has_tau_v<Sample>, "a Scenario's Sample needs `tau`, the torques the loop applies (scenarios/loop.hpp)");
  static_assert(has_time_reached_v<Summary>,
                "a Scenario's Summary needs `time_reached` (derive it from scenarios::RunTotals, scenarios/summary.hpp)");
  static_assert(has_clamped_steps_v<Summary>,
                "a Scenario's Summary needs `clamped_steps` (derive it from scenarios::RunTotals, scenarios/summary.hpp)");
  return true;
}

/// Scenario S's types and static members (scenarios/loop.hpp); its Sample's and Summary's members.
template <class S>
constexpr bool scenario() {
  static_assert(has_observer_v<S>, "a Scenario needs a type `Observer`, constructible from the Model (scenarios/loop.hpp)");
  static_assert(has_sample_v<S>, "a Scenario needs a type `Sample`, one instant of the run (scenarios/loop.hpp)");
  static_assert(has_summary_v<S>, "a Scenario needs a type `Summary`, what a run measured (scenarios/loop.hpp)");
  static_assert(has_robot_file_v<S>, "a Scenario needs `static constexpr const char* kRobotFile` (scenarios/loop.hpp)");
  static_assert(has_graded_duration_v<S>, "a Scenario needs `static constexpr double kGradedDuration` (scenarios/loop.hpp)");
  static_assert(has_settings_v<S>, "a Scenario needs `static SimulationSettings settings()` (scenarios/loop.hpp)");
  static_assert(has_what_v<S>, "a Scenario needs `std::string what() const` (scenarios/loop.hpp)");
  static_assert(has_csv_columns_v<S>, "a Scenario needs `static std::vector<std::string> csv_columns()` (scenarios/loop.hpp)");
  if constexpr (has_sample_v<S> && has_summary_v<S>) return members<typename S::Sample, typename S::Summary>();
  return true;
}

/// The gains GainOverrides::apply sets (scenarios/common.hpp): the live lab's sliders.
template <class Goal>
constexpr bool gains() {
  static_assert(has_kpx_v<Goal>, "GainOverrides::apply: the Goal needs `double kpx`, the task stiffness (1/s^2)");
  static_assert(has_kvx_v<Goal>, "GainOverrides::apply: the Goal needs `double kvx`, the task damping (1/s)");
  static_assert(has_kvj_v<Goal>, "GainOverrides::apply: the Goal needs `double kvj`, the joint damping (1/s)");
  return true;
}

}  // namespace opspace::scenarios::check
