#!/usr/bin/env bash
# scripts/regrade on three students, two at a time: alice (the untouched stubs), bob (the
# reference, in a subfolder), carol (the reference, but 1a's mass_matrix spins forever). The
# grader's per-test limit is 60 s (--timeout 60: over a hundred times the longest reference test;
# 20 s was once too short for the reference's problem 3, in the fresh-Debian check at nice 19
# beside CI) and problem 1a's own is 5 s (--timeout 1a=5: 1a's tests are a few 2x2 products, a
# millisecond each); it stops the two tests of 1a that call mass_matrix (ii, 3 points; vi's
# split, 2 points: the reference's split_displacement calls its own mass_matrix) while alice and
# bob are graded. The gradebook has alice 0, bob full marks, carol 1a = 23 - 5 = 18 and the rest
# full. Then carol alone with --limit 6: the watchdog stops her whole grading, and her row and
# results.json say so.
#   bash tests/deploy/regrade.sh REPO WORK
set -euo pipefail
repo=$1 work=$2
check="$repo/tests/deploy/check_json.cmake"
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
skip_unless_stubs_untouched
fresh_work "$work" in/alice in/bob/hw2 in/carol in2/carol
cp "$repo"/exercises/p*.cpp "$work/in/alice/"
cp "$repo"/solutions/p*.cpp "$work/in/bob/hw2/"
cp "$repo"/solutions/p*.cpp "$work/in/carol/"
# A volatile counter: the compiler may not assume the loop ends.
sed -i 's/^Eigen::Matrix2d mass_matrix(double m1, double m2) {$/&\n  for (volatile unsigned long spin = 0;; spin = spin + 1) {\n  }/' "$work/in/carol/p1a.cpp"
grep -q 'volatile unsigned long spin' "$work/in/carol/p1a.cpp" || { echo "solutions/p1a.cpp changed: update this test"; exit 1; }
cp "$work"/in/carol/* "$work/in2/carol/"

start=$(date +%s)
bash "$repo/scripts/regrade" "$work/in" "$work/out" --jobs 2 -- --timeout 60 --timeout 1a=5 2> "$work/regrade.err"
cat "$work/regrade.err"
echo "regrade of 3 students: $(( $(date +%s) - start )) s"
grep -q 'regrade: 3/3 done' "$work/regrade.err" || { echo "no progress line"; exit 1; }
cat "$work/out/gradebook.csv"
# The rows from the list (problems.txt): each problem's points, the total. Carol loses 1a's two
# tests that call mass_matrix, 5 points; 1a is the list's first problem.
[ "${OPSPACE_KEYS[0]}" = 1a ] || { echo "problems.txt does not begin with 1a: update this test"; exit 1; }
keys=$(IFS=,; echo "${OPSPACE_KEYS[*]}")
full=$(IFS=,; echo "${OPSPACE_POINTS[*]}")
zeros=${full//[0-9]/}
zeros=${zeros//,/0,}0
carol="$((OPSPACE_POINTS[0] - 5)),${full#*,},$((OPSPACE_TOTAL - 5))"
grep -qx "student,$keys,total,max,note" "$work/out/gradebook.csv"
grep -qx "alice,$zeros,0,$OPSPACE_TOTAL," "$work/out/gradebook.csv"
grep -qx "bob,$full,$OPSPACE_TOTAL,$OPSPACE_TOTAL," "$work/out/gradebook.csv"
grep -qx "carol,$carol,$OPSPACE_TOTAL," "$work/out/gradebook.csv"
for s in alice bob carol; do
  [ -s "$work/out/$s/report.txt" ] || { echo "no report for $s"; exit 1; }
done
cmake -DJSON="$work/out/bob/results.json" -DFULL=ALL "-DOUTPUT=found in the folder 'hw2'" -P "$check"
cmake -DJSON="$work/out/carol/results.json" "-DFULL=$(IFS=';'; echo "${OPSPACE_KEYS[*]:1}")" -P "$check"
grep -qE 'did not answer within (5 s|25 s of waiting)' "$work/out/carol/report.txt" || { echo "carol's report does not say she hung (within 1a's 5 s)"; exit 1; }
# The class page (issue 49) puts carol at the top, alone: her two tests interrupted by the time-out.
grep -q '<tr class="attention" data-student="3">.*2 test(s) interrupted' "$work/out/class.html" ||
  { echo "the class page does not put carol's two interrupted tests at the top"; exit 1; }
[ "$(grep -c '<tr class="attention"' "$work/out/class.html")" -eq 1 ] || { echo "the class page flags others than carol"; exit 1; }

bash "$repo/scripts/regrade" "$work/in2" "$work/out2" --jobs 1 --limit 6 -- --timeout 30 2> "$work/regrade2.err"
cat "$work/out2/gradebook.csv"
grep -q "^carol,${zeros//0/},0,,\"not graded: see the report\"\$" "$work/out2/gradebook.csv"
grep -q 'grading took more than 6 s and was stopped' "$work/out2/carol/report.txt"
cmake -DJSON="$work/out2/carol/results.json" -DEMPTY=ON "-DOUTPUT=grading took more than 6 s" -P "$check"
grep -q '<tr class="attention" data-student="1">.*not graded: grading took more than 6 s and was stopped' "$work/out2/class.html" ||
  { echo "the class page does not put carol, not graded, at the top"; exit 1; }
echo "regrade graded the stub, the reference and the hanging submission without stalling"

# Issue 38: a student's folder name and prints decide nothing but their own grade. Problem 1a
# alone, two at a time: folders named "=cmd|' -C calc'!A0" (a formula, OWASP's example) and
# "evil<line feed>name,0,0" (a new row) hold the untouched stub, and printer holds the
# reference, whose mass_matrix prints "errno 11 Resource temporarily unavailable": the retry
# that grepped report.txt graded printer again, with a new seed. The gradebook has one line per
# student, no field that begins with = + - @, and nobody graded again.
formula="=cmd|' -C calc'!A0"
newline=$'evil\nname,0,0'
mkdir -p "$work/in3/$formula" "$work/in3/$newline" "$work/in3/printer"
cp "$repo/exercises/p1a.cpp" "$work/in3/$formula/"
cp "$repo/exercises/p1a.cpp" "$work/in3/$newline/"
cp "$repo/solutions/p1a.cpp" "$work/in3/printer/"
sed -i -e '1i #include <cstdio>' \
  -e 's/^Eigen::Matrix2d mass_matrix(double m1, double m2) {$/&\n  std::printf("errno 11 Resource temporarily unavailable\\n");\n  std::fflush(stdout);/' \
  "$work/in3/printer/p1a.cpp"
grep -q 'errno 11' "$work/in3/printer/p1a.cpp" || { echo "solutions/p1a.cpp changed: update this test"; exit 1; }
bash "$repo/scripts/regrade" "$work/in3" "$work/out3" --jobs 2 -- --problem 1a --timeout 60 2> "$work/regrade3.err" ||
  { cat "$work/regrade3.err"; exit 1; }
cat "$work/regrade3.err"
cat -A "$work/out3/gradebook.csv"
rows=$(grep -vc '^UNPROTECTED,' "$work/out3/gradebook.csv")
[ "$rows" -eq 4 ] || { echo "the gradebook has $rows lines, not a header and 3 rows"; exit 1; }
# Problem 1a alone: its column, then the others' empty ones.
others=${zeros#0,}
others=${others//0/}
points_1a=${OPSPACE_POINTS[0]}
grep -qx "\"'=cmd|' -C calc'!A0\",0,$others,0,$points_1a," "$work/out3/gradebook.csv" || { echo "the formula's row is not neutralised"; exit 1; }
grep -qx "\"evil\\\\nname,0,0\",0,$others,0,$points_1a," "$work/out3/gradebook.csv" || { echo "the line feed's row is not one quoted field"; exit 1; }
grep -qx "printer,$points_1a,$others,$points_1a,$points_1a," "$work/out3/gradebook.csv" || { echo "printer did not keep 1a's $points_1a points"; exit 1; }
if cut -d, -f1 "$work/out3/gradebook.csv" | grep -q '^[-=+@]'; then echo "a field begins with = + - or @"; exit 1; fi
grep -q 'errno 11 Resource temporarily unavailable' "$work/out3/printer/report.txt" ||
  { echo "printer's print is not in the report (the bait this case needs)"; exit 1; }
if grep -q 'again' "$work/regrade3.err" "$work/out3/printer/report.txt"; then
  echo "a print of the student's made regrade grade printer again"
  exit 1
fi
# The retry reads the grader's own record: its faults and its seed (deploy/grader_status.cmake).
printf '{"extra_data": {"grader": {"seed": 77, "grader_faults": 1}}}' > "$work/faulty.json"
printf '{"extra_data": {"grader": {"seed": 77, "grader_faults": 0}}}' > "$work/clean.json"
[ "$(cmake -DJSON="$work/faulty.json" -P "$repo/deploy/grader_status.cmake")" = 77 ] || { echo "a grader fault is not retried"; exit 1; }
[ -z "$(cmake -DJSON="$work/clean.json" -P "$repo/deploy/grader_status.cmake")" ] || { echo "a clean grading is retried"; exit 1; }
echo "regrade kept the names out of the gradebook's formulas and rows, and a print out of its retry"
