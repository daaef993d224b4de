// The plotting and replay writers without external tools: decimation, frame choice, the
// page's data block, and that a missing gnuplot or viewer bundle is reported, never thrown.
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include "opspace/model/urdf.hpp"
#include "opspace/visuals/visuals.hpp"

namespace fs = std::filesystem;
using namespace opspace;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("opspace-test-visuals-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Restores an environment variable when the test ends.
class EnvGuard {
 public:
  EnvGuard(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    ::setenv(name, value, 1);
  }
  ~EnvGuard() { had_ ? (void)::setenv(name_.c_str(), old_.c_str(), 1) : (void)::unsetenv(name_.c_str()); }

 private:
  std::string name_, old_;
  bool had_ = false;
};

}  // namespace

TEST_CASE("decimate keeps a single-sample spike and stays within its point budget") {
  std::vector<double> x(20001), y(20001, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1e-3 * static_cast<double>(i);
  y[12345] = 200.0;  // one 1 ms spike, like PART2's wrist torque
  y[777] = -5.0;
  std::vector<double> xo, yo;
  plot::decimate(x, y, 4000, xo, yo);
  // Two points per bucket of ceil(2 n / budget) samples: at most the budget plus one bucket.
  CHECK(xo.size() <= 4002);
  CHECK(*std::max_element(yo.begin(), yo.end()) == 200.0);
  CHECK(*std::min_element(yo.begin(), yo.end()) == -5.0);
  CHECK(std::is_sorted(xo.begin(), xo.end()));  // time order survives
  plot::decimate(std::vector<double>{0, 1, 2}, std::vector<double>{3, 4, 5}, 4000, xo, yo);
  CHECK(yo == std::vector<double>{3, 4, 5});  // short series are untouched
}

TEST_CASE("without gnuplot, render writes the data and script and says why nothing was drawn") {
  const EnvGuard no_gnuplot("OPSPACE_GNUPLOT", "/nonexistent/gnuplot");
  CHECK(plot::find_gnuplot().empty());
  const fs::path dir = fresh_dir("plot");
  plot::Figure f("demo", "a \"quoted\" title");
  f.panel("panel", "m").add("y", {0.0, 1.0}, {1.0, 2.0}).color = "#123456";
  f.panels[0].level("limit", 1.5);
  const plot::Output out = plot::render({f}, (dir / "run").string());
  CHECK(out.images.empty());
  CHECK(out.skipped.find("gnuplot was not found") != std::string::npos);
  REQUIRE(fs::exists(dir / "run-demo.gp"));
  REQUIRE(fs::exists(dir / "run-demo.dat"));
  std::ifstream gp(dir / "run-demo.gp");
  std::stringstream text;
  text << gp.rdbuf();
  CHECK(text.str().find("\\\"quoted\\\"") != std::string::npos);  // gnuplot string escaping
  CHECK(text.str().find("set output 'run-demo.png'") != std::string::npos);  // relative: the folder can move
  fs::remove_all(dir);
}

TEST_CASE("a series with unequal x and y is refused, naming it") {
  plot::Panel p;
  CHECK_THROWS_WITH_AS(p.add("tau1", {0.0, 1.0}, {0.0}), doctest::Contains("tau1"), std::invalid_argument);
}

TEST_CASE("frame_indices keeps the first and last sample and one per frame period") {
  std::vector<double> t(1001);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 1e-3 * static_cast<double>(i);  // 1 s at 1 ms
  const std::vector<std::size_t> f = replay::frame_indices(t, 50.0);
  // 1 s at 50 frames/s: frames at 0, 20, ..., 1000 ms, i.e. 51.
  CHECK(f.size() == 51);
  CHECK(f.front() == 0);
  CHECK(f.back() == 1000);
  CHECK(f[1] == 20);
}

TEST_CASE("the replay data block has one pose per body per frame and the markers") {
  replay::Scene scene;
  scene.title = "PUMA </script> test";
  scene.model = load_urdf(robot_path("puma.urdf"));
  for (int k = 0; k <= 100; ++k) {
    scene.t.push_back(0.01 * k);
    scene.q.push_back(Eigen::VectorXd::Constant(6, 0.01 * k));
  }
  scene.markers.push_back(replay::Marker::point_at("target", "#ff0000", {Eigen::Vector3d(0.1, 0.2, 0.3)}));
  scene.markers.push_back(replay::Marker::trail("path", "#0000ff", replay::Track(101, Eigen::Vector3d::Zero())));
  scene.readouts.push_back({"error", std::vector<double>(101, 1.0)});
  const std::string json = replay::scene_json(scene);
  // 1 s at 50 frames/s: 51 frames, each a list of 6 bodies x 7 numbers.
  CHECK(count(json, "],[") >= 50);
  CHECK(json.find("\"bodies\":6") != std::string::npos);
  CHECK(count(json, "\"kind\":\"cylinder\"") == scene.model.visuals.size());  // puma.urdf: cylinders only
  CHECK(json.find("</script") == std::string::npos);  // the data block cannot end early
  CHECK(json.find("\"target\"") != std::string::npos);

  scene.markers.push_back(replay::Marker::trail("short", "#000000", replay::Track(7)));
  CHECK_THROWS_WITH_AS(replay::scene_json(scene), doctest::Contains("short"), std::invalid_argument);
}

TEST_CASE("without the viewer bundle no page is written, and the note says why") {
  const EnvGuard no_bundle("OPSPACE_REPLAY_BUNDLE", "/nonexistent/opspace-replay.js");
  replay::Scene scene;
  scene.model = load_urdf(robot_path("puma.urdf"));
  scene.t = {0.0};
  scene.q = {Eigen::VectorXd::Zero(6)};
  const fs::path dir = fresh_dir("replay");
  const replay::Output out = replay::write(scene, (dir / "page.html").string());
  CHECK(out.page.empty());
  CHECK(out.skipped.find("/nonexistent/opspace-replay.js") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "page.html"));
  fs::remove_all(dir);
}

TEST_CASE("the pictures of a run are named after its log") {
  CHECK(visuals::prefix_of("out/hw2-p1-part3.csv") == "out/hw2-p1-part3");
  CHECK(visuals::prefix_of("log") == "log");
}
