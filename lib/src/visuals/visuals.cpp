#include "opspace/visuals/visuals.hpp"

#include <exception>
#include <filesystem>
#include <ostream>
#include <string>

#ifndef OPSPACE_EXPLORER_PAGE
#define OPSPACE_EXPLORER_PAGE ""
#endif

namespace opspace::visuals {

namespace fs = std::filesystem;

std::string prefix_of(const std::string& csv_path) {
  const std::string ext = ".csv";
  if (csv_path.size() > ext.size() && csv_path.compare(csv_path.size() - ext.size(), ext.size(), ext) == 0) {
    return csv_path.substr(0, csv_path.size() - ext.size());
  }
  return csv_path;
}

plot::Figure torque_figure(const Model& model, const std::vector<double>& t,
                           const std::vector<Eigen::VectorXd>& tau, const std::string& who) {
  plot::Figure torques{"torques", "Joint torques against their URDF effort limits - " + who};
  torques.columns = 2;
  torques.row_height = 260;
  for (int i = 0; i < model.dof(); ++i) {
    const Body& b = model.bodies[static_cast<std::size_t>(i)];
    std::vector<double> tau_i;
    tau_i.reserve(tau.size());
    for (const Eigen::VectorXd& v : tau) tau_i.push_back(v(i));
    plot::Panel& p = torques.panel("joint " + std::to_string(i + 1) + " (" + b.joint_name + ")", "N m");
    p.add("tau" + std::to_string(i + 1), t, std::move(tau_i)).color = "#1f77b4";
    p.level("effort limit", b.effort).level("", -b.effort);
  }
  return torques;
}

Published publish(const std::vector<plot::Figure>& figures, const replay::Scene* scene,
                  const std::string& prefix, std::ostream& out) {
  Published result;
  // A picture that cannot be made (unwritable folder, a run with no samples) is a note: the
  // run itself, and its log, are what count.
  if (!figures.empty()) {
    try {
      const plot::Output plots = plot::render(figures, prefix);
      result.images = plots.images;
      for (const std::string& image : plots.images) out << "plot:   " << image << "\n";
      if (!plots.skipped.empty()) result.skipped.push_back(plots.skipped);
    } catch (const std::exception& e) {
      result.skipped.push_back(std::string("no plots: ") + e.what());
    }
  }
  if (scene) {
    try {
      const replay::Output page = replay::write(*scene, prefix + "-replay.html");
      result.page = page.page;
      if (!page.page.empty()) out << "replay: " << page.page << "\n";
      // The explorer (docs/visuals.md): the same robots, live, where this build wrote it.
      std::error_code ec;
      if (!page.page.empty() && *OPSPACE_EXPLORER_PAGE && fs::exists(OPSPACE_EXPLORER_PAGE, ec)) out << "explorer: " << OPSPACE_EXPLORER_PAGE << "\n";
      if (!page.skipped.empty()) result.skipped.push_back(page.skipped);
    } catch (const std::exception& e) {
      result.skipped.push_back(std::string("no 3D replay: ") + e.what());
    }
  }
  for (const std::string& why : result.skipped) out << "note:   " << why << "\n";
  return result;
}

}  // namespace opspace::visuals
