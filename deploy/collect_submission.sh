#!/usr/bin/env bash
# Gathers a student's exercise files from a submission folder into a clean folder that the
# grader reads (hw2-grade --exercises OUT), and says what it did, one note per line, in
# OUT/notes.txt. Used by run_autograder (Gradescope) and scripts/regrade.
#
#   bash deploy/collect_submission.sh SUBMISSION OUT STUBS [UNZIP UNZIPPED]
#
# - p<key>.cpp, one per problem of problems.txt (p1a.cpp ...), are taken from the submission's
#   top folder, or from the one subfolder that holds them (a zipped folder, exercises/,
#   hw2/exercises/ ...);
# - a file that is missing is replaced by the untouched stub from STUBS: it grades 0, with a note;
# - a file with another name is not graded: the note names the expected ones; other files
#   are ignored, with a note;
# - only regular files are read: a symbolic link is refused (it could point at anything the
#   grader, which runs as root, may read), and so are files under a linked folder;
# - nothing of the submission is trusted: names are shown cleaned of control characters, at
#   most 1 MiB + 1 byte of a file is copied (the grader refuses files over 1 MiB);
# - with UNZIP (hw2-unzip, apps/unzip.cpp) and UNZIPPED (a folder that does not exist yet;
#   scripts/regrade gives them), each .zip of the submission (at most 4) is opened by UNZIP into
#   UNZIPPED/<k>, and its files are read as if they were the submission's, in a folder named
#   after the zip (hw2.zip holding hw2/ reads as a folder hw2.zip holding hw2/); a zip UNZIP
#   refuses (a link, a path leaving its folder, a zip bomb, a broken zip ...) is noted "Your zip
#   '...' was refused, not unzipped: why" and none of its files is read. Without them a .zip is
#   ignored, with the other files.
# Exit code 0 whenever OUT was written (even with every file missing).
set -euo pipefail

