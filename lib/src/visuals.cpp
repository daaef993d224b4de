#include "opspace/visuals.hpp"

#include <exception>
#include <ostream>

namespace opspace::visuals {

std::string prefix_of(const std::string& csv_path) {
  const std::string ext = ".csv";
  if (csv_path.size() > ext.size() && csv_path.compare(csv_path.size() - ext.size(), ext.size(), ext) == 0) {
    return csv_path.substr(0, csv_path.size() - ext.size());
  }
  return csv_path;
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
      if (!page.skipped.empty()) result.skipped.push_back(page.skipped);
    } catch (const std::exception& e) {
      result.skipped.push_back(std::string("no 3D replay: ") + e.what());
    }
  }
  for (const std::string& why : result.skipped) out << "note:   " << why << "\n";
  return result;
}

}  // namespace opspace::visuals
