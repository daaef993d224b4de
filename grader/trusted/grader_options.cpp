// hw2-grade's command line (docs/grader.md): the options, their checks and the usage text.
#include "grader_options.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <thread>

namespace opspace::grading {

namespace {

// More threads than problems would wait idle: the suite has a handful of problems, 64 is far
// more than any list holds, and refuses a typo of thousands.
constexpr unsigned long kMaxJobs = 64;

bool is_problem(const std::string& key) {
  for (const Problem& p : graded_suite())
    if (p.key == key) return true;
  return false;
}

// "SECONDS" or "KEY=SECONDS": sets the limit of every test, or of problem KEY's tests.
bool parse_timeout(const std::string& text, GraderOptions& options, const char* program) {
  const std::size_t equals = text.find('=');
  const std::string key = equals == std::string::npos ? "" : text.substr(0, equals);
  const std::string number = equals == std::string::npos ? text : text.substr(equals + 1);
  if (equals != std::string::npos && !is_problem(key)) {
    std::cerr << program << ": --timeout " << text << ": no problem '" << key << "' (--help lists the keys)\n";
    return false;
  }
  char* end = nullptr;
  const double seconds = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !(seconds > 0.0) || seconds > 86400.0) {
    std::cerr << program << ": --timeout needs a number of seconds between 0 and 86400, or KEY=SECONDS, not '"
              << text << "'\n";
    return false;
  }
  if (key.empty()) options.timeout = seconds;
  else options.problem_timeout[key] = seconds;
  return true;
}

// A size in MiB: a whole number from 1 to 2^30 (a petabyte, past any machine).
bool parse_mib(const std::string& text, unsigned long long& mib, const std::string& option, const char* program) {
  char* end = nullptr;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] < '0' || text[0] > '9' || *end != '\0' || value == 0 || value > (1ull << 30)) {
    std::cerr << program << ": " << option << " needs a whole number of MiB from 1 to " << (1ull << 30) << ", not '"
              << text << "'\n";
    return false;
  }
  mib = value;
  return true;
}

}  // namespace

int grader_usage(std::ostream& out, const char* program, double default_timeout, int code) {
  out << "usage: " << program << " [--problem KEY] [--exercises DIR] [--timeout [KEY=]SECONDS]... [--seed N]\n"
      << "          [--gradescope FILE] [--prairielearn FILE] [--junit FILE] [--html FILE] [--hidden TEXT]...\n"
      << "          [--sandbox-user NAME] [--unprotected] [--hidden-visibility WHEN] [--gradescope-format FORMAT] [--no-isolation]\n"
      << "          [--memory MIB] [--cache DIR] [--cache-limit MIB] [--jobs N] [--one-runner]\n"
      << "  --problem      grade one problem only (";
  bool first = true;
  for (const Problem& p : graded_suite()) {
    out << (first ? "" : ", ") << p.key;
    first = false;
  }
  out << ")\n"
      << "  --exercises    the folder holding p1a.cpp ... p4.cpp (default: this repository's)\n"
      << "  --timeout      time limit of each test, in seconds (default " << default_timeout << ");\n"
      << "                 KEY=SECONDS sets problem KEY's alone (repeatable)\n"
      << "  --seed         replay the random inputs of an earlier run (its report prints the seed)\n"
      << "  --gradescope   also write Gradescope's results.json to FILE\n"
      << "  --gradescope-format html (default: plots as pictures, matrices as tables) or text\n"
      << "                 (plots as tables of samples): results.json's tests' output_format\n"
      << "  --prairielearn also write PrairieLearn's results.json to FILE (score in [0, 1], the\n"
      << "                 failed runs' plots as images; --hidden tests left out, counted in the score)\n"
      << "  --junit        also write JUnit XML to FILE\n"
      << "  --html         also write the report as a page to FILE, with each simulated test's run\n"
      << "                 plotted (scripts/grade: out/grade/report.html)\n"
      << "  --hidden       hide from the student the tests whose name contains TEXT (repeatable):\n"
      << "                 the report and results.json's lines count the others; the score, the\n"
      << "                 gradebook's, counts all\n"
      << "  --hidden-visibility after_published (default) or after_due_date: when Gradescope\n"
      << "                 shows the hidden tests, and the total, to the student\n"
      << "  --sandbox-user when run as root: a named account runs student code, shared with any\n"
      << "                 grading running at once (default: an account of this grading's own)\n"
      << "  --unprotected  grade even where the sandbox is incomplete (no namespaces): the code\n"
      << "                 graded runs with the grader's rights; for your own files only\n"
      << "  --memory       this grading's memory budget for all it starts (compilers, runners,\n"
      << "                 their /tmp), in MiB (default: the machine's; scripts/regrade divides it\n"
      << "                 between the gradings it runs at once)\n"
      << "  --cache        the runners' cache folder (default: the build's grading-cache)\n"
      << "  --cache-limit  the runners' cache bound in MiB (default " << kDefaultCacheMib
      << "): the least recently used\n"
      << "                 runners are removed past it when a grading ends\n"
      << "  --check-sandbox say whether the sandbox holds whole here, and grade nothing\n"
      << "                 (exit 0 if it does, 3 if not)\n"
      << "  --jobs         grade N problems at once, each with its own runner (default: one per\n"
      << "                 core, or one as root, where the runners share one account's process limit)\n"
      << "  --one-runner   one runner per problem: no second runner making a problem's simulated\n"
      << "                 runs beside its tests when a core is spare (the same report either way)\n"
      << "  --no-isolation run the student's code without the sandbox (debugging only)\n"
      << "Exit code 0 whenever grading ran, whatever the score; 3 when it refused to run code\n"
      << "where the sandbox cannot be built (see --unprotected).\n";
  return code;
}

