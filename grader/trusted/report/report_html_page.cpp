// The report's page of report_html.hpp (its plots: report_html.cpp): per problem and test the
// status, points, findings and hint, each simulated test's figure with its numbers, a wrong
// matrix's entries.
#include <cmath>
#include <ostream>

#include "report/html_text.hpp"
#include "report/report_html.hpp"

namespace opspace::grading {

namespace {

const char* plotted_name(Plotted p) {
  switch (p) {
    case Plotted::kLargest: return "largest";
    case Plotted::kRunningRms: return "running-rms";
    case Plotted::kRunningMean: return "running-mean";
    case Plotted::kFinal: return "final";
    case Plotted::kSeries: break;
  }
  return "series";
}

// A figure with its numbers in data- attributes: the series as plotted, the bound, how the plot
// gives the judged statistic (data-plotted) and the two values the verdict used (data-verdict,
// data-verdict-reference), which the tests read back off the series.
void figure_block(std::ostream& out, const RunFigure& f) {
  const double final_value = f.student.v.empty() ? NAN : f.student.v.back();
  out << "<figure class=\"run\" data-quantity=\"" << html_text(f.quantity) << "\" data-unit=\"" << html_text(f.unit)
      << "\" data-scale=\"" << html_number(f.unit_scale, 17) << "\" data-bound=\"" << html_number(f.bound, 17) << "\" data-upper=\""
      << (f.upper ? 1 : 0) << "\" data-from=\"" << html_number(f.judged_from, 17) << "\" data-final=\"" << html_number(final_value, 17)
      << "\" data-plotted=\"" << plotted_name(f.plotted) << "\" data-draws=\"" << html_text(f.draws) << "\" data-verdict=\""
      << exact_number(f.verdict_yours) << "\" data-verdict-reference=\"" << exact_number(f.verdict_reference)
      << "\"\n  data-student-t=\"" << joined_numbers(f.student.t, 7) << "\"\n  data-student-v=\"" << joined_numbers(f.student.v, 17)
      << "\"\n  data-reference-t=\"" << joined_numbers(f.reference.t, 7) << "\"\n  data-reference-v=\""
      << joined_numbers(f.reference.v, 17) << "\">\n"
      << svg_plot(f) << "\n<figcaption>" << html_text(f.quantity) << ": <span class=\"key student\">your run</span>";
  if (!f.reference.t.empty()) out << ", <span class=\"key reference\">the reference's (the problem set's law)</span>";
  else out << " (the reference's run is drawn for a failed test)";
  if (std::isfinite(f.bound))
    out << ", <span class=\"key bound\">the bound</span>: " << (f.upper ? "at most " : "at least ")
        << html_text(html_number(f.bound * f.unit_scale, 4) + " " + f.unit) << " on " << html_text(f.judged);
  else if (!f.judged.empty())
    out << "; the check reads " << html_text(f.judged);
  if (f.judged_from > 0.0) out << "; the shaded start is not judged";
  if (y_range(f).clipped) out << "; your run leaves the plot at the top";
  if (y_range(f).log) out << "; the axis is logarithmic: your run goes far beyond the bound's scale";
  if (!f.draws.empty() && std::isfinite(f.verdict_yours)) {
    out << ". Judged, " << html_text(f.draws) << ": yours " << html_text(html_number(f.verdict_yours * f.unit_scale, 4) + " " + f.unit);
    if (std::isfinite(f.verdict_reference))
      out << ", the reference's " << html_text(html_number(f.verdict_reference * f.unit_scale, 4) + " " + f.unit);
    out << ".</figcaption>\n</figure>\n";
    return;
  }
  out << ". Your final value: " << html_text(html_number(final_value * f.unit_scale, 6) + " " + f.unit) << ".</figcaption>\n</figure>\n";
}

// The entries of a wrong matrix or vector: expected, computed, difference; the wrong ones marked.
void entry_table(std::ostream& out, const EntryTable& e) {
  if (e.what.empty() || e.expected.size() > 100) return;
  const double scale = std::max(1.0, e.expected.cwiseAbs().maxCoeff());
  const auto wrong = [&](Eigen::Index i, Eigen::Index j) {
    const double c = e.computed(i, j);
    return !std::isfinite(c) || std::abs(c - e.expected(i, j)) > e.tol * scale;
  };
  if (e.expected.cols() > 1) {  // a matrix: its grid, each entry expected over computed
    out << "<table class=\"entries grid\"><caption>" << html_text(e.what) << ": each entry expected, then computed (wrong beyond "
        << html_text(html_number(e.tol * scale, 3)) << ")</caption>\n";
    for (Eigen::Index i = 0; i < e.expected.rows(); ++i) {
      out << "<tr>";
      for (Eigen::Index j = 0; j < e.expected.cols(); ++j)
        out << "<td" << (wrong(i, j) ? " class=\"wrong\"" : "") << ">" << html_number(e.expected(i, j), 6) << "<br>"
            << html_number(e.computed(i, j), 6) << "</td>";
      out << "</tr>\n";
    }
    out << "</table>\n";
    return;
  }
  out << "<table class=\"entries\"><caption>" << html_text(e.what) << ", entry by entry (wrong beyond "
      << html_text(html_number(e.tol * scale, 3)) << ")</caption>\n<tr><th>entry</th><th>expected</th><th>computed</th><th>difference</th></tr>\n";
  for (Eigen::Index i = 0; i < e.expected.rows(); ++i) {
    const double x = e.expected(i, 0), c = e.computed(i, 0);
    out << "<tr" << (wrong(i, 0) ? " class=\"wrong\"" : "") << "><td>(" << i << ")</td><td>" << html_number(x, 6) << "</td><td>"
        << html_number(c, 6) << "</td><td>" << html_number(c - x, 3) << "</td></tr>\n";
  }
  out << "</table>\n";
}

void test_block(std::ostream& out, const ProblemResult& p, const TestResult& r, std::uint64_t seed) {
  const std::string st = status(r);
  out << "<section class=\"test " << (st == "PASS" ? "pass" : "fail") << "\" data-test=\""
      << html_text(p.problem->key + " " + r.test->title) << "\" data-status=\"" << st << "\" data-simulated=\""
      << (r.test->replay.empty() ? 0 : 1) << "\" data-not-written=\"" << (r.not_written ? 1 : 0) << "\">\n<h3><span class=\"status\">" << st << "</span> "
      << format_points(r.score) << "/" << format_points(r.test->points) << " " << html_text(r.test->title) << "</h3>\n";
  if (r.not_written) {
    // One line, as in the text report and on Gradescope: the judged values, the hint, the replay
    // and the plots would only describe the stub (the stubs' 41 tests drew 19 plots).
    out << "<p class=\"not-written\">" << html_text(r.findings.back()) << "</p>\n";
    if (!r.printed.empty()) out << "<p>your code printed:</p>\n<pre class=\"printed\">" << html_text(r.printed) << "</pre>\n";
    out << "</section>\n";
    return;
  }
  if (!r.judged.empty()) {
    out << "<ul class=\"judged\">\n";
    for (const std::string& j : r.judged) out << "<li>judged: " << html_text(j) << "</li>\n";
    out << "</ul>\n";
  }
  if (r.score < r.test->points) {
    out << "<ul class=\"findings\">\n";
    for (const std::string& finding : r.findings) out << "<li>" << html_text(finding) << "</li>\n";
    out << "</ul>\n";
    if (shows_hint(r)) out << "<p class=\"hint\">hint: " << html_text(r.test->hint) << "</p>\n";
    const std::string replay = replay_command(*r.test, seed);
    if (!replay.empty()) out << "<p class=\"replay\">replay it: <code>" << html_text(replay) << "</code></p>\n";
    entry_table(out, r.table);
  }
  for (const RunFigure& f : r.figures) figure_block(out, f);
  if (!r.printed.empty()) out << "<p>your code printed:</p>\n<pre class=\"printed\">" << html_text(r.printed) << "</pre>\n";
  out << "</section>\n";
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:60em;margin:1em auto;padding:0 1em;color:#222}"
    "h2{border-bottom:1px solid #ccc;padding-bottom:.2em}h3{font-size:1em;margin:.2em 0}"
    ".test{border-left:4px solid #2ca02c;padding:.3em .8em;margin:.8em 0}.test.fail{border-color:#d62728}"
    ".status{font-weight:bold}.fail .status{color:#d62728}.pass .status{color:#2ca02c}"
    "table.grid caption{text-align:left;white-space:nowrap}table.grid td{text-align:right;padding:.2em .6em;border:1px solid #ddd}figure{margin:.5em 0}figcaption{font-size:.9em;color:#444}"
    ".key.student{color:#d62728}.key.reference{color:#1f77b4}.key.bound{color:#2ca02c}"
    "table.entries{border-collapse:collapse;font-size:.9em;margin:.5em 0}"
    "table.entries td,table.entries th{border:1px solid #ccc;padding:.1em .5em;text-align:right}"
    "tr.wrong,td.wrong{background:#fdd}code{background:#f4f4f4;padding:.1em .3em}pre.printed{background:#f4f4f4;padding:.5em}";

}  // namespace

void write_html_report(std::ostream& out, const std::vector<ProblemResult>& problems,
                       const std::vector<std::string>& hidden, std::uint64_t seed) {
  double total = 0.0, total_max = 0.0;
  for (const ProblemResult& p : problems) {
    const ShownScore shown = shown_score(p, hidden);
    total += shown.score;
    total_max += shown.max_score;
  }
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>opspace: grade report</title>\n"
      << "<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>Grade report: " << format_points(total) << " / "
      << format_points(total_max) << " points</h1>\n<p>Seed " << seed
      << " (<code>bash scripts/grade --seed " << seed << "</code> grades these inputs again). Each simulated test "
      << "plots what its check reads: <span class=\"key student\">your run</span> and, for a failed test, "
      << "<span class=\"key reference\">the reference's</span> (the problem set's law in the same scenario), with "
      << "<span class=\"key bound\">the bound</span> (docs/grader.md, \"Reading a failed test's page\").</p>\n";
  for (const ProblemResult& p : problems) {
    const ShownScore shown = shown_score(p, hidden);
    out << "<h2>Problem " << html_text(p.problem->key) << ": " << html_text(p.problem->title) << " (" << format_points(shown.score)
        << " / " << format_points(shown.max_score) << ")</h2>\n";
    if (!p.failure.empty()) out << "<pre class=\"printed\">" << html_text(p.failure) << "</pre>\n";
    for (const std::string& note : p.notes) out << "<p class=\"note\">" << html_text(note) << "</p>\n";
    for (const TestResult& r : p.results)
      if (!is_hidden(p, r, hidden)) test_block(out, p, r, seed);
    if (shown.hidden_tests > 0)
      out << "<p>" << shown.hidden_tests << " hidden test(s) of " << format_points(shown.hidden_points)
          << " points not shown: they count in the grade your instructor publishes.</p>\n";
    if (!p.warnings.empty()) out << "<p>compiler warnings (not counted):</p>\n<pre class=\"printed\">" << html_text(p.warnings) << "</pre>\n";
  }
  out << "</body>\n</html>\n";
}

}  // namespace opspace::grading
