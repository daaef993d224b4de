#!/usr/bin/env bash
# A zip in a submission, opened as hostile (hw2-unzip, apps/unzip.cpp, through collect_submission.sh). First
# hw2-unzip alone on each hostile zip, each refused within 10 s (the reader's limit is 30 s; each
# takes well under a second) with its reason, writing nothing:
#   bomb       1 GiB of zeros deflated to about 1 MB (the bound: 64 MiB uncompressed)
#   traversal  an entry up a folder (.. then p1a.cpp);  absolute  an entry '/tmp/...';  symlink  a link to /etc/passwd
#   device     a character device entry;  many  1001 empty files (the bound: 1000)
#   corrupt    a zip cut short
# a zip holding a zip, whose inner zip is left out with a note, and a good zip extracted whole.
# Then scripts/regrade (problem 1a, two at a time) on four students: 'unzipped' (the reference's
# p1a.cpp), 'zipped' (the same file in hw2.zip, in a folder), 'bomb' and 'traversal' (the hostile
# zips, each also holding p1a.cpp elsewhere in it): zipped earns unzipped's grade; each hostile
# zip costs its own row alone (0, the note in the gradebook and "Look at these first").
#   bash tests/deploy/regrade_zips.sh REPO BUILD WORK
set -euo pipefail
repo=$1 build=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/../support/script.sh"
skip_unless_stubs_untouched
fresh_work "$work" zips in/unzipped in/zipped in/bomb in/traversal
unzip=$build/apps/hw2-unzip
[ -x "$unzip" ] || fail "no $unzip (libarchive-dev missing?)"
z=$work/zips
python3 - "$z" "$repo/solutions/p1a.cpp" <<'PY'
import io, stat, sys, zipfile
z, p1a = sys.argv[1], open(sys.argv[2]).read()
def make(name, entries):
    with zipfile.ZipFile(f"{z}/{name}.zip", "w", zipfile.ZIP_DEFLATED) as f:
        for n, d in entries: f.writestr(n, d)
def special(name, entry, mode, data):
    i = zipfile.ZipInfo(entry); i.create_system = 3; i.external_attr = mode << 16
    with zipfile.ZipFile(f"{z}/{name}.zip", "w") as f: f.writestr(i, data)
