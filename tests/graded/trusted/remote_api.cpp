#include "remote_api.hpp"

#include "protocol/codec.hpp"

namespace opspace::grading {

namespace {

using protocol::Function;

// slot = a function that sends its arguments to `function` and decodes the answer as R.
template <class R, class... A>
void bind(std::function<R(A...)>& slot, RunnerProcess& runner, Function function) {
  slot = [&runner, function](A... args) -> R {
    protocol::Writer w;
    (protocol::put(w, args), ...);
    const std::vector<unsigned char> bytes = runner.call(function, w.bytes(), protocol::encoded_size<R>());
    protocol::Reader r(bytes.data(), bytes.size());
    R value{};
    try {
      protocol::get(r, value);
      r.finish();
    } catch (const protocol::DecodeError& e) {
      throw RunnerFailure(std::string("your code sent an answer that does not decode: ") + e.what());
    }
    return value;
  };
}

}  // namespace

Hw2Api remote_api(const std::string& key, RunnerProcess& runner) {
  static std::uint64_t next_identity = 1000;
  Hw2Api api{};
  api.identity = ++next_identity;
  if (key == "1a") {
    P1aApi& a = api.p1a;
    bind(a.degrees_of_freedom, runner, Function::kP1aDegreesOfFreedom);
    bind(a.mass_matrix, runner, Function::kP1aMassMatrix);
    bind(a.task_jacobian, runner, Function::kP1aTaskJacobian);
    bind(a.pseudo_inverse, runner, Function::kP1aPseudoInverse);
    bind(a.weighted_inverse, runner, Function::kP1aWeightedInverse);
    bind(a.inertia_weighted_inverse, runner, Function::kP1aInertiaWeightedInverse);
    bind(a.nullspace_projector, runner, Function::kP1aNullspaceProjector);
    bind(a.inverse_kinematics_step, runner, Function::kP1aInverseKinematicsStep);
    bind(a.split_displacement, runner, Function::kP1aSplitDisplacement);
  } else if (key == "1b") {
    bind(api.p1b.control, runner, Function::kP1bControl);
  } else if (key == "2") {
    bind(api.p2.desired_acceleration, runner, Function::kP2DesiredAcceleration);
    bind(api.p2.desired_twist_acceleration, runner, Function::kP2DesiredTwistAcceleration);
    bind(api.p2.control, runner, Function::kP2Control);
  } else if (key == "3") {
    bind(api.p3.motion_selection, runner, Function::kP3MotionSelection);
    bind(api.p3.force_selection, runner, Function::kP3ForceSelection);
    bind(api.p3.control, runner, Function::kP3Control);
  } else if (key == "4") {
    P4Api& a = api.p4;
    bind(a.degrees_of_freedom, runner, Function::kP4DegreesOfFreedom);
    bind(a.singular_directions, runner, Function::kP4SingularDirections);
    bind(a.moving_directions, runner, Function::kP4MovingDirections);
    bind(a.rotation_axes, runner, Function::kP4RotationAxes);
    bind(a.singularity_type, runner, Function::kP4SingularityType);
    bind(a.control, runner, Function::kP4Control);
  }
  return api;
}

}  // namespace opspace::grading