unsigned jobs_by_default(bool shared_account) {
  return shared_account ? 1u : std::max(1u, std::thread::hardware_concurrency());
}

double timeout_of(const GraderOptions& options, const std::string& key) {
  const auto found = options.problem_timeout.find(key);
  return found == options.problem_timeout.end() ? options.timeout : found->second;
}

bool parse_grader_options(int argc, char** argv, GraderOptions& options, int& exit_code) {
  const double default_timeout = options.timeout;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--help" || arg == "-h") {
      exit_code = grader_usage(std::cout, argv[0], default_timeout, 0);
      return false;
    }
    if (arg == "--problem" && has_value) {
      options.only_problem = argv[++i];
    } else if (arg == "--exercises" && has_value) {
      options.exercises = argv[++i];
    } else if (arg == "--timeout" && has_value) {
      if (!parse_timeout(argv[++i], options, argv[0])) {
        exit_code = 2;
        return false;
      }
    } else if (arg == "--seed" && has_value) {
      char* end = nullptr;
      const std::string text = argv[++i];
      options.seed = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || text[0] == '-' || options.seed == 0) {
        std::cerr << argv[0] << ": --seed needs a positive whole number\n";
        exit_code = 2;
        return false;
      }
    } else if ((arg == "--memory" || arg == "--cache-limit") && has_value) {
      if (!parse_mib(argv[++i], arg == "--memory" ? options.memory_mib : options.cache_mib, arg, argv[0])) {
        exit_code = 2;
        return false;
      }
    } else if (arg == "--cache" && has_value) {
      options.cache_dir = argv[++i];
    } else if (arg == "--gradescope" && has_value) {
      options.gradescope_path = argv[++i];
    } else if (arg == "--prairielearn" && has_value) {
      options.prairielearn_path = argv[++i];
    } else if (arg == "--gradescope-format" && has_value) {
      options.gradescope_format = argv[++i];
      if (options.gradescope_format != "html" && options.gradescope_format != "text") {
        std::cerr << argv[0] << ": --gradescope-format is html or text, not '" << options.gradescope_format << "'\n";
        exit_code = 2;
        return false;
      }
    } else if (arg == "--junit" && has_value) {
      options.junit_path = argv[++i];
    } else if (arg == "--html" && has_value) {
      options.html_path = argv[++i];
    } else if (arg == "--hidden" && has_value) {
      options.hidden.push_back(argv[++i]);
    } else if (arg == "--hidden-visibility" && has_value) {
      // Gradescope's "hidden" would show the student a total holding the hidden tests' points
      // (its specification: hidden tests are for tests worth nothing).
      options.hidden_as = argv[++i];
      if (options.hidden_as != "after_published" && options.hidden_as != "after_due_date") {
        std::cerr << argv[0] << ": --hidden-visibility is after_published or after_due_date, not '"
                  << options.hidden_as << "' (a hidden test with points would show in the total)\n";
        exit_code = 2;
        return false;
      }
    } else if (arg == "--jobs" && has_value) {
      char* end = nullptr;
      const std::string text = argv[++i];
      const unsigned long jobs = std::strtoul(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || text[0] == '-' || jobs == 0 || jobs > kMaxJobs) {
        std::cerr << argv[0] << ": --jobs needs a whole number from 1 to " << kMaxJobs << ", not '" << text << "'\n";
        exit_code = 2;
        return false;
      }
      options.jobs = static_cast<unsigned>(jobs);
    } else if (arg == "--sandbox-user" && has_value) {
      options.user = argv[++i];
    } else if (arg == "--check-sandbox") {
      options.check_sandbox = true;
    } else if (arg == "--unprotected") {
      options.allow_unprotected = true;
    } else if (arg == "--one-runner") {
      options.second_runner = false;
    } else if (arg == "--no-isolation") {
      options.isolate = false;
    } else {
      std::cerr << argv[0] << ": unknown or incomplete argument '" << arg << "'\n";
      exit_code = grader_usage(std::cerr, argv[0], default_timeout, 2);
      return false;
    }
  }
  return true;
}

std::uint64_t drawn_seed() {
  std::random_device device;
  return (static_cast<std::uint64_t>(device()) << 20 ^ device()) % 1000000000ull + 1;
}

std::vector<const Problem*> chosen_problems(const std::vector<Problem>& suite, const std::string& only) {
  std::vector<const Problem*> chosen;
  for (const Problem& problem : suite)
    if (only.empty() || problem.key == only) chosen.push_back(&problem);
  return chosen;
}

GradingSettings grading_settings(const GraderOptions& options, const std::vector<const Problem*>& chosen,
                                 const Account& account) {
  GradingSettings settings;
  settings.isolate = options.isolate;
  for (const Problem* problem : chosen) settings.timeouts[problem->key] = timeout_of(options, problem->key);
  settings.second_runner = options.second_runner;
  settings.jobs = options.jobs > 0 ? options.jobs : jobs_by_default(options.isolate && account.uid != 0);
  return settings;
}

ResultsFiles results_files(const GraderOptions& options, bool unprotected) {
  return {options.gradescope_path, options.prairielearn_path, options.junit_path, options.html_path,
          options.hidden,          options.hidden_as,         options.gradescope_format, options.seed,
          unprotected};
}

}  // namespace opspace::grading