make("good", [("hw2/p1a.cpp", p1a), ("hw2/notes.txt", "mine")])
make("traversal", [("hw2/p1a.cpp", p1a), ("../p1a.cpp", p1a)])
make("absolute", [("/tmp/opspace-unzip-absolute", "x")])
special("symlink", "p1a.cpp", stat.S_IFLNK | 0o777, "/etc/passwd")
special("device", "tty", stat.S_IFCHR | 0o666, "")
make("many", [(f"f{k}", "") for k in range(1001)])
inner = io.BytesIO()
with zipfile.ZipFile(inner, "w") as f: f.writestr("p1a.cpp", p1a)
make("nested", [("inner.zip", inner.getvalue()), ("readme.txt", "x")])
good = open(f"{z}/good.zip", "rb").read()
open(f"{z}/corrupt.zip", "wb").write(good[:len(good) // 2])
with zipfile.ZipFile(f"{z}/bomb.zip", "w", zipfile.ZIP_DEFLATED, compresslevel=9) as f:
    f.writestr("hw2/p1a.cpp", p1a)
    with f.open("zeros", "w", force_zip64=True) as w:
        block = b"\0" * (1 << 24)
        for _ in range(64): w.write(block)  # 1 GiB
PY
refused() {  # NAME REASON
  local rc=0 start=$SECONDS
  "$unzip" "$z/$1.zip" "$work/out-$1" > "$work/said" 2> /dev/null || rc=$?
  [ "$rc" -eq 1 ] || fail "hw2-unzip on $1.zip exited $rc, not 1 (refused): $(cat "$work/said")"
  grep -q "$2" "$work/said" || fail "hw2-unzip on $1.zip did not say '$2': $(cat "$work/said")"
  [ ! -e "$work/out-$1" ] || fail "hw2-unzip on $1.zip left its folder"
  [ $((SECONDS - start)) -le 10 ] || fail "hw2-unzip on $1.zip took $((SECONDS - start)) s"
  echo "ok   $1.zip refused in $((SECONDS - start)) s: $(cat "$work/said")"
}
refused bomb "more than 64 MiB uncompressed"
refused traversal "leaves the folder: '../p1a.cpp'"
refused absolute "is absolute"
refused symlink "symbolic link: 'p1a.cpp'"
refused device "neither a file nor a folder"
refused many "more than 1000 entries"
refused corrupt "not a zip it can read"
[ ! -e /tmp/opspace-unzip-absolute ] || fail "the absolute entry was written"
"$unzip" "$z/nested.zip" "$work/out-nested" > "$work/said" || fail "hw2-unzip refused nested.zip: $(cat "$work/said")"
grep -q "'inner.zip' is a zip inside the zip: not opened" "$work/said" || fail "the inner zip is not noted"
[ -f "$work/out-nested/readme.txt" ] && [ ! -e "$work/out-nested/inner.zip" ] || fail "nested.zip's inner zip was written, or its file was not"
"$unzip" "$z/good.zip" "$work/out-good" > "$work/said" || fail "hw2-unzip refused good.zip: $(cat "$work/said")"
cmp -s "$work/out-good/hw2/p1a.cpp" "$repo/solutions/p1a.cpp" || fail "good.zip's p1a.cpp is not the file zipped"
echo "ok   nested.zip: its inner zip left out, noted; good.zip extracted whole"

# The regrade: a zipped submission grades as the unzipped one, a hostile zip costs its own row.
cp "$repo/solutions/p1a.cpp" "$work/in/unzipped/"
cp "$z/good.zip" "$work/in/zipped/hw2.zip"
cp "$z/bomb.zip" "$work/in/bomb/hw2.zip"
cp "$z/traversal.zip" "$work/in/traversal/hw2.zip"
bash "$repo/scripts/regrade" "$work/in" "$work/out" --jobs 2 -- --problem 1a --timeout 60 2> "$work/regrade.err" ||
  { cat "$work/regrade.err"; fail "regrade failed"; }
book=$work/out/gradebook.csv
cat "$book"
p=${OPSPACE_POINTS[0]}
[ "${OPSPACE_KEYS[0]}" = 1a ] || fail "problems.txt does not begin with 1a: update this test"
grep -q "^unzipped,$p,.*,$p,$p,$" "$book" || fail "the unzipped submission does not earn $p of $p"
grep -q "^zipped,$p,.*,$p,$p,$" "$book" || fail "the zipped submission does not earn the unzipped one's $p of $p"
grep -q "^bomb,0,.*,0,$p,\"Your zip 'hw2.zip' was refused, not unzipped: more than 64 MiB uncompressed" "$book" ||
  fail "the zip bomb's row is not 0 with its note"
grep -q "^traversal,0,.*,0,$p,\"Your zip 'hw2.zip' was refused, not unzipped: an entry's path leaves the folder" "$book" ||
  fail "the traversal's row is not 0 with its note"
[ ! -e "$work/out/traversal/p1a.cpp" ] && [ ! -e "$work/out/traversal/unzipped/p1a.cpp" ] || fail "the traversal wrote its file"
grep -q "Your files were found in the folder 'hw2.zip/hw2'" "$work/out/zipped/report.txt" || fail "the zipped report does not say where its files were"
attention=$(grep '<tr class="attention"' "$work/out/class.html")
echo "$attention"
[ "$(printf '%s\n' "$attention" | wc -l)" -eq 2 ] || fail "Look at these first is not the two hostile zips alone"
printf '%s\n' "$attention" | grep -q '>bomb<.*Your zip &#39;hw2.zip&#39; was refused' || fail "the bomb is not in Look at these first"
printf '%s\n' "$attention" | grep -q '>traversal<.*Your zip &#39;hw2.zip&#39; was refused' || fail "the traversal is not in Look at these first"
echo "a zipped submission grades as unzipped; each hostile zip is refused promptly and costs its own row"
