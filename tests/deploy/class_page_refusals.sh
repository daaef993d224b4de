#!/usr/bin/env bash
# hw2-class on folders it cannot make a page of (issue 59): a missing folder, a file, an empty
# folder and a Gradescope export not graded yet (submission_<id>/ with a student's file and no
# results.json) each make it say so on stderr and exit non-zero, writing no page (before: "class
# page of 0 student(s)", exit 0). Then a folder of one honest results.json and issue 59's hostile
# one (a run of 1e306 m shown in mm: infinite once scaled; before, the page's tick loop grew past
# 4 GiB): the page is made under 1 GiB of address space (hw2-class needs tens of MB) within the
# test's timeout, the honest student's run drawn, the hostile row noted as refused.
#   bash tests/deploy/class_page_refusals.sh BUILD WORK
set -euo pipefail
build=$1 work=$2
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
fresh_work "$work" empty export/submission_4410001 class
class=$build/apps/hw2-class

refused() {  # FOLDER WHAT
  local rc=0
  "$class" "$1" > "$work/out" 2> "$work/err" || rc=$?
  [ "$rc" -ne 0 ] || fail "hw2-class on $2 exited 0: $(cat "$work/out")"
  [ -s "$work/err" ] || fail "hw2-class on $2 exited $rc saying nothing on stderr"
  [ ! -e "$1/class.html" ] || fail "hw2-class on $2 wrote a page"
  echo "ok   $2: exit $rc, $(cat "$work/err")"
}
refused "$work/missing" "a missing folder"
touch "$work/file"
refused "$work/file" "a file"
refused "$work/empty" "an empty folder"
echo 'int main() {}' > "$work/export/submission_4410001/p1a.cpp"
printf 'submission_4410001:\n  :submitters:\n  - :name: Ann\n' > "$work/export/submission_metadata.yml"
refused "$work/export" "a Gradescope export not graded yet"

# One test of 1b failed, its run of three points in m shown in mm (class_record.hpp's fields).
results() {  # V: the run's values
  cat <<JSON
{"score": 0, "max_score": 4, "tests": [{"name": "1b iv. the run", "score": 0, "max_score": 4,
 "extra_data": {"problem": "1b", "test": "iv. the run", "mistake": "", "runs": [{"statistic": "tip error",
 "quantity": "q", "unit": "mm", "unit_scale": 1000, "bound": 0.005, "upper": true, "judged": "j",
 "judged_from": 0, "t": "0 1 2", "v": "$1", "reference_t": "0 1 2", "reference_v": "0.001 0.001 0.001"}]}}]}
JSON
}
results "0.1 0.5 0.7" > "$work/class/ann.json"
results "0.1 1e306 0.7" > "$work/class/mallory.json"
rc=0
( ulimit -v $((1 << 20)); "$class" "$work/class" ) > "$work/out" 2> "$work/err" || rc=$?
[ "$rc" -eq 0 ] || fail "hw2-class on a hostile results.json exited $rc: $(cat "$work/err")"
page=$work/class/class.html
grep -q '<div class="panel" data-group="failed, no known mistake named" data-students="1">' "$page" ||
  fail "the honest student's run is not drawn alone"
grep -q '<tr class="attention" data-student="2"><td><a class="student"[^>]*>mallory</a></td><td>[^<]*refused' "$page" ||
  grep -q '<tr class="attention" data-student="2"><td><span class="student">mallory</span></td><td>[^<]*refused' "$page" ||
  fail "the hostile row is not noted as refused"
if grep -q '<tr class="attention" data-student="1"' "$page"; then fail "the honest row is noted"; fi
echo "ok   a hostile results.json: $(cat "$work/out")"
echo "hw2-class refuses what it cannot read, saying so, and a hostile number costs its own row"
