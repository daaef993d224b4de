#!/usr/bin/env bash
# hw2-class on a Gradescope export as it comes, not regraded: the page and the gradebook drawn from
# the results Gradescope stored in submission_metadata.yml (each entry's :results:, written by
# Ruby's Psych: plain keys inside, numbers plain, texts that read as numbers quoted). Six entries:
#   submission_1  a group of two, Ann and Bob: 1a 2 of 2, 1b 0 of 4 with its run: two rows, one grade
#   submission_2  Eve: hostile numbers (a score of 1e306, a test's score .nan, a run of 1e306 m,
#                 a unit's factor .inf): her row, refused and noted, counted 0 where a score
#   submission_3  Zoe: :status: failed, no :results:: not graded, saying so
#   submission_4  Mallory: "billion laughs" (an alias of an alias, 10^9 values): refused promptly
#   submission_5  Carol: results without the tests' records (name and tags only), and a :score:
#                 (5) that is not her results' (2): counted by name, the difference noted
#   submission_6  Dan: results nested 40 deep (the reader takes 32): refused
# and a folder submission_7 the metadata does not list: a row saying so. All under 1 GiB of
# address space (hw2-class needs tens of MB) within the test's timeout. The page names members,
# says its source and how many stored results carry the tests' records; gradebook.csv has a row
# per member with the export's columns.
#   bash tests/deploy/class_page_stored.sh BUILD WORK
set -euo pipefail
build=$1 work=$2
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
ex=$work/export
fresh_work "$work" export/submission_1 export/submission_7
class=$build/apps/hw2-class
[ "${OPSPACE_KEYS[*]}" = "1a 1b 2 3 4" ] || fail "problems.txt is not 1a 1b 2 3 4: update this test's gradebook rows"

# One run of test 1b iv, three points in m shown in mm (class_record.hpp's fields); V its values.
run() {
  cat <<YAML
          - statistic: tip error
            quantity: q
            unit: mm
            unit_scale: ${2:-1000}
            bound: 0.005
            upper: true
            judged: j
            judged_from: 0
            t: 0 1 2
            v: $1
            reference_t: 0 1 2
            reference_v: 0.001 0.001 0.001
YAML
}
# Results of 1a i (2 of 2) and 1b iv (0 of 4, its run); SCORE the top score, 1A_SCORE 1a's.
results() {
  cat <<YAML
  :results:
    score: $1
    max_score: 6.0
    tests:
    - name: 1a i. the mass matrix
      score: ${2:-2.0}
      max_score: 2.0
      extra_data:
        problem: 1a
        test: i. the mass matrix
        mistake: ''
    - name: 1b iv. the run
      score: 0.0
      max_score: 4.0
      extra_data:
        problem: 1b
        test: iv. the run
        mistake: ''
        runs:
$(run "${3:-0.1 0.5 0.7}" "${4:-1000}")
YAML
}
{
  echo '---'
  cat <<'YAML'
submission_1:
  :submitters:
  - :name: Lee, Ann
    :sid: '1001'
    :email: ann@example.edu
  - :name: Bob
    :sid: '1002'
    :email: bob@example.edu
  :created_at: 2026-11-30 23:58:01.000000000 -08:00
  :score: 2.0
  :status: processed
YAML
  results 2.0
  cat <<'YAML'
submission_2:
  :submitters:
  - :name: Eve
    :sid: '1003'
  :score: 2.0
  :status: processed
YAML
  results 1e306 .nan "0.1 1e306 0.7" .inf
  cat <<'YAML'
submission_3:
  :submitters:
  - :name: Zoe
    :sid: '1004'
  :status: failed
submission_4:
  :submitters:
  - :name: Mallory
    :sid: '1005'
  :score: 0.0
  :status: processed
  :results:
    a: &a [x, x, x, x, x, x, x, x, x, x]
    b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]
    c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]
    d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]
    e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]
    f: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e, *e]
    g: &g [*f, *f, *f, *f, *f, *f, *f, *f, *f, *f]
    h: &h [*g, *g, *g, *g, *g, *g, *g, *g, *g, *g]
    tests: [*h, *h, *h, *h, *h, *h, *h, *h, *h, *h]
submission_5:
  :submitters:
  - :name: Carol
    :sid: '1006'
  :score: 5.0
  :status: processed
  :results:
    score: 2.0
    tests:
    - name: 1a i. the mass matrix
      score: 2.0
      max_score: 2.0
      tags: []
submission_6:
  :submitters:
  - :name: Dan
    :sid: '1007'
  :status: processed
