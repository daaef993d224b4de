// The explorer's WebAssembly entry points (em++, web/explorer/CMakeLists.txt): the page hands
// each robot's Model text over once, then asks for a view at every slider move. The numbers
// come from explore.cpp and the library, compiled from the same sources as the native build.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "explore.hpp"
#include "opspace/model/model_text.hpp"

namespace {

struct Loaded {
  opspace::Model model;
  opspace::Data data;
  opspace::explore::Tip tip;
  explicit Loaded(opspace::Model m) : model(std::move(m)), data(model) {}
};

std::vector<std::unique_ptr<Loaded>> robots;
std::string last_error;
std::string last_view;

}  // namespace

extern "C" {

/// Reads a Model text (model_text.hpp); returns its handle, or -1 (see explorer_error).
int explorer_load(const char* model_text, const char* source, const char* tip_link, double px, double py,
                  double pz) {
  try {
    auto loaded = std::make_unique<Loaded>(opspace::read_model_text(model_text, source));
    loaded->tip.frame = loaded->model.frame_id(tip_link);
    loaded->tip.point = Eigen::Vector3d(px, py, pz);
    robots.push_back(std::move(loaded));
    return static_cast<int>(robots.size()) - 1;
  } catch (const std::exception& e) {
    last_error = e.what();
    return -1;
  }
}

/// explore::view_json for robot `handle` (q: n doubles); nullptr on error (see explorer_error).
/// The string lives until the next call.
const char* explorer_view(int handle, const double* q, int n, double ux, double uy, double uz, double tip_s,
                          int self_joint, double self_s) {
  try {
    if (handle < 0 || handle >= static_cast<int>(robots.size())) throw std::invalid_argument("no robot handle " + std::to_string(handle));
    Loaded& r = *robots[handle];
    opspace::explore::Request request;
    request.q = Eigen::Map<const Eigen::VectorXd>(q, n);
    request.u = Eigen::Vector3d(ux, uy, uz);
    request.tip_s = tip_s;
    request.self_joint = self_joint;
    request.self_s = self_s;
    last_view = opspace::explore::view_json(r.model, r.data, r.tip, request);
    return last_view.c_str();
  } catch (const std::exception& e) {
    last_error = e.what();
    return nullptr;
  }
}

/// The message of the last failed call.
const char* explorer_error() { return last_error.c_str(); }

}  // extern "C"
