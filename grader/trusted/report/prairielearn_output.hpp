/// @file prairielearn_output.hpp
/// PrairieLearn's results.json (deploy/prairielearn/README.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "judge/problem_result.hpp"

namespace opspace::grading {

/// What PrairieLearn's results.json hides, and the run's seed.
struct PrairieLearnSettings {
  std::vector<std::string> hidden;  ///< tests whose "<key> <name>" contains one of these: left out
  std::uint64_t seed = 0;           ///< the run's seed, for each failed simulated test's replay
};

/// PrairieLearn's external grader's results.json (its external grading guide): gradable true,
/// score the whole grade in [0, 1] (hidden tests included), message (one line per problem,
/// counting the tests shown), and tests[] with name, description, points, max_points, message,
/// output and images[] (each failed simulated test's plots as data:image/png URLs); the hidden
/// tests left out. Kept under kPrairieLearnLimit bytes: pictures are dropped, last first, then
/// outputs cut, each with a note in message.
void write_prairielearn(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                        const PrairieLearnSettings& settings);

/// PrairieLearn's bound on results.json: 1 MB. A decimal megabyte, the smaller reading.
constexpr std::size_t kPrairieLearnLimit = 1000 * 1000;

}  // namespace opspace::grading
