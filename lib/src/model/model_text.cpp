#include "opspace/model/model_text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "printable.hpp"
#include "inertia_check.hpp"

namespace opspace {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- writing ----

std::string encode(const std::string& name) {
  if (name.empty()) return "%-";
  std::string out;
  for (unsigned char c : name) {
    if (c <= 0x20 || c == '%' || c >= 0x7f) {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

class Writer {
 public:
  Writer& word(const std::string& w) {
    out_ << (first_ ? "" : " ") << w;
    first_ = false;
    return *this;
  }
  Writer& num(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return word(buffer);
  }
  Writer& nums(const Eigen::Ref<const Eigen::MatrixXd>& M) {  // row by row
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
      for (Eigen::Index c = 0; c < M.cols(); ++c) num(M(r, c));
    }
    return *this;
  }
  Writer& placement(const Eigen::Isometry3d& X) { return nums(X.linear()).nums(X.translation().transpose()); }
  void end_line() {
    out_ << '\n';
    first_ = true;
  }
  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_;
  bool first_ = true;
};

void write_inertia(Writer& w, const Inertia& I) {
  w.num(I.mass).nums(I.com.transpose()).nums(I.inertia);
}

void write_shape(Writer& w, const char* record, const Shape& s) {
  static const char* const kKinds[] = {"box", "cylinder", "sphere"};
  w.word(record).word(encode(s.link)).num(s.body).word(kKinds[static_cast<int>(s.kind)]);
  w.nums(s.box_size.transpose()).num(s.radius).num(s.length).placement(s.placement);
  w.end_line();
}

// ---- reading ----

/// The tokens of one line, consumed left to right, with errors naming the line.
class Line {
 public:
  Line(const std::string& text, const std::string& where) : where_(where) {
    std::istringstream in(text);
    for (std::string t; in >> t;) tokens_.push_back(t);
  }
  bool empty() const { return tokens_.empty(); }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(where_ + ": " + detail::printable(what));
  }
  std::string word(const char* what) {
    if (next_ >= tokens_.size()) fail(std::string("missing ") + what);
    return tokens_[next_++];
  }
  std::string name(const char* what) {
    const std::string w = word(what);
    if (w == "%-") return "";
    std::string out;
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (w[i] != '%') {
        out += w[i];
        continue;
      }
      const std::string hex = w.substr(i + 1, 2);
      char* end = nullptr;
      const long c = hex.size() == 2 ? std::strtol(hex.c_str(), &end, 16) : -1;
      if (c < 0 || end != hex.c_str() + 2) fail(std::string("bad escape in ") + what + " '" + w + "'");
      out += static_cast<char>(c);
      i += 2;
    }
    return out;
  }
  double num(const char* what) {
    const std::string w = word(what);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end != w.c_str() + w.size() || !std::isfinite(v) || errno == ERANGE) {
      fail(std::string(what) + " is '" + w + "', not a finite number");
    }
    return v;
  }
  /// A joint limit: a finite number, or inf / -inf (a continuous joint, or no <limit>).
  double limit(const char* what) {
    if (next_ < tokens_.size() && (tokens_[next_] == "inf" || tokens_[next_] == "-inf")) {
      return tokens_[next_++] == "inf" ? kInf : -kInf;
    }
    return num(what);
  }
  int index(const char* what, int lowest, int below) {
    const double v = num(what);
    if (v != std::floor(v) || v < lowest || v >= below) {
      fail(std::string(what) + " " + tokens_[next_ - 1] + " is not an index in [" + std::to_string(lowest) +
           ", " + std::to_string(below) + ")");
    }
    return static_cast<int>(v);
  }
  template <int R, int C>
  Eigen::Matrix<double, R, C> matrix(const char* what) {
    Eigen::Matrix<double, R, C> M;
    for (int r = 0; r < R; ++r) {
      for (int c = 0; c < C; ++c) M(r, c) = num(what);
    }
    return M;
  }
  /// A rigid transform: R^T R = I and det R = 1, to the rounding of a rotation written in
  /// 17 digits (1e-9 leaves room for products of several such rotations).
  Eigen::Isometry3d placement(const char* what) {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = matrix<3, 3>(what);
    X.translation() = matrix<1, 3>(what).transpose();
    const Eigen::Matrix3d R = X.linear();
    if (!(R.transpose() * R).isIdentity(1e-9) || !(R.determinant() > 0.0)) {
      fail(std::string(what) + ": its 3x3 part is not a rotation (R^T R = I, det R = 1)");
    }
    return X;
  }
  Inertia inertia(const char* what) {
    Inertia I;
    I.mass = num(what);
    if (I.mass < 0.0) fail(std::string(what) + ": negative mass");
    I.com = matrix<1, 3>(what).transpose();
    I.inertia = matrix<3, 3>(what);
    // What the URDF loader requires too.
    const std::string defect = detail::inertia_defect(I.inertia);
    if (!defect.empty()) fail(std::string(what) + ": inertia matrix " + defect);
    return I;
  }
  void done() const {
    if (next_ != tokens_.size()) fail("unexpected '" + tokens_[next_] + "' at the end of the line");
  }

 private:
  std::string where_;
  std::vector<std::string> tokens_;
  std::size_t next_ = 0;
};

