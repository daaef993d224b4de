// A Scenario that lacks what the one loop needs (scenarios/loop.hpp): a Goal without kvj, which
// the live lab's gains set, and a Summary without clamped_steps, which the loop fills. It must not
// compile, and the first errors must name the missing members (check_missing_members.sh).
#include "opspace/scenarios/loop.hpp"

struct Goal {
  double kpx = 0.0, kvx = 0.0;  // no kvj
};
struct Sample {
  double t = 0.0;
  Eigen::VectorXd tau;
};
struct Summary {
  double time_reached = 0.0;  // no clamped_steps
};
struct Scenario {
  struct Observer {
    explicit Observer(const opspace::Model&) {}
  };
  using Sample = ::Sample;
  using Summary = ::Summary;
  static constexpr const char* kRobotFile = "puma.urdf";
  static constexpr double kGradedDuration = 1.0;
  static opspace::SimulationSettings settings() { return {}; }
  void start(opspace::Simulation&) const {}
  Sample tick(Observer&, opspace::Simulation&, const opspace::scenarios::GainOverrides& gains) const {
    Goal goal;
    gains.apply(goal);
    return {};
  }
  std::string what() const { return "missing members"; }
  static std::vector<std::string> csv_columns() { return {}; }
  std::vector<double> csv_row(const Sample&) const { return {}; }
  void summarise(opspace::scenarios::RunResult<Sample, Summary>&, const opspace::Model&,
                 const opspace::Simulation&) const {}
};

int main() { opspace::scenarios::run(Scenario{}, {}); }
