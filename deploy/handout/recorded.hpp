/// @file recorded.hpp
/// The handout's visible suite as data: for each graded test its identity, title, points and hint, and
/// the calls the test made to the reference solutions, each with its encoded arguments and
/// the reference's encoded answer (protocol/codec.hpp, the machine's byte order). Numbers,
/// not code: a handout carries no reference implementation (docs/instructor.md).
///
/// The text format, one record per line:
///   opspace-visible-suite 2 <hex of the double 1.0>      the byte order it was written in
///   problem <key> <title>
///   test <points> <identity> <title>                      (GradedTest: the identity has no space)
///   hint <text>
///   call <function code, hex> <arguments, hex> <answer, hex>
/// Texts escape '\' as "\\" and a line end as "\n". Version 1 named a test by its title alone: a
/// grader reading it would match no library answer to its tests, so it is refused.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace opspace::recorded {

using Bytes = std::vector<unsigned char>;

struct Call {
  std::uint32_t function = 0;  ///< protocol::Function
  Bytes arguments;             ///< the encoded arguments
  Bytes answer;                ///< the reference's encoded answer
};

struct Test {
  std::string id, title, hint;
  double points = 0.0;
  std::vector<Call> calls;
};

struct Problem {
  std::string key, title;
  std::vector<Test> tests;
};

inline std::string hex(const Bytes& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size() * 2);
  for (const unsigned char b : bytes) out += digits[b >> 4], out += digits[b & 15];
  return out;
}

inline Bytes unhex(const std::string& text, const std::string& where) {
  auto value = [&](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    throw std::runtime_error(where + ": not a hexadecimal digit");
  };
  if (text.size() % 2 != 0) throw std::runtime_error(where + ": odd number of hexadecimal digits");
  Bytes out(text.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<unsigned char>(value(text[2 * i]) * 16 + value(text[2 * i + 1]));
  return out;
}

inline std::string escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') out += "\\\\";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

inline std::string unescape(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) {
      out += text[i + 1] == 'n' ? '\n' : text[i + 1];
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

inline std::string byte_order() {
  const double one = 1.0;
  Bytes bytes(sizeof one);
  std::memcpy(bytes.data(), &one, sizeof one);
  return hex(bytes);
}

inline void write(std::ostream& out, const std::vector<Problem>& problems) {
  out << "opspace-visible-suite 2 " << byte_order() << "\n";
  for (const Problem& p : problems) {
    out << "problem " << p.key << " " << escape(p.title) << "\n";
    for (const Test& t : p.tests) {
      out << "test " << t.points << " " << t.id << " " << escape(t.title) << "\n" << "hint " << escape(t.hint) << "\n";
      for (const Call& c : t.calls) {
        std::ostringstream code;
        code << std::hex << c.function;
        // "-" stands for no bytes (a function without arguments).
        const std::string arguments = c.arguments.empty() ? "-" : hex(c.arguments);
        out << "call " << code.str() << " " << arguments << " " << hex(c.answer) << "\n";
      }
    }
  }
}

/// Reads a suite; throws std::runtime_error naming the file and line on bad input.
inline std::vector<Problem> read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the visible suite");
  std::vector<Problem> problems;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = path + ":" + std::to_string(number);
    const std::size_t space = line.find(' ');
    const std::string kind = line.substr(0, space), rest = space == std::string::npos ? "" : line.substr(space + 1);
    if (number == 1) {
      if (kind != "opspace-visible-suite" || rest.rfind("2 ", 0) != 0)
        throw std::runtime_error(where + ": not a visible suite of this version (2); make the handout again");
      if (rest.substr(2) != byte_order())
        throw std::runtime_error(where + ": written on a machine of another byte order; make the handout on this kind of machine");
      continue;
    }
    if (kind == "problem") {
      const std::size_t at = rest.find(' ');
      problems.push_back({rest.substr(0, at), unescape(at == std::string::npos ? "" : rest.substr(at + 1)), {}});
    } else if (kind == "test" && !problems.empty()) {
      const std::size_t at = rest.find(' '), title = at == std::string::npos ? at : rest.find(' ', at + 1);
      if (title == std::string::npos) throw std::runtime_error(where + ": a test needs its points, identity and title");
      Test t;
      t.points = std::stod(rest.substr(0, at));
      t.id = rest.substr(at + 1, title - at - 1);
      t.title = unescape(rest.substr(title + 1));
      problems.back().tests.push_back(t);
    } else if (kind == "hint" && !problems.empty() && !problems.back().tests.empty()) {
      problems.back().tests.back().hint = unescape(rest);
    } else if (kind == "call" && !problems.empty() && !problems.back().tests.empty()) {
      std::istringstream fields(rest);
      std::string code, arguments, answer;
      fields >> code >> arguments >> answer;
      Call c;
      c.function = static_cast<std::uint32_t>(std::stoul(code, nullptr, 16));
      if (arguments != "-") c.arguments = unhex(arguments, where);
      c.answer = unhex(answer, where);
      problems.back().tests.back().calls.push_back(std::move(c));
    } else {
      throw std::runtime_error(where + ": unexpected line '" + kind + "'");
    }
  }
  return problems;
}

}  // namespace opspace::recorded
