// opspace-explorer: the native side of the explorer page (docs/visuals.md).
//   opspace-explorer page OUT.html CORE.js VIEWER.js   writes the page: the four robots' Models as
//                                                       text, their shapes, the WebAssembly module
//                                                       (CORE.js) and the viewer (VIEWER.js), inlined
//   opspace-explorer view ROBOT Q [U TIP_S SELF_JOINT SELF_S]
//                                                       prints what the page computes for that
//                                                       request (Q, U: comma-separated), as JSON
//   opspace-explorer model ROBOT                        prints the robot's Model as the page hands it
//                                                       to the module (model_text.hpp)
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "explore.hpp"
#include "opspace/model/model_text.hpp"
#include "page_data.hpp"
#include "robots.hpp"

namespace ex = opspace::explore;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// An inlined script cannot hold "</script".
std::string inline_script(std::string script) {
  for (std::size_t at = script.find("</script"); at != std::string::npos; at = script.find("</script", at)) {
    script.replace(at, 2, "<\\/");
  }
  return script;
}

int write_page(const std::string& out_path, const std::string& core, const std::string& viewer) {
  const std::string data = ex::page_data_json(ex::course_robots());
  std::ofstream out(out_path);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>opspace explorer</title>\n"
      << "<!-- Written by opspace-explorer (web/explorer/main.cpp). The numbers come from the library's C++ "
         "compiled to WebAssembly (web/explorer/wasm_api.cpp); viewer: web/src/explorer.js with three.js (MIT). -->\n"
      << "</head>\n<body>\n"
      << "<script id=\"opspace-explorer-data\" type=\"application/json\">" << data << "</script>\n"
      << "<script>" << inline_script(read_file(core)) << "</script>\n"
      << "<script>" << inline_script(read_file(viewer)) << "</script>\n</body>\n</html>\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write the explorer page " + out_path);
  std::cout << "explorer: " << out_path << "\n";
  return 0;
}

std::vector<double> numbers(const std::string& list, const char* what) {
  std::vector<double> v;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    v.push_back(std::strtod(item.c_str(), &end));
    if (item.empty() || *end != '\0') throw std::invalid_argument(std::string(what) + ": '" + item + "' is not a number");
  }
  return v;
}

int print_view(const std::vector<std::string>& args) {
  if (args.size() != 2 && args.size() != 6) throw std::invalid_argument("view takes ROBOT Q [U TIP_S SELF_JOINT SELF_S]");
  const ex::Robot r = ex::course_robot(args[0]);
  const std::vector<double> q = numbers(args[1], "Q");
  ex::Request request;
  request.q = Eigen::Map<const Eigen::VectorXd>(q.data(), static_cast<Eigen::Index>(q.size()));
  if (args.size() == 6) {
    const std::vector<double> u = numbers(args[2], "U");
    if (u.size() != 3) throw std::invalid_argument("U takes three numbers");
    request.u = Eigen::Vector3d(u[0], u[1], u[2]);
    request.tip_s = numbers(args[3], "TIP_S").at(0);
    request.self_joint = static_cast<int>(numbers(args[4], "SELF_JOINT").at(0));
    request.self_s = numbers(args[5], "SELF_S").at(0);
  }
  // The page's model is the text, read back: the same numbers the WebAssembly module reads.
  const opspace::Model model = opspace::read_model_text(opspace::write_model_text(r.model), r.key);
  opspace::Data data(model);
  std::cout << ex::view_json(model, data, r.tip, request) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 4 && args[0] == "page") return write_page(args[1], args[2], args[3]);
    if (!args.empty() && args[0] == "view") return print_view({args.begin() + 1, args.end()});
    if (args.size() == 2 && args[0] == "model") {
      std::cout << opspace::write_model_text(ex::course_robot(args[1]).model);
      return 0;
    }
    std::cerr << "usage: opspace-explorer page OUT.html CORE.js VIEWER.js\n"
                 "       opspace-explorer view ROBOT Q [U TIP_S SELF_JOINT SELF_S]\n"
                 "       opspace-explorer model ROBOT\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "opspace-explorer: " << e.what() << "\n";
    return 1;
  }
}
