/// @file pinned_run.hpp
/// A problem's closed-loop run with its law pinned at every tick (law_pin.hpp), made once per
/// implementation (Hw2Api::identity) and variant (1b's part, 4's target) and shared by the
/// behaviour tests that read it; the suite's own tests grade several implementations in turn.
/// A problem may list its runs ahead of its tests (Problem::runs) for a second runner to make
/// (runs_ahead.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <utility>

#include "law_pin.hpp"
#include "run/runs_ahead.hpp"

namespace opspace::grading {

/// What a run left: the problem's Result and the pin of its law.
template <class Result>
struct PinnedRun {
  Result result;
  LawPin pin;
};

/// The key of `identity`'s run `variant` of the problem whose runs are Results.
template <class Result>
RunKey run_key(std::uint64_t identity, int variant) {
  static const char kind = 0;  // one address per Result type, that is per problem
  return RunKey{&kind, identity, variant};
}

/// The run of `identity`'s `variant`, made by `simulate(pin)` (which returns the Result, its
/// control feeding `pin`) on first use (shared_run). Kept once made; a run that ends early
/// (the runner failed during it: its Result says so) is kept too, and costs each test that reads it.
template <class Result, class Simulate>
const PinnedRun<Result>& pinned_run(std::uint64_t identity, int variant, double law_tolerance, Simulate simulate) {
  const void* run = shared_run(run_key<Result>(identity, variant), [&]() -> std::shared_ptr<const void> {
    auto made = std::make_shared<PinnedRun<Result>>(PinnedRun<Result>{Result{}, LawPin{law_tolerance}});
    made->result = simulate(made->pin);
    return made;
  });
  return *static_cast<const PinnedRun<Result>*>(run);
}

}  // namespace opspace::grading
