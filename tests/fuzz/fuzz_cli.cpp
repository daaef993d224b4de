// libFuzzer target: the command lines of hw2-p1 .. hw2-p4 (lib/src/programs/cli.cpp). An input is the
// program's name on its first line (hw2-p1, hw2-p2, hw2-p3 or hw2-p4), then one argument per
// line (an argument cannot hold a newline here, nor a NUL in a real argv). Each command line
// must end in one of three ways: the program goes on (-1) with options it can run (a duration
// in (0, kMaxDuration], a log path), or help (0) was asked for, or it is refused (2) with a
// message on stderr that quotes one of its arguments (or, for hw2-p1 without a PART, the
// usage). Seeds: seeds/cli/*.txt.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <problems/1b/run/command.hpp>
#include <problems/4/run/command.hpp>

#include "opspace/programs/cli.hpp"

namespace programs = opspace::programs;

namespace {

/// Reports a finding and aborts, which libFuzzer records as a crash with its input.
void require(bool ok, const std::string& what, const std::string& output) {
  if (ok) return;
  std::fprintf(stderr, "fuzz-cli: %s\nthe program printed:\n%s\n", what.c_str(), output.c_str());
  std::abort();
}

/// The programs' usage(), shortened: the first line only.
int usage(const char* program, int code) {
  (code ? std::cerr : std::cout) << "usage: " << program << " ...\n";
  return code;
}

/// Redirects std::cout and std::cerr into one string for its lifetime.
class Captured {
 public:
  Captured() : out_(std::cout.rdbuf(text_.rdbuf())), err_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~Captured() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  Captured(const Captured&) = delete;
  Captured& operator=(const Captured&) = delete;
  std::string str() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::streambuf* out_;
  std::streambuf* err_;
};

/// What parse() left in the options when the program goes on.
void check_options(const programs::Options& o, bool needs_csv, const std::string& output) {
  require(std::isfinite(o.run.duration) && o.run.duration > 0.0 && o.run.duration <= programs::kMaxDuration,
          "duration outside (0, kMaxDuration]: " + std::to_string(o.run.duration), output);
  require(!needs_csv || !o.run.csv_path.empty(), "no log path", output);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) args.push_back(line.substr(0, line.find('\0')));
  if (args.empty()) return 0;
  const std::string& program = args[0];
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int argc = static_cast<int>(args.size());

  int code = -1;
  std::string output;
  if (program == "hw2-p1") {
    programs::P1Command command;
    {
      Captured captured;
      code = programs::parse_p1(argc, argv.data(), &usage, command);
      output = captured.str();
    }
    if (code == -1) {
      check_options(command.options, true, output);
      const int part = static_cast<int>(command.part);
      require(part >= 1 && part <= 4, "no such part", output);
    }
  } else if (program == "hw2-p2" || program == "hw2-p3") {  // their main()s parse alike
    programs::Options options;
    options.run.duration = 10.0;
    options.run.csv_path = "out/" + program + ".csv";
    programs::Program p;
    p.usage = &usage;
    {
      Captured captured;
      code = programs::parse(argc, argv.data(), 1, p, options);
      output = captured.str();
    }
    if (code == -1) check_options(options, true, output);
  } else if (program == "hw2-p4") {
    programs::P4Command command;
    command.options.run.duration = 3.0;
    {
      Captured captured;
      code = programs::parse_p4(argc, argv.data(), &usage, command);
      output = captured.str();
    }
    if (code == -1) {
      check_options(command.options, false, output);
      require(!command.targets.empty(), "no target", output);
    }
  } else {
    return 0;
  }

  require(code == -1 || code == 0 || code == 2, "exit code " + std::to_string(code), output);
  if (code == 0) {
    bool help = false;
    for (int i = 1; i < argc; ++i) help = help || args[i] == "--help" || args[i] == "-h";
    require(help, "exit code 0 without --help", output);
  } else if (code == 2) {
    // The message names the program and quotes an argument, or is the usage of a bare hw2-p1.
    bool quoted = argc == 1 && output.rfind("usage: " + program, 0) == 0;
    for (int i = 1; i < argc && !quoted; ++i) {
      quoted = output.find(program + ": ") != std::string::npos &&
               (output.find("'" + args[i] + "'") != std::string::npos ||
                output.find(args[i] + " needs") != std::string::npos);
    }
    require(quoted, "refused without naming an argument", output);
  } else {
    require(output.empty(), "the program goes on after printing", output);
  }
  return 0;
}
