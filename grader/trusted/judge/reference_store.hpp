/// @file reference_store.hpp
/// The reference's series of the report's figures (grading.hpp: RunFigure): the problem set's
/// law run by the grader in each simulated test's scenario. A run costs as much as the
/// student's, so it is made only for a figure that needs it, a failed test's, and kept: for
/// every later figure of this process, and on disk in the grader's cache (set_reference_store),
/// where every later grading by the same grader finds it. A passed test's figure shows the
/// student's run alone, whatever the store holds: a grading's page and results.json do not
/// depend on what earlier gradings left (tests/graded/check_jobs.sh compares a cold store's with
/// a warm one's).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "judge/figure.hpp"

namespace opspace::grading {

/// Makes the reference's series for the figures of failed tests, and keeps them in `folder` too
/// (created if missing), one file per series: the grader's cache folder for this grader (its
/// toolchain's fingerprint names it, so that a rebuilt grader, whose scenarios or oracles may
/// differ, never reads an older one's). Empty: in this process only. Until it is called (the
/// suite's own in-process tests, which grade dozens of mistakes and read no page), no reference
/// run is made and a figure shows the student's run alone.
void set_reference_store(const std::string& folder);

/// The reference's series `key`, made by `make` the first time it is asked for.
const Series& reference_series(const std::string& key, const std::function<Series()>& make);

/// The reference's value of the statistic `key` (what a behaviour test judges of the reference's
/// run, Judgement::reference), made by `make` the first time it is asked for and kept as the
/// series are: a later grading by the same grader reads it without running the reference.
double reference_statistic(const std::string& key, const std::function<double()>& make);

/// Fills the reference series of `figures` when `needed` (a failed test); else leaves them empty.
void attach_references(std::vector<RunFigure>& figures, bool needed);

}  // namespace opspace::grading
