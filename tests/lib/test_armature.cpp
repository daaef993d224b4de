// The armature (Body::armature: a motor's reflected inertia Jm G^2): how a URDF gives it, what it
// adds to A(q) and to inverse dynamics, that the model text keeps it, and that the simulation
// swings a pendulum with it at the period of the closed form.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/model/model_text.hpp"
#include "opspace/model/urdf.hpp"
#include "opspace/simulation/simulation.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;

namespace {

std::string pendulum_path() { return std::string(OPSPACE_TEST_DATA_DIR) + "/sim/armature_pendulum.urdf"; }

/// A one-joint robot whose joint element holds `armature` (an element, or nothing).
std::string one_joint(const std::string& armature, const std::string& type = "revolute") {
  return "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"><inertial><mass value=\"1\"/>"
         "<inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>"
         "<joint name=\"j\" type=\"" + type + "\"><parent link=\"a\"/><child link=\"b\"/><axis xyz=\"0 0 1\"/>"
         "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>" + armature + "</joint></robot>";
}

}  // namespace

TEST_CASE("a URDF joint's <armature> gives Jm G^2 from the motor's parameters, or the value itself") {
  // 1e-4 kg m^2 behind 100:1 is 1e-4 * 100^2 = 1 kg m^2 (to rounding); the gear's sign is its
  // direction, which the square drops; no element means no armature.
  CHECK(load_urdf(pendulum_path()).bodies[0].armature == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(parse_urdf(one_joint("<armature rotor_inertia=\"2e-4\" gear_ratio=\"-50\"/>"), "s").bodies[0].armature ==
        doctest::Approx(0.5).epsilon(1e-15));
  CHECK(parse_urdf(one_joint("<armature value=\"0.25\"/>"), "s").bodies[0].armature == 0.25);
  CHECK(parse_urdf(one_joint(""), "s").bodies[0].armature == 0.0);
}

TEST_CASE("an <armature> that cannot be a motor's inertia is refused with its line and cause") {
  const auto refused = [](const std::string& element, const std::string& type = "revolute") {
    try {
      parse_urdf(one_joint(element, type), "s.urdf");
    } catch (const UrdfError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(refused("<armature value=\"-1\"/>") == "s.urdf:1: joint 'j' has <armature value=\"-1\">: expected a finite number >= 0");
  CHECK(refused("<armature value=\"1kg\"/>") == "s.urdf:1: joint 'j' has <armature value=\"1kg\">: expected a finite number >= 0");
  CHECK(refused("<armature value=\"inf\"/>") == "s.urdf:1: joint 'j' has <armature value=\"inf\">: expected a finite number >= 0");
  CHECK(refused("<armature/>").find("has an <armature> with no value") != std::string::npos);
  CHECK(refused("<armature value=\"1\" gear_ratio=\"2\"/>").find("both value and rotor_inertia/gear_ratio") != std::string::npos);
  CHECK(refused("<armature rotor_inertia=\"1e-4\"/>") ==
        "s.urdf:1: joint 'j' has <armature gear_ratio=\"\">: expected a finite number");
  CHECK(refused("<armature rotor_inertia=\"1e300\" gear_ratio=\"1e300\"/>").find("overflows") != std::string::npos);
  CHECK(refused("<armature value=\"1\"/><armature value=\"2\"/>").find("has a second <armature>") != std::string::npos);
  CHECK(refused("<armature value=\"1\"/>", "fixed").find("is fixed: an <armature> needs a moving joint") != std::string::npos);
}

TEST_CASE("the armature adds to A's diagonal and to inverse dynamics, and nothing else") {
  // A(q) with armature D is A(q) + diag(D) (the same sums, plus D on the diagonal: equal to the
  // rounding of that one addition, 1e-14 for entries of a few kg m^2), and
  // RNEA adds D_i qdd_i: the toolbox's model of a geared motor. b and g do not change.
  Model plain = load_urdf(robot_path("iiwa7.urdf"));
  Model armed = plain;
  opspace::testing::Random rng(392);
  const Eigen::VectorXd D = rng.vector(7, 0.0, 2.0);
  for (int i = 0; i < 7; ++i) armed.bodies[i].armature = D(i);
  Data dp(plain), da(armed);
  const Eigen::VectorXd q = rng.vector(7, -2, 2), qd = rng.vector(7), qdd = rng.vector(7);
  CHECK((crba(armed, da, q) - crba(plain, dp, q) - Eigen::MatrixXd(D.asDiagonal())).cwiseAbs().maxCoeff() < 1e-14);
  const Eigen::VectorXd expected = rnea(plain, dp, q, qd, qdd) + D.cwiseProduct(qdd);
  CHECK((rnea(armed, da, q, qd, qdd) - expected).norm() < 1e-12);
  CHECK((forward_dynamics(armed, da, q, qd, expected) - qdd).norm() < 1e-10);
}

TEST_CASE("the model text keeps the armature, and older texts without it still read") {
  const Model model = load_urdf(pendulum_path());
  const std::string text = write_model_text(model);
  CHECK(text.find("\narmature 0 ") != std::string::npos);
  CHECK(read_model_text(text, "t").bodies[0].armature == model.bodies[0].armature);
  Model plain = model;
  plain.bodies[0].armature = 0.0;
  CHECK(write_model_text(plain).find("\narmature ") == std::string::npos);
}

TEST_CASE("a free-swinging pendulum with armature keeps the period of the closed form") {
  // I_axis = 0.26 kg m^2, armature D = 1 kg m^2, m g l = 9.81 * 0.5 N m (armature_pendulum.urdf).
  // Released at rest from theta0, the period is T = 4 sqrt((I_axis + D) / (m g l)) K(sin(theta0/2))
  // (K: the complete elliptic integral of the first kind): 3.20 s here, against 1.45 s without the
  // armature. Measured over four periods from the zero crossings of q (linear interpolation
  // between steps, an error below 1e-6 s at 1 ms and these speeds). Measured: 6e-7 relative with
  // RK4, 1.4e-7 with Euler; a correction from the step's start alone misses by 8e-4 under RK4,
  // so the bound 1e-5 tells the two apart.
  const double theta0 = 0.5, mgl = 9.81 * 0.5, I_axis = 0.26, D = 1.0;
  const double closed_form = 4.0 * std::sqrt((I_axis + D) / mgl) * std::comp_ellint_1(std::sin(theta0 / 2));
  const Model model = load_urdf(pendulum_path());
  for (const Integrator integrator : {Integrator::kRK4, Integrator::kEuler}) {
    CAPTURE(integrator == Integrator::kRK4 ? "RK4" : "Euler");
    SimulationSettings settings;
    settings.integrator = integrator;
    Simulation sim(model, settings);
    sim.set_state(Eigen::VectorXd::Constant(1, theta0), Eigen::VectorXd::Zero(1));
    double first = -1.0, last = -1.0, previous = theta0;
    int crossings = 0;
    const Eigen::VectorXd no_torque = Eigen::VectorXd::Zero(1);
    while (crossings < 9 && sim.time() < 60.0) {
      sim.step(no_torque);
      const double now = sim.q()(0);
      if ((previous > 0) != (now > 0)) {
        const double t = sim.time() - settings.dt * now / (now - previous);
        if (crossings == 0) first = t;
        last = t;
        ++crossings;
      }
      previous = now;
    }
    REQUIRE(crossings == 9);
    const double period = (last - first) / 4.0;  // 9 crossings: 8 half periods
    MESSAGE("period " << period << " s, closed form " << closed_form << " s, relative difference "
                      << std::abs(period - closed_form) / closed_form);
    CHECK(std::abs(period - closed_form) < 1e-5 * closed_form);
  }
}