if [ $# -ne 3 ] && [ $# -ne 5 ]; then
  echo "usage: collect_submission.sh SUBMISSION OUT STUBS [UNZIP UNZIPPED]" >&2
  exit 2
fi
submission=$1 out=$2 stubs=$3 unzip=${4:-} unzipped=${5:-}
# The exercise files: p<key>.cpp for each problem of the list (problems.txt).
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/problems.sh"
expected=("${OPSPACE_KEYS[@]/#/p}")
expected=("${expected[@]/%/.cpp}")
expected_list=$(printf '%s, ' "${expected[@]}")
expected_list=${expected_list%, }
# is_expected NAME: NAME is one of the exercise files.
is_expected() {
  local e
  for e in "${expected[@]}"; do [ "$1" = "$e" ] && return 0; done
  return 1
}
# looks_like_exercise NAME (lower case): NAME holds an exercise file's stem (p1a_final.txt).
looks_like_exercise() {
  local e
  for e in "${expected[@]}"; do [[ "$1" == *"${e%.cpp}"* ]] && return 0; done
  return 1
}
max_bytes=$((1024 * 1024 + 1))

mkdir -p "$out"
notes="$out/notes.txt"
: > "$notes"
note() { printf '%s\n' "$*" >> "$notes"; }
# A name as the student sees it: printable ASCII only, at most 120 characters.
shown() { printf '%s' "$1" | LC_ALL=C tr -c '[:print:]' '?' | cut -c1-120; }

# Every regular file and symbolic link of the submission (find does not follow links), without
# the archivers' litter; at most 500, at most 6 folders deep.
files=()
links=()
if [ -d "$submission" ]; then
  while IFS= read -r -d '' path; do
    rel=${path#"$submission"/}
    case "/$rel" in */__MACOSX/* | */.DS_Store | */._* | */.git/*) continue ;; esac
    if [ -L "$path" ]; then links+=("$rel"); else files+=("$rel"); fi
  done < <(find "$submission" -mindepth 1 -maxdepth 6 \( -type f -o -type l \) -print0 2>/dev/null | head -z -n 500)
fi

# Each zip, opened by hw2-unzip (its limits and checks: apps/unzip.cpp) into a folder of its own;
# its files join the submission's under the zip's name, read from where they were written.
declare -A where=()
if [ -n "$unzip" ]; then
  kept=() zips=()
  for rel in "${files[@]}"; do
    lower=$(printf '%s' "$rel" | tr '[:upper:]' '[:lower:]')
    if [[ "$lower" == *.zip ]]; then zips+=("$rel"); else kept+=("$rel"); fi
  done
  files=("${kept[@]}")
  k=0
  for rel in "${zips[@]}"; do
    k=$((k + 1))
    if [ "$k" -gt 4 ]; then
      note "Your zip '$(shown "$rel")' was not opened: at most 4 zips of a submission are."
      continue
    fi
    mkdir -p "$unzipped"
    said=""
    if said=$("$unzip" "$submission/$rel" "$unzipped/$k" 2> /dev/null); then
      while IFS= read -r line; do
        [ -z "$line" ] || note "In your zip '$(shown "$rel")': $(shown "$line")"
      done <<< "$said"
      while IFS= read -r -d '' path; do
        inner="$rel/${path#"$unzipped/$k"/}"
        files+=("$inner")
        where[$inner]=$path
      done < <(find "$unzipped/$k" -mindepth 1 -maxdepth 6 -type f -print0 2>/dev/null | head -z -n 500)
    else
      note "Your zip '$(shown "$rel")' was refused, not unzipped: $(shown "$(printf '%s' "$said" | head -n 1)")."
    fi
  done
fi

# The folder holding the most expected files wins (then the shallowest): a submission made of
# one zipped folder is graded like one made of the files themselves.
best="" best_count=0 best_depth=99
declare -A count_in=()
for rel in "${files[@]}"; do
  name=${rel##*/}
  for e in "${expected[@]}"; do
    if [ "$name" = "$e" ]; then
      dir=.
      [[ "$rel" == */* ]] && dir=${rel%/*}
      count_in[$dir]=$(( ${count_in[$dir]:-0} + 1 ))
    fi
  done
done
for dir in "${!count_in[@]}"; do
  depth=$(printf '%s' "$dir" | tr -cd '/' | wc -c)
  [ "$dir" = . ] && depth=-1
  c=${count_in[$dir]}
  if [ "$c" -gt "$best_count" ] || { [ "$c" -eq "$best_count" ] && [ "$depth" -lt "$best_depth" ]; }; then
    best=$dir best_count=$c best_depth=$depth
  fi
done
if [ -n "$best" ] && [ "$best" != . ]; then
  note "Your files were found in the folder '$(shown "$best")' of your submission."
fi

used=()
for e in "${expected[@]}"; do
  source=""
  if [ -n "$best" ]; then
    candidate=$e
    [ "$best" != . ] && candidate=$best/$e
    for rel in "${files[@]}"; do [ "$rel" = "$candidate" ] && source=$rel; done
  fi
  if [ -z "$source" ]; then
    # Elsewhere in the submission: the shallowest copy.
    for rel in "${files[@]}"; do
      if [ "${rel##*/}" = "$e" ] && { [ -z "$source" ] || [ "${#rel}" -lt "${#source}" ]; }; then source=$rel; fi
    done
    [ -n "$source" ] && note "$e was taken from '$(shown "$source")'."
  fi
  if [ -n "$source" ]; then
    head -c "$max_bytes" "${where[$source]:-$submission/$source}" > "$out/$e"
    used+=("$source")
  else
    cp "$stubs/$e" "$out/$e"
    linked=""
    for rel in "${links[@]}"; do [ "${rel##*/}" = "$e" ] && linked=$rel; done
    if [ -n "$linked" ]; then
      note "$e: '$(shown "$linked")' is a symbolic link, which the grader does not follow: submit the file itself. Graded as the untouched stub (0 points)."
    else
      note "$e is missing from your submission: graded as the untouched stub (0 points)."
    fi
  fi
done

# What else was there.
wrong=() ignored=()
for rel in "${files[@]}"; do
  is_used=0
  for u in "${used[@]}"; do [ "$u" = "$rel" ] && is_used=1; done
  [ "$is_used" -eq 1 ] && continue
  name=${rel##*/}
  lower=$(printf '%s' "$name" | tr '[:upper:]' '[:lower:]')
  if is_expected "$name"; then
    ignored+=("$(shown "$rel") (another copy)")
    continue
  fi
  case "$lower" in
    *.cpp | *.cc | *.cxx | *.c++ | *.c | *.h | *.hpp | *.hh) wrong+=("$(shown "$rel")") ;;
    *) if looks_like_exercise "$lower"; then wrong+=("$(shown "$rel")"); else ignored+=("$(shown "$rel")"); fi ;;
  esac
done
for rel in "${links[@]}"; do
  is_expected "${rel##*/}" && continue
  ignored+=("$(shown "$rel") (a symbolic link)")
done
if [ ${#wrong[@]} -gt 0 ]; then
  note "Not graded, the name is not one the grader reads: $(printf "'%s' " "${wrong[@]:0:20}")(the grader reads only $expected_list: rename a file that holds your answer to a problem)."
fi
if [ ${#ignored[@]} -gt 0 ]; then
  note "Ignored (not exercise files): $(printf "'%s' " "${ignored[@]:0:20}")"
fi
if [ ${#used[@]} -eq 0 ]; then
  note "No exercise file was found in your submission: upload $expected_list (the files themselves, or one folder holding them). Every problem was graded as the untouched stub (0 points)."
fi
exit 0
