// URDF loading in three passes, a file each (declared in urdf_passes.hpp), run here:
//  0. Scans of the text (urdf_text.cpp): it must be UTF-8 without NUL bytes (TinyXML reads past
//     the end of a cut UTF-8 sequence), and the markup's nesting depth and attributes per
//     element are bounded (TinyXML recurses once per level and compares each new attribute with
//     the element's others: the call stack or quadratic time would pay for them).
//  1. TinyXML (urdf_structure.cpp; urdfdom itself depends on it) checks what urdfdom does not,
//     or reports without a line number: well-formed XML, joint types, mimic joints, the tree
//     shape (one parent per link, one root, no loop). It also records each link's and joint's
//     line.
//  2. urdfdom parses the checked text (here), and the links are walked from the root into a
//     Model (urdf_build.cpp), with every number checked on the way (masses, inertias, limits,
//     shape sizes, and the sums and products of finite numbers that overflow).
// urdfdom's console_bridge messages are captured while it parses, so the user sees only our
// UrdfError (console_bridge's handler is process-global: do not load URDFs from two threads).
#include "opspace/model/urdf.hpp"

#include <cerrno>
#include <console_bridge/console.h>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>
#include <urdf_parser/urdf_parser.h>

#include "printable.hpp"
#include "urdf_passes.hpp"

namespace opspace {

namespace urdf_passes {

using detail::printable;

void fail(const std::string& source, int line, const std::string& cause) {
  throw UrdfError(source + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + printable(cause));
}

}  // namespace urdf_passes

namespace {

using urdf_passes::fail;

/// Collects console_bridge messages (urdfdom's) instead of printing them.
class CapturedLog : public console_bridge::OutputHandler {
 public:
  CapturedLog() { console_bridge::useOutputHandler(this); }
  ~CapturedLog() override { console_bridge::restorePreviousOutputHandler(); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors += (errors.empty() ? "" : "; ") + text;
  }
  std::string errors;
};

}  // namespace

Model parse_urdf(const std::string& xml, const std::string& source) {
  urdf_passes::check_encoding(xml, source);
  urdf_passes::check_markup(xml, source);
  const urdf_passes::Lines lines = urdf_passes::check_structure(xml, source);
  urdf::ModelInterfaceSharedPtr tree;
  std::string errors;
  {
    CapturedLog log;
    try {
      tree = urdf::parseURDF(xml);
    } catch (const std::exception& e) {
      log.errors += e.what();
    }
    errors = log.errors;
  }
  if (!tree) {
    fail(source, urdf_passes::line_named_in(errors, lines),
         "urdfdom rejected the file: " + (errors.empty() ? "no reason given" : errors));
  }

  Model model;
  model.name = tree->getName();
  model.source = source;
  urdf_passes::build_model(model, *tree, lines);
  return model;
}

Model load_urdf(const std::string& path) {
  // The largest robots' URDF files are under 1 MB (meshes live in files of their own): the
  // cap keeps a wrong path (/dev/zero, a FIFO, a log) from filling the memory.
  constexpr std::size_t kMaxBytes = std::size_t{16} << 20;
  std::ifstream file(path, std::ios::binary);
  if (!file) fail(path, 0, std::string("cannot open the file (") + std::strerror(errno) + ")");
  std::string text;
  char chunk[1 << 16];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
    if (text.size() > kMaxBytes) fail(path, 0, "larger than 16 MB: not a URDF (meshes live in files of their own)");
  }
  if (file.bad()) fail(path, 0, std::string("cannot read the file (") + std::strerror(errno) + ")");
  return parse_urdf(text, path);
}

std::string robot_path(const std::string& file_name) { return std::string(OPSPACE_ROBOTS_DIR) + "/" + file_name; }

}  // namespace opspace