Shape read_shape(Line& line, int bodies) {
  Shape s;
  s.link = line.name("link name");
  s.body = line.index("shape body", -1, bodies);
  const std::string kind = line.word("shape kind");
  if (kind == "box") {
    s.kind = Shape::Kind::kBox;
  } else if (kind == "cylinder") {
    s.kind = Shape::Kind::kCylinder;
  } else if (kind == "sphere") {
    s.kind = Shape::Kind::kSphere;
  } else {
    line.fail("shape kind '" + kind + "' is not box, cylinder or sphere");
  }
  s.box_size = line.matrix<1, 3>("box size").transpose();
  s.radius = line.num("radius");
  s.length = line.num("length");
  if (s.box_size.minCoeff() < 0.0 || s.radius < 0.0 || s.length < 0.0) {
    line.fail("shape of link '" + s.link + "' has a negative size");
  }
  s.placement = line.placement("shape placement");
  return s;
}

}  // namespace

std::string write_model_text(const Model& model) {
  Writer w;
  w.word("opspace-model").word("1").end_line();
  w.word("robot").word(encode(model.name)).end_line();
  w.word("gravity").nums(model.gravity.transpose()).end_line();
  w.word("base");
  write_inertia(w, model.base_inertia);
  w.end_line();
  for (const Body& b : model.bodies) {
    w.word("body").word(encode(b.joint_name)).word(encode(b.link_name));
    w.word(b.type == JointType::kRevolute ? "revolute" : "prismatic").num(b.parent);
    w.placement(b.joint_placement).nums(b.axis.transpose());
    write_inertia(w, b.inertia);
    w.num(b.lower).num(b.upper).num(b.effort).num(b.velocity).end_line();
  }
  for (int i = 0; i < model.dof(); ++i) {  // only where there is one: older texts stay valid
    if (model.bodies[i].armature != 0.0) w.word("armature").num(i).num(model.bodies[i].armature).end_line();
  }
  for (const Frame& f : model.frames) {
    w.word("frame").word(encode(f.name)).num(f.body).placement(f.placement).end_line();
  }
  for (const Shape& s : model.visuals) write_shape(w, "visual", s);
  for (const Shape& s : model.collisions) write_shape(w, "collision", s);
  w.word("end").end_line();
  return w.text();
}

Model read_model_text(const std::string& text, const std::string& source) {
  Model model;
  model.source = source;
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  bool header = false;
  bool ended = false;
  while (std::getline(in, raw)) {
    Line line(raw, source + ":" + std::to_string(++number));
    if (line.empty()) continue;
    if (ended) line.fail("text after 'end'");
    const std::string record = line.word("record");
    if (!header) {
      if (record != "opspace-model" || line.word("format version") != "1") {
        line.fail("not an opspace model text (expected 'opspace-model 1' on the first line)");
      }
      header = true;
    } else if (record == "robot") {
      model.name = line.name("robot name");
    } else if (record == "gravity") {
      model.gravity = line.matrix<1, 3>("gravity").transpose();
    } else if (record == "base") {
      model.base_inertia = line.inertia("base inertia");
    } else if (record == "body") {
      Body b;
      b.joint_name = line.name("joint name");
      b.link_name = line.name("link name");
      const std::string type = line.word("joint type");
      if (type != "revolute" && type != "prismatic") line.fail("joint type '" + type + "' is not revolute or prismatic");
      b.type = type == "revolute" ? JointType::kRevolute : JointType::kPrismatic;
      b.parent = line.index("parent", -1, model.dof());  // parents come first
      b.joint_placement = line.placement("joint placement");
      b.axis = line.matrix<1, 3>("axis").transpose();
      if (b.axis.norm() == 0.0) line.fail("joint '" + b.joint_name + "' has a zero axis");
      // The URDF loader normalises the axis: written in 17 digits, its norm is 1 to rounding.
      if (!(std::abs(b.axis.norm() - 1.0) <= 1e-12)) line.fail("joint '" + b.joint_name + "' has an axis that is not a unit vector");
      b.inertia = line.inertia("body inertia");
      b.lower = line.limit("lower limit");
      b.upper = line.limit("upper limit");
      if (!(b.lower <= b.upper)) line.fail("joint '" + b.joint_name + "' has its lower limit above its upper limit");
      b.effort = line.num("effort limit");
      b.velocity = line.num("velocity limit");
      if (b.effort < 0.0 || b.velocity < 0.0) line.fail("joint '" + b.joint_name + "' has a negative effort or velocity limit");
      model.bodies.push_back(b);
    } else if (record == "armature") {
      const int i = line.index("armature joint", 0, model.dof());  // after its body
      const double armature = line.num("armature");
      if (armature < 0.0) line.fail("joint '" + model.bodies[i].joint_name + "' has a negative armature");
      model.bodies[i].armature = armature;
    } else if (record == "frame") {
      Frame f;
      f.name = line.name("frame name");
      f.body = line.index("frame body", -1, model.dof());
      f.placement = line.placement("frame placement");
      model.frames.push_back(f);
    } else if (record == "visual" || record == "collision") {
      (record == "visual" ? model.visuals : model.collisions).push_back(read_shape(line, model.dof()));
    } else if (record == "end") {
      ended = true;
    } else {
      line.fail("unknown record '" + record + "'");
    }
    line.done();
  }
  if (!ended) {
    throw std::invalid_argument(source + ":" + std::to_string(number) + ": the text ends before 'end' (cut short?)");
  }
  return model;
}

}  // namespace opspace
