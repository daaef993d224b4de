#!/usr/bin/env bash
# A failed test of one problem as the student sees it on the report page (issue 41, the pictures
# of problems/<KEY>/guide.md): solutions/ with p<KEY>.cpp replaced by MUTANT (a known-wrong file of
# tests/mutants/) graded by the real grader with --html, then, in the section of TEST:
#   - it FAILED (the mutant is the catalogue's mistake that costs it);
#   - figure QUANTITY (a simulated test), read from the figure's data attributes after its
#     unjudged start, as the picture shows it (SHOWS):
#       max:   the student's largest value is past the bound, the reference's largest within it
#              (the figure keeps each stretch's peak, grader/suite/run_figure.hpp, so a test that
#              bounds the largest value reads the same peaks);
#       apart: every student point is past the bound and every reference point below the
#              student's lowest: the two curves apart, the bound between or under them. For a
#              test that bounds a mean or an RMS, which the peak-keeping figure cannot give (the
#              reference's contact force in problem 3 is noisy: its plotted peaks pass the 1 N
#              its mean stays within); that the reference passes the test itself is the suite's
#              "graded: the reference solutions earn full marks ...";
#   - or QUANTITY "entries" (a formula test): its table marks from LEAST to MOST entries wrong.
# The page is then screenshot in Chromium by tests/vis ("vis: problem KEY's report page ...").
#   check_mutant_page.sh GRADER REPO WORK KEY MUTANT TEST QUANTITY SHOWS|LEAST [MOST]
# Seen to fail, each branch: the reference's p2.cpp as MUTANT ("expected FAIL ..., the page says
# PASS"); 1a's table with LEAST 3 (it marks 2 of 4); problem 3 with SHOWS max (the reference's
# plotted peak force error 4.5 N passes the 1 N bound of its mean: why 3 reads apart); problem 2's
# joint-drift figure with SHOWS apart (the mutant's drift stays under the bound with the
# reference's: the test fails on the law pin alone).
set -euo pipefail
grader=$1 repo=$2 work=$3 key=$4 mutant=$5 test_name=$6 quantity=$7 shows=$8 most=${9:-}
seed=41  # any seed: the page's layout does not depend on it, and the simulated runs draw none

