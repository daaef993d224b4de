#!/usr/bin/env bash
# The class page (issue 49), from one regrade of a small synthetic class: scripts/synthetic-class
# --shared-files 12 7 writes the reference, the stubs, each of the six files of tests/mutants/ alone in the
# reference and four random mixes (seed 7: every mutant made by at least one student, three
# of them by two or three); the reference's folder is renamed "<script>alert(1)" and the
# stubs' "<img src=x onerror=alert(2)>" (a name is the student's text). Then:
#  1. OUT/class.html and OUT/mistakes.csv count each known mistake exactly as the manifest made
#     it, on their data (check_class_page.cmake), and show the names as escaped text;
#  2. hw2-class --anonymous on the same OUT: the same counts, and no name in any form;
#  3. the page rebuilt by hw2-class from a folder holding only the students' results.json (a
#     Gradescope export) is the regrade's page, but for the links to report.txt it cannot have;
#  4. regrade --anonymous itself, on two of the students and problem 1a alone (runners cached):
#     its page names neither.
# tests/vis's "vis: the class page ..." opens OUT/class.html in Chromium (this test is its fixture).
#   bash tests/deploy/class_page.sh REPO BUILD WORK
set -euo pipefail
repo=$1 build=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
skip_unless_stubs_untouched
fresh_work "$work"
bash "$repo/scripts/synthetic-class" --shared-files "$work/in" 12 7 "$work/manifest"
script='<script>alert(1)' img='<img src=x onerror=alert(2)>'
mv "$work/in/learner-001" "$work/in/$script"
mv "$work/in/learner-002" "$work/in/$img"
sed -i -e "s/^learner-001 /$script /" -e "s/^learner-002 /$img /" "$work/manifest"
# The catalogue's name of each file's mistake (the header of each file of tests/mutants/ says which).
mistakes=(
  "p1a_mass_no_coupling.cpp=A without the coupling term: m2 left off the diagonal"
  "p1b_part3_pinv.cpp=PART3 projects with the pseudo-inverse, like PART2"
  "p2_E_pinv_at_lambda_d.cpp=E^+ evaluated at lambda_d instead of the current lambda"
  "p2_no_feedforward.cpp=no feed-forward acceleration [vdot_d; wdot_d]"
  "p3_force_times_lambda.cpp=the desired force multiplied by Lambda0 (treated as an acceleration)"
  "p4_potentials_swapped.cpp=the Z0 and Y0 potentials swapped"
)
[ "$(ls "$repo"/tests/mutants/p*_*.cpp | wc -l)" -eq ${#mistakes[@]} ] || { echo "tests/mutants/ changed: update this test's list"; exit 1; }
list=$(IFS=';'; echo "${mistakes[*]}")
names=$(sed 's/ [^ ]* [^ ]*$//' "$work/manifest" | sort -u | tr '\n' ';')
check() { cmake "-DMISTAKES=$list" "-DNAMES=${names%;}" -DMANIFEST="$work/manifest" "$@" -P "$repo/tests/deploy/check_class_page.cmake"; }

start=$(date +%s)
bash "$repo/scripts/regrade" "$work/in" "$work/out" --jobs 2 -- --timeout 60 2> "$work/regrade.err" || { cat "$work/regrade.err"; exit 1; }
echo "regrade of 12 students: $(( $(date +%s) - start )) s"
cat "$work/out/mistakes.csv"
echo "1. the regrade's page and mistakes.csv"
check -DPAGE="$work/out/class.html" -DCSV="$work/out/mistakes.csv"

echo "2. the anonymous page"
mkdir -p "$work/anonymous"
"$build/apps/hw2-class" "$work/out" --anonymous --out "$work/anonymous"
# Each name holds "learner-" or "alert", in any of its forms.
check -DPAGE="$work/anonymous/class.html" -DCSV="$work/anonymous/mistakes.csv" -DANONYMOUS=ON "-DFORBIDDEN=learner-;alert"
grep -q '>student 12<' "$work/anonymous/class.html" || { echo "the anonymous page does not number the students"; exit 1; }

echo "3. the page from the results.json files alone"
while IFS= read -r -d '' json; do
  student=${json%/results.json} student=${student##*/}
  mkdir -p "$work/export/$student"
  cp "$json" "$work/export/$student/"
done < <(find "$work/out" -mindepth 2 -maxdepth 2 -name results.json -print0)
"$build/apps/hw2-class" "$work/export"
sed -E 's#<a class="student" href="[^"]*">([^<]*)</a>#<span class="student">\1</span>#g' "$work/out/class.html" > "$work/unlinked.html"
cmp "$work/unlinked.html" "$work/export/class.html" || { diff "$work/unlinked.html" "$work/export/class.html" | head -20; exit 1; }
cmp "$work/out/mistakes.csv" "$work/export/mistakes.csv"
grep -q 'href="%3Cscript%3Ealert%281%29/report.txt"' "$work/out/class.html" || { echo "no link to the report of '$script'"; exit 1; }

echo "4. regrade --anonymous"
mkdir -p "$work/in2"
cp -r "$work/in/$script" "$work/in/learner-003" "$work/in2/"
bash "$repo/scripts/regrade" "$work/in2" "$work/out2" --jobs 2 --anonymous -- --problem 1a --timeout 60 2> "$work/regrade2.err" ||
  { cat "$work/regrade2.err"; exit 1; }
for name in learner- alert; do
  if grep -qF "$name" "$work/out2/class.html" "$work/out2/mistakes.csv"; then echo "regrade --anonymous names '$name'"; exit 1; fi
done
grep -q '^1,"1a","A without the coupling term: m2 left off the diagonal",1,.*"student 2"$' "$work/out2/mistakes.csv" ||
  { cat "$work/out2/mistakes.csv"; echo "regrade --anonymous: learner-003's 1a mistake is not student 2's"; exit 1; }
echo "the class page counts each mistake exactly, escapes the names, hides them when anonymous, and comes from results.json alone"
