// One rule for the law and the behaviour (issue 58; docs/grader.md, "The law and the behaviour"):
// a behaviour test's verdict follows from the statistics it judges, never from how large a
// difference from the law is in torque. A slip scaled up (0.5, 1, 1.1, 1.5, 2, 5 times an extra
// term) scores no better as it grows, and each simulated test earns exactly what its own judged
// statistics give: the bound's credit, or nothing where a statistic moved further than a tenth of
// its bound from the reference's (law_pin.hpp). Seen to fail on the former gate, which withheld
// every behaviour test of problem 3's extra force-direction damping at 0.51 % of the torque
// whatever the statistics (verdict 0 where the statistics gave 2 or 3 points).
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "judge/graded_suite.hpp"
#include "law_pin.hpp"
#include "linked_api.hpp"
#include "judge/oracles.hpp"
#include <problems/1b/tests.hpp>

namespace grading = opspace::grading;
namespace hw2 = opspace::hw2;

namespace {

// The scales of the extra term: the family.
const std::vector<double> kScales = {0.5, 1.0, 1.1, 1.5, 2.0, 5.0};

// The credit a judged statistic's value gives by the partial-credit rule (docs/grader.md,
// "Partial credit"): full within the bound, half within twice it (a maximum) or above half of
// it (a minimum), nothing beyond.
double credit(const grading::Judgement& j) {
  if (!std::isfinite(j.yours)) return 0.0;
  if (j.upper) return j.yours <= j.bound ? 1.0 : j.yours <= 2.0 * j.bound ? 0.5 : 0.0;
  return j.yours >= j.bound ? 1.0 : j.yours >= 0.5 * j.bound ? 0.5 : 0.0;
}

// What a simulated test of a law that differs must earn from its judged statistics alone.
double earned_by_statistics(const grading::TestResult& r) {
  double fraction = 1.0;
  for (const grading::Judgement& j : r.judgements) fraction = std::min(fraction, grading::moved(j) ? 0.0 : credit(j));
  return fraction * r.test->points;
}

const grading::Problem& problem(const std::string& key) {
  static const std::vector<grading::Problem> suite = grading::graded_suite();
  for (const grading::Problem& p : suite)
    if (p.key == key) return p;
  throw std::runtime_error("no problem " + key);
}

// Grades problem `key` with `scaled(api, s)` installing the slip at each scale in turn: the
// scores never rise with the scale, and each simulated test's score is what its statistics give.
void check_family(const std::string& key, const std::string& slip,
                  const std::function<void(grading::Hw2Api&, double)>& scaled, std::uint64_t identity) {
  double previous = HUGE_VAL;
  std::string scores;
  for (const double scale : kScales) {
    grading::Hw2Api api = grading::linked_api();
    scaled(api, scale);
    api.identity = identity++;  // its own simulated runs
    double total = 0.0;
    for (const grading::TestResult& r : grading::run_tests(problem(key).tests, api)) {
      total += r.score;
      if (r.test->replay.empty() || r.judgements.empty()) continue;  // a formula test, or a run that judged nothing
      std::ostringstream judged;
      for (const std::string& line : r.judged) judged << "\n    " << line;
      for (const std::string& line : r.findings) judged << "\n    finding: " << line;
      INFO("problem " << key << ", " << slip << " times " << scale << ": " << r.test->title << judged.str());
      CHECK(r.score == doctest::Approx(earned_by_statistics(r)));
    }
    scores += " " + std::to_string(total);
    INFO("problem " << key << ", " << slip << ": scores by scale" << scores);
    CHECK(total <= previous);
    previous = total;
  }
}

}  // namespace

TEST_CASE("law gate: 1b with an extra tip damping Jv^T Lambda_v (-s kvx dx) in every part scores no better as s grows") {
  const auto law = grading::oracle::reference_api().p1b.control;
  check_family("1b", "an extra tip damping", [law](grading::Hw2Api& api, double s) {
    api.p1b.control = [law, s](hw2::p1b::Part part, const hw2::p1b::State& x, const hw2::p1b::Goal& g) {
      return (law(part, x, g) + x.Jv.transpose() * (x.Lambda_v * (-s * g.kvx * x.dx))).eval();
    };
  }, 5100);
}

TEST_CASE("law gate: 2 with an extra task damping J0^T Lambda0 (-s kvx [v; w]) scores no better as s grows") {
  const auto law = grading::oracle::reference_api().p2.control;
  check_family("2", "an extra task damping", [law](grading::Hw2Api& api, double s) {
    api.p2.control = [law, s](const hw2::p2::State& x, const hw2::p2::Goal& g) {
      hw2::p2::Vector6d twist;
      twist << x.v, x.w;
      return (law(x, g) + x.J0.transpose() * (x.Lambda0 * (-s * g.kvx * twist))).eval();
    };
  }, 5200);
}