source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" exercises
cp "$repo"/solutions/*.cpp "$work/exercises/"
cp "$mutant" "$work/exercises/p$key.cpp"
"$grader" --unprotected --problem "$key" --exercises "$work/exercises" --seed "$seed" --html "$work/page/report.html" \
  > "$work/report.txt" 2> "$work/grader.err" ||
  fail "the grader exited with $?: $(cat "$work/report.txt" "$work/grader.err")"

page=$(tr '\n' ' ' < "$work/page/report.html")
# The page's text as the grader writes it (report_html.cpp, text()): &, <, >, " and ' escaped.
escaped() {
  # The replacements quoted: bash 5.2 reads an unquoted & in one as the matched text.
  local t=${1//&/"&amp;"}
  t=${t//</"&lt;"}
  t=${t//>/"&gt;"}
  t=${t//\"/"&quot;"}
  echo "${t//\'/"&#39;"}"
}
test_name=$(escaped "$test_name")
quantity=$(escaped "$quantity")
section=${page#*data-test=\""$key $test_name"\"}
[ "$section" != "$page" ] || fail "the page has no section for '$key $test_name'"
section=${section%%</section>*}
status=${section#*data-status=\"}
status=${status%%\"*}
[ "$status" = FAIL ] || fail "expected FAIL for '$key $test_name', the page says $status"
echo "ok   '$key $test_name' FAILed"

if [ "$quantity" = entries ]; then
  table=${section#*<table class=\"entries}
  [ "$table" != "$section" ] || fail "the test's section has no table of entries"
  table=${table%%</table>*}
  entries=$(grep -oE '<td[ >]' <<< "$table" | wc -l)
  [[ $table == " grid"* ]] || entries=$(($(grep -o '<tr' <<< "$table" | wc -l) - 1))
  # A vector's table marks its wrong rows, a matrix's grid its wrong cells.
  wrong=$(grep -oE '<t[rd] class="wrong"' <<< "$table" | wc -l)
  if [ "$wrong" -lt "$shows" ] || [ "$wrong" -gt "$most" ]; then
    fail "expected $shows to $most wrong entries in the table, it marks $wrong of $entries"
  fi
  echo "ok   its table marks $wrong of $entries entries wrong"
  exit 0
fi

figure=${section#*data-quantity=\""$quantity"\"}
[ "$figure" != "$section" ] || fail "the test's section has no figure of '$quantity'"
figure=${figure%%>*}
attribute() {
  local value=${figure#* data-"$1"=\"}
  echo "${value%%\"*}"
}
bound=$(attribute bound)
from=$(attribute from)
[ "$(attribute upper)" = 1 ] || fail "this check reads figures whose bound is an upper one"
# The extreme (max or min) of the series T (times) V (values) at or after `from`; a value that is
# not finite counts as the largest.
extreme() {
  awk -v from="$from" -v which="$1" -v times="$2" -v values="$3" 'BEGIN {
    n = split(times, t, " "); split(values, v, " "); c = 0
    for (k = 1; k <= n; ++k) if (t[k] + 0 >= from + 0) {
      x = (v[k] == "NaN" ? 1e308 : v[k] + 0)
      if (!c++ || (which == "max" ? x > m : x < m)) m = x }
    if (!c) print "none"; else printf "%.17g\n", m }'
}
student_max=$(extreme max "$(attribute student-t)" "$(attribute student-v)")
student_min=$(extreme min "$(attribute student-t)" "$(attribute student-v)")
reference_max=$(extreme max "$(attribute reference-t)" "$(attribute reference-v)")
[ "$reference_max" != none ] || fail "the figure has no reference series after $from s"
[ "$student_max" != none ] || fail "the figure has no student series after $from s"
case $shows in
  max)
    awk -v s="$student_max" -v r="$reference_max" -v b="$bound" 'BEGIN { exit !(s + 0 > b + 0 && r + 0 <= b + 0) }' ||
      fail "expected the student's largest '$quantity' after $from s past the bound $bound and the reference's within it: student $student_max, reference $reference_max"
    echo "ok   the figure: the student's largest '$quantity' after $from s is $student_max, past the bound $bound; the reference's is $reference_max"
    ;;
  apart)
    awk -v s="$student_min" -v r="$reference_max" -v b="$bound" 'BEGIN { exit !(s + 0 > b + 0 && r + 0 < s + 0) }' ||
      fail "expected every student point of '$quantity' after $from s past the bound $bound and every reference point below the student's lowest: student's lowest $student_min, reference's highest $reference_max"
    echo "ok   the figure: after $from s the student's '$quantity' stays at or above $student_min, past the bound $bound; the reference's stays at or below $reference_max"
    ;;
  judged)
    # Issue 46: the statistic the verdict used (data-verdict, the reference's data-verdict-
    # reference) is the one read off the plotted series (data-plotted: the largest value from
    # data-from on, else the last point, a running RMS or mean), to 1e-9, for both runs; the
    # student's is past the bound, the reference's within it.
    plotted=$(attribute plotted)
    read_off() {
      awk -v from="$from" -v how="$plotted" -v times="$1" -v values="$2" 'BEGIN {
        n = split(times, t, " "); split(values, v, " "); m = ""
        for (k = 1; k <= n; ++k) if (how != "largest" || t[k] + 0 >= from + 0) {
          if (how != "largest" || m == "" || v[k] + 0 > m + 0) m = v[k] }
        print m }'
    }
    same() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; s = (b < 0 ? -b : b); if (s < 1) s = 1; exit !(d <= 1e-9 * s) }'; }
    verdict=$(attribute verdict)
    verdict_reference=$(attribute verdict-reference)
    mine=$(read_off "$(attribute student-t)" "$(attribute student-v)")
    theirs=$(read_off "$(attribute reference-t)" "$(attribute reference-v)")
    same "$mine" "$verdict" || fail "the plot of '$quantity' reads $mine ($plotted), the verdict used $verdict"
    same "$theirs" "$verdict_reference" ||
      fail "the reference's plot of '$quantity' reads $theirs ($plotted), the verdict used $verdict_reference"
    awk -v s="$verdict" -v r="$verdict_reference" -v b="$bound" 'BEGIN { exit !(s + 0 > b + 0 && r + 0 <= b + 0) }' ||
      fail "expected the student's judged '$quantity' past the bound $bound and the reference's within it: $verdict, $verdict_reference"
    echo "ok   the figure: the judged '$quantity' read off the plot ($plotted) is the verdict's, $verdict past the bound $bound; the reference's $verdict_reference within it"
    ;;
  *) fail "SHOWS is max, apart or judged, not '$shows'" ;;
esac