YAML
  printf '  :results: '
  for _ in $(seq 40); do printf '['; done  # 40: beyond the 32 levels read, far within yaml-cpp's own guard
  printf 'x'
  for _ in $(seq 40); do printf ']'; done
  printf '\n'
} > "$ex/submission_metadata.yml"

rc=0
start=$(date +%s%N)
( ulimit -v $((1 << 20)); "$class" "$ex" --out "$work" ) > "$work/out" 2> "$work/err" || rc=$?
ms=$(( ($(date +%s%N) - start) / 1000000 ))
cat "$work/out" "$work/err"
[ "$rc" -eq 0 ] || fail "hw2-class on an export with stored results exited $rc"
echo "hw2-class drew the export's stored results in $ms ms"
page=$work/class.html book=$work/gradebook.csv
cat "$book"
grep -q 'class page of 8 student(s)' "$work/out" || fail "the page does not count 8 rows (a group of 2, 5 others, a folder not listed)"
grep -q 'Built from the results Gradescope stored in submission_metadata.yml' "$page" || fail "the page does not say where its results come from"
# Records: Ann and Bob's submission and Eve's carry them; Carol's does not; the refused and missing ones are not read.
grep -q '2 of 6 submissions&#39;\? stored results carry each test&#39;\?s record\|2 of 6 submissions.s stored results carry' "$page" ||
  fail "the page does not say how many stored results carry the tests' records"
grep -q 'Lee, Ann (SID 1001, ann@example.edu)' "$page" || fail "the page does not name Ann"
grep -q 'Bob (SID 1002, bob@example.edu)' "$page" || fail "the page does not name Bob"
grep -q '<div class="panel" data-group="failed, no known mistake named" data-students="2">' "$page" ||
  fail "Ann and Bob's run is not drawn (two members), or Eve's hostile run is drawn"
attention=$(grep '<tr class="attention"' "$page")
echo "$attention"
row() { printf '%s\n' "$attention" | grep -q "$1" || fail "look first: $2"; }
row 'Eve.*its score 1e+306 refused' "Eve's score of 1e306 is not refused"
row 'Eve.*its score nan refused (not a number)' "Eve's test score .nan is not refused"
row 'Eve.*its run of tip error refused' "Eve's run is not refused"
row 'Zoe.*not graded: Gradescope stored no results for it.*status for it: failed' "Zoe's missing results and status are not said"
row 'Mallory.*not graded: its stored results were refused: more than 1048576 values' "Mallory's alias bomb is not refused"
row 'Carol.*score 5 is not its stored results.* 2' "Carol's adjusted score is not noted"
row 'Dan.*not graded: its stored results were refused: nested more than 32 deep' "Dan's nesting is not refused"
row 'submission_7.*not in submission_metadata.yml' "the folder the metadata does not list is not said"
if printf '%s\n' "$attention" | grep -q 'Ann\|Bob'; then fail "Ann or Bob needs a look"; fi
expect() { grep -qxF -- "$1" "$book" || fail "no gradebook row: $1"; }
expect "name,sid,email,submission,1a,1b,2,3,4,total,max,note"
expect "\"Lee, Ann\",1001,ann@example.edu,submission_1,2,0,,,,2,6,"
expect "Bob,1002,bob@example.edu,submission_1,2,0,,,,2,6,"
grep -q '^Eve,1003,,submission_2,0,0,,,,0,6,".*its score 1e+306 refused' "$book" || fail "Eve's row does not count 0 with its note"
grep -q '^Zoe,1004,,submission_3,,,,,,,,"not graded: Gradescope stored no results for it' "$book" || fail "Zoe's row"
grep -q '^Mallory,1005,,submission_4,,,,,,,,"not graded: its stored results were refused' "$book" || fail "Mallory's row"
grep -q '^Carol,1006,,submission_5,2,,,,,2,0,"Gradescope.s score 5 is not' "$book" || fail "Carol's row"
grep -q '^submission_7,,,submission_7,,,,,,,,"not graded: not in submission_metadata.yml' "$book" || fail "the unlisted folder's row"
[ "$(wc -l < "$book")" -eq 9 ] || fail "the gradebook is not a header and 8 rows"
echo "hw2-class drew a Gradescope export from its stored results, a row per member, each hostile entry costing its own row"
# --anonymous: a page for a lecture names nobody, and no gradebook is written beside it.
mkdir "$work/lecture"
"$class" "$ex" --anonymous --out "$work/lecture" > /dev/null 2>&1 || fail "hw2-class --anonymous on the export failed"
[ ! -e "$work/lecture/gradebook.csv" ] || fail "an anonymous page's folder holds the gradebook"
if grep -q 'Ann\|Mallory' "$work/lecture/class.html"; then fail "the anonymous page names a student"; fi
echo "ok   --anonymous: no name on the page, no gradebook"
