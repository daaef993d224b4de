#!/usr/bin/env bash
# scripts/regrade on a Gradescope export as it comes (issue 59): submission_<id>/ folders and
# submission_metadata.yml (Ruby-symbol keys, as Gradescope writes them). Problem 1a alone, two
# at a time, the reference's p1a.cpp:
#   4410001  a group of two, "Lee, Ann" and Bob "Bobby" Tables: two rows, the same full grade
#   4410002  Zoë Ünïcode, the file in a subfolder (as a zipped folder unpacks: regrade reads no .zip)
#   4410003  <b>Eve</b>: p1a.cpp missing, the answer in p1a_final.cpp (misnamed): 0
#   4410004  =HYPERLINK("x"): a p1a.cpp that does not compile: 0
# The gradebook has one row per member (name,sid,email,submission, the problems, total, max,
# note), every name escaped; the class page names the members and puts Eve (missing, misnamed)
# and the formula (did not compile) at the top, alone. Then a malformed metadata file: regrade
# stops before grading, naming the file and the line.
#   bash tests/deploy/gradescope_export.sh REPO WORK
set -euo pipefail
repo=$1 work=$2
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
skip_unless_stubs_untouched
ex=$work/export
fresh_work "$work" export/submission_4410001 export/submission_4410002/hw2 export/submission_4410003 \
  export/submission_4410004 bad/submission_1
cp "$repo/solutions/p1a.cpp" "$ex/submission_4410001/"
cp "$repo/solutions/p1a.cpp" "$ex/submission_4410002/hw2/"
cp "$repo/solutions/p1a.cpp" "$ex/submission_4410003/p1a_final.cpp"
sed 's/^Eigen::Matrix2d mass_matrix(double m1, double m2) {$/&\n  this does not compile;/' "$repo/solutions/p1a.cpp" > "$ex/submission_4410004/p1a.cpp"
grep -q 'this does not compile' "$ex/submission_4410004/p1a.cpp" || { echo "solutions/p1a.cpp changed: update this test"; exit 1; }
cat > "$ex/submission_metadata.yml" <<'YAML'
---
submission_4410001:
  :submitters:
  - :name: Lee, Ann
    :sid: '1001'
    :email: ann@example.edu
  - :name: Bob "Bobby" Tables
    :sid: 1002
    :email: bob@example.edu
  :created_at: 2026-11-30 23:58:01.000000000 -08:00
  :score: 0.0
  :status: processed
submission_4410002:
  :submitters:
  - :name: "Zoë Ünïcode"
    :sid: '1003'
    :email: zoe@example.edu
  :created_at: 2026-11-30 22:00:00.000000000 -08:00
submission_4410003:
  :submitters:
  - :name: "<b>Eve</b>"
    :sid: '1004'
    :email: eve@example.edu
submission_4410004:
  :submitters:
  - :name: =HYPERLINK("x")
    :sid: '1005'
    :email: mallory@example.edu
YAML

bash "$repo/scripts/regrade" "$ex" "$work/out" --jobs 2 -- --problem 1a --timeout 60 2> "$work/regrade.err" ||
  { cat "$work/regrade.err"; exit 1; }
