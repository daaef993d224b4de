// The grader's reading of a runner's symbols (grader/trusted/build/library_answers.cpp): which
// library answer a demangled name belongs to, whatever form nm prints it in. The names are
// written as GNU nm -C prints them; what each belongs to follows from C++'s grammar.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "build/library_answers.hpp"

using opspace::grading::answers_among;
using opspace::grading::owner_name;
using opspace::grading::symbol_names;

namespace {
const std::string kRef = "Eigen::Ref<Eigen::Matrix<double, -1, -1, 0, -1, -1> const, 0, Eigen::OuterStride<-1> > const&";
}  // namespace

TEST_CASE("a symbol belongs to the function it is part of, whatever nm adds around the name") {
  const std::string pinv = "Eigen::Matrix<double, -1, -1, 0, -1, -1> opspace::pseudo_inverse(" + kRef + ", double)";
  CHECK(owner_name(pinv) == "opspace::pseudo_inverse");
  CHECK_MESSAGE(owner_name(pinv + " [clone .cold]") == "opspace::pseudo_inverse", "a part the compiler split off");
  CHECK_MESSAGE(owner_name("opspace::pseudo_inverse(" + kRef + ", double)::{lambda(double)#1}::operator()(double) const") ==
                    "opspace::pseudo_inverse",
                "a lambda inside it");
  CHECK_MESSAGE(owner_name("guard variable for opspace::pseudo_inverse(" + kRef + ", double)::cache") ==
                    "opspace::pseudo_inverse",
                "a static variable inside it");
  CHECK_MESSAGE(owner_name("void opspace::detail::cholesky_solve_in_place<Eigen::Matrix<double, -1, -1, 0, -1, -1>, "
                           "Eigen::Matrix<double, -1, -1, 0, -1, -1> >(Eigen::Matrix<double, -1, -1, 0, -1, -1> const&, "
                           "Eigen::Matrix<double, -1, -1, 0, -1, -1>&)") == "opspace::detail::cholesky_solve_in_place",
                "a template instance: its arguments are left out");
  CHECK(owner_name("vtable for opspace::scenarios::Watchdog") == "opspace::scenarios::Watchdog");
  CHECK(owner_name("opspace::scenarios::Watchdog::~Watchdog()") == "opspace::scenarios::Watchdog::~Watchdog");
  CHECK_MESSAGE(owner_name("opspace::Progress::operator<<(double)") == "opspace::Progress::operator<<",
                "an operator's '<' is no template bracket");
  CHECK(owner_name("bool opspace::operator< <double>(opspace::X<double> const&, opspace::X<double> const&)") ==
        "opspace::operator<");
  CHECK_MESSAGE(owner_name("opspace::(anonymous namespace)::size_of(long, long)") ==
                    "opspace::{anonymous}::size_of",
                "a file's own helper stays in its namespace");
  CHECK(owner_name("opspace::kSvdTolerance") == "opspace::kSvdTolerance");
}

TEST_CASE("nm's POSIX lines give the names, with or without value and size") {
  const std::string nm = "Eigen::Matrix<double, -1, -1, 0, -1, -1> opspace::pseudo_inverse(" + kRef +
                         ", double) T 0000000000004f20 00000000000002a1\n"
                         "opspace::hw2::p1a::mass_matrix(double, double) T 1130 3c\n"
                         "opspace::weighted_inverse(" + kRef + ", " + kRef + ", double) w\n"
                         "opspace::svd(" + kRef + ", unsigned int) U\n"
                         "deadbeef D 0000000000004010\n"
                         "not a line of nm\n";
  const std::vector<std::string> names = symbol_names(nm);
  REQUIRE(names.size() == 5);
  CHECK(owner_name(names[0]) == "opspace::pseudo_inverse");
  CHECK(names[1] == "opspace::hw2::p1a::mass_matrix(double, double)");
  CHECK(owner_name(names[2]) == "opspace::weighted_inverse");
  CHECK(owner_name(names[3]) == "opspace::svd");
  CHECK_MESSAGE(names[4] == "deadbeef", "a value without a size; D is also a hexadecimal digit");
}

TEST_CASE("each problem's answers are found among a runner's names, and nothing else") {
  const std::vector<std::string> runner = {
      "Eigen::Matrix<double, -1, -1, 0, -1, -1> opspace::pseudo_inverse(" + kRef + ", double)",
      "opspace::svd(" + kRef + ", unsigned int)",
      "opspace::hw2::p1a::pseudo_inverse(Eigen::Matrix<double, 1, 2, 1, 1, 2> const&)",
      "opspace::pp::mass_matrix(double, double)",
      "opspace::scenarios::p1b::desired(double)",
      "opspace::directions(Eigen::Ref<Eigen::Matrix<double, 3, -1, 0, 3, -1> const, 0, Eigen::OuterStride<-1> > const&, double)"};
  // 1a forbids J+ and the closed forms; the student's own pseudo_inverse and the SVD are theirs
  // to have. Every problem forbids the scenarios.
  CHECK(answers_among("1a", runner) ==
        std::vector<std::string>{"opspace::pp::mass_matrix", "opspace::pseudo_inverse", "opspace::scenarios::p1b::desired"});
  CHECK_MESSAGE(answers_among("1b", runner) == std::vector<std::string>{"opspace::scenarios::p1b::desired"},
                "J+ is what 1b's stub offers");
  CHECK(answers_among("4", runner) ==
        std::vector<std::string>{"opspace::directions", "opspace::scenarios::p1b::desired"});
  CHECK_MESSAGE(answers_among("1a", {"opspace::pseudo_inverse_of_mine(double)", "opspace::ppx::f()"}).empty(),
                "a name that only begins like an answer is not one");
}
