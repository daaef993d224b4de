// hw2-grade linked with the reference solutions, except that problem 1b's controller
// misbehaves as a student's might: it segfaults, hangs, throws or returns NaN.
//   faulty-grader MODE [hw2-grade arguments...]
// The grader must grade the other problems as usual and give 1b zero with a message.
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "api.hpp"
#include "grader.hpp"

namespace {

using opspace::hw2::p1b::Goal;
using opspace::hw2::p1b::Part;
using opspace::hw2::p1b::State;
using opspace::hw2::p1b::Vector6d;

Vector6d segfault(Part, const State& s, const Goal&) {
  volatile double* nowhere = nullptr;
  nowhere[static_cast<int>(s.t)] = 1.0;  // writes through a null pointer
  return Vector6d::Zero();
}

Vector6d hang(Part, const State&, const Goal&) {
  volatile unsigned long spins = 0;
  while (spins != 1) spins = spins + 2;  // never reaches 1: an endless loop
  return Vector6d::Zero();
}

Vector6d throws(Part, const State&, const Goal&) { throw std::runtime_error("index out of range"); }

Vector6d nan(Part, const State&, const Goal&) {
  return Vector6d::Constant(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: faulty-grader segfault|hang|throw|nan [hw2-grade arguments...]\n";
    return 2;
  }
  opspace::grading::Hw2Api api = opspace::grading::linked_api();
  const std::string mode = argv[1];
  if (mode == "segfault") api.p1b.control = &segfault;
  else if (mode == "hang") api.p1b.control = &hang;
  else if (mode == "throw") api.p1b.control = &throws;
  else if (mode == "nan") api.p1b.control = &nan;
  else {
    std::cerr << "faulty-grader: unknown mode " << mode << "\n";
    return 2;
  }
  argv[1] = argv[0];
  return opspace::grading::grader_main(argc - 1, argv + 1, api, "solutions/ with a faulty 1b controller");
}