cat "$work/regrade.err"
cat "$work/out/gradebook.csv"
keys=$(IFS=,; echo "${OPSPACE_KEYS[*]}")
full=$(IFS=,; echo "${OPSPACE_POINTS[*]}")
zeros=${full//[0-9]/}
zeros=${zeros//,/0,}0
others=${zeros#0,}
others=${others//0/}
p=${OPSPACE_POINTS[0]}
[ "${OPSPACE_KEYS[0]}" = 1a ] || { echo "problems.txt does not begin with 1a: update this test"; exit 1; }
book=$work/out/gradebook.csv
expect() { grep -qxF -- "$1" "$book" || { echo "no gradebook row: $1"; exit 1; }; }
expect "name,sid,email,submission,$keys,total,max,note"
expect "\"Lee, Ann\",1001,ann@example.edu,submission_4410001,$p,$others,$p,$p,"
expect "\"Bob \"\"Bobby\"\" Tables\",1002,bob@example.edu,submission_4410001,$p,$others,$p,$p,"
expect "\"Zoë Ünïcode\",1003,zoe@example.edu,submission_4410002,$p,$others,$p,$p,"
expect "<b>Eve</b>,1004,eve@example.edu,submission_4410003,0,$others,0,$p,"
expect "\"'=HYPERLINK(\"\"x\"\")\",1005,mallory@example.edu,submission_4410004,0,$others,0,$p,"
rows=$(grep -vc '^UNPROTECTED,' "$book")
[ "$rows" -eq 6 ] || { echo "the gradebook has $rows lines, not a header and 5 rows"; exit 1; }

# The class page: the members by name, escaped; a group's two each with the grade.
page=$work/out/class.html
"$repo/build/release/apps/hw2-class" "$work/out" --out "$work" > "$work/class.out"
grep -qx "class page of 5 student(s): .*" "$work/class.out" || { cat "$work/class.out"; echo "the page does not count 5 students"; exit 1; }
grep -q 'Lee, Ann (SID 1001, ann@example.edu)' "$page" || { echo "the page does not name Ann from the metadata"; exit 1; }
grep -q 'Bob &quot;Bobby&quot; Tables (SID 1002' "$page" || { echo "the page does not name Bob, escaped"; exit 1; }
grep -q 'Zoë Ünïcode (SID 1003' "$page" || { echo "the page does not name Zoë"; exit 1; }
grep -q '&lt;b&gt;Eve&lt;/b&gt;' "$page" || { echo "the page does not name Eve, escaped"; exit 1; }
if grep -q '<b>Eve' "$page"; then echo "a student's name is markup on the page"; exit 1; fi
if grep -q '>submission_44100' "$page"; then echo "the page names a submission's folder instead of its members"; exit 1; fi
# Look at these first: Eve (missing and misnamed) and the formula (did not compile), no one else.
attention=$(grep '<tr class="attention"' "$page")
echo "$attention"
[ "$(printf '%s\n' "$attention" | wc -l)" -eq 2 ] || { echo "the look-first list is not Eve and the formula alone"; exit 1; }
printf '%s\n' "$attention" | grep -q 'Eve.*missing, graded as the stub: p1a\.cpp<br>misnamed, not graded: .*p1a_final\.cpp' ||
  { echo "the look-first list does not say Eve's p1a.cpp is missing and p1a_final.cpp misnamed"; exit 1; }
printf '%s\n' "$attention" | grep -q 'HYPERLINK.*did not compile: problem 1a' ||
  { echo "the look-first list does not say the formula's p1a.cpp did not compile"; exit 1; }
if printf '%s\n' "$attention" | grep -q 'HYPERLINK.*interrupted'; then echo "a compile error is told as interrupted tests"; exit 1; fi
echo "regrade named the export's rows from its metadata, a row per member, and listed what to look at first"

# A malformed metadata file: no grading, the file and the line said.
cp "$repo/solutions/p1a.cpp" "$work/bad/submission_1/"
printf 'submission_1:\n  :submitters:\n  - :name: [Ann\n    :sid: 1\n' > "$work/bad/submission_metadata.yml"
code=0
bash "$repo/scripts/regrade" "$work/bad" "$work/bad-out" --jobs 1 -- --problem 1a 2> "$work/bad.err" || code=$?
cat "$work/bad.err"
[ "$code" -eq 2 ] || { echo "regrade exited $code on a malformed metadata file, not 2"; exit 1; }
grep -qE 'submission_metadata\.yml:[0-9]+: not YAML' "$work/bad.err" || { echo "the error does not name the file and its line"; exit 1; }
[ ! -e "$work/bad-out/submission_1" ] || { echo "regrade graded before reading the metadata"; exit 1; }
printf 'submission_1:\n  :submitters: Ann\n' > "$work/bad/submission_metadata.yml"
code=0
bash "$repo/scripts/regrade" "$work/bad" "$work/bad-out" --jobs 1 -- --problem 1a 2> "$work/bad.err" || code=$?
grep -q 'submission_metadata\.yml:2: submission_1: :submitters: is not a list' "$work/bad.err" ||
  { cat "$work/bad.err"; echo "a metadata file of the wrong shape is not told with its line"; exit 1; }
echo "a malformed metadata file stopped regrade with its file and line"