TEST_CASE("law gate: 3 with damping in the force directions J0^T Lambda0 Omega-bar (-s kvx [v; w]) scores no better as s grows") {
  // The law of a later year of the course: in contact the plane holds v_x and w_y, w_z at zero,
  // so it moves nothing the behaviour tests judge.
  const auto law = grading::oracle::reference_api().p3.control;
  const hw2::p3::Matrix6d omega_bar = grading::oracle::reference_api().p3.force_selection();
  check_family("3", "damping in the force directions", [law, omega_bar](grading::Hw2Api& api, double s) {
    api.p3.control = [law, omega_bar, s](const hw2::p3::State& x, const hw2::p3::Goal& g) {
      hw2::p3::Vector6d twist;
      twist << x.v, x.w;
      return (law(x, g) + x.J0.transpose() * (x.Lambda0 * (omega_bar * (-s * g.kvx * twist)))).eval();
    };
  }, 5300);
}

// The law with its torque scaled by `factor` at every tick: the law test sees any factor beyond
// its 1e-6; a behaviour test sees nothing it judges move beyond round-off.
void scale_laws(grading::Hw2Api& api, double factor) {
  const grading::Hw2Api law = grading::oracle::reference_api();
  api.p1b.control = [f = law.p1b.control, factor](hw2::p1b::Part p, const hw2::p1b::State& x, const hw2::p1b::Goal& g) {
    return (f(p, x, g) * factor).eval();
  };
  api.p2.control = [f = law.p2.control, factor](const hw2::p2::State& x, const hw2::p2::Goal& g) {
    return (f(x, g) * factor).eval();
  };
  api.p3.control = [f = law.p3.control, factor](const hw2::p3::State& x, const hw2::p3::Goal& g) {
    return (f(x, g) * factor).eval();
  };
  api.p4.control = [f = law.p4.control, factor](hw2::p4::Target t, const hw2::p4::State& x, const hw2::p4::Goal& g) {
    return (f(t, x, g) * factor).eval();
  };
}

// PART2's run is chaotic (the pseudo-inverse projector lets the null-space task drive the tip):
// a change of the torque by 1e-12 of itself, far below what the law test sees, moves its q2 error
// and drift ratio. Its judged statistics may move within twice the spread seen here
// (problems/1b/grade/graded.cpp, kPart2Q2Moved and kRatioMovedShare): the spread must stay under
// half of that. Measured: q2 0.28 to 0.39 rad, ratio 737 to 878 over k = 0 ... 7.
TEST_CASE("law gate: 1b's PART2 run is chaotic, and its statistics may move by twice the spread round-off gives them") {
  double q2_low = HUGE_VAL, q2_high = -HUGE_VAL, ratio_low = HUGE_VAL, ratio_high = -HUGE_VAL, ratio_reference = 0.0;
  for (int k = 0; k < 6; ++k) {
    grading::Hw2Api api = grading::linked_api();
    scale_laws(api, 1.0 + k * 1e-12);
    api.identity = 5400 + static_cast<std::uint64_t>(k);
    for (const grading::TestResult& r : grading::run_tests(problem("1b").tests, api)) {
      if (r.test->id != grading::test_id::p1b::kSimDriftRatio) continue;
      REQUIRE(r.judgements.size() == 2);
      const grading::Judgement& q2 = r.judgements[0];
      const grading::Judgement& ratio = r.judgements[1];
      q2_low = std::min(q2_low, q2.yours), q2_high = std::max(q2_high, q2.yours);
      ratio_low = std::min(ratio_low, ratio.yours), ratio_high = std::max(ratio_high, ratio.yours);
      ratio_reference = ratio.reference;
      INFO("k = " << k << ": q2 " << q2.yours << " rad (may move " << q2.moved_within << "), ratio " << ratio.yours
                  << " (may move " << ratio.moved_within << ")");
      CHECK(q2_high - q2_low <= 0.5 * q2.moved_within);
      CHECK(ratio_high - ratio_low <= 0.5 * ratio.moved_within);
    }
  }
  INFO("q2 from " << q2_low << " to " << q2_high << " rad; ratio from " << ratio_low << " to " << ratio_high);
  CHECK(q2_high > q2_low);  // chaotic indeed: else the wider tolerance has no reason
  CHECK(ratio_reference > 0.0);
}

// A slip the law test sees (the torque 1e-5 of itself too large, ten times its tolerance) and
// no behaviour test should: every simulated test of every problem earns its points.
TEST_CASE("law gate: a law off by 1e-5 of its torque loses the law tests and earns every simulated test") {
  for (const double factor : {1.0 + 1e-5, 1.0 - 2e-5}) {
    grading::Hw2Api api = grading::linked_api();
    scale_laws(api, factor);
    api.identity = factor > 1.0 ? 5500 : 5501;
    for (const std::string key : {"1b", "2", "3", "4"}) {
      for (const grading::TestResult& r : grading::run_tests(problem(key).tests, api)) {
        if (r.test->replay.empty()) continue;
        std::ostringstream judged;
        for (const std::string& line : r.judged) judged << "\n    " << line;
        for (const std::string& line : r.findings) judged << "\n    finding: " << line;
        INFO("the law times " << factor << ": problem " << key << ": " << r.test->title << judged.str());
        CHECK(r.score == r.test->points);
      }
    }
  }
}
