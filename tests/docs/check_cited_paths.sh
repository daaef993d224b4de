#!/usr/bin/env bash
# Every repository path cited in a comment or a doc exists, so that a moved or removed file
# leaves no stale reference behind (docs/architecture.md, "Where each file lives").
#
#   bash tests/docs/check_cited_paths.sh [ROOT]      (ROOT: the repository, by default this one)
#
# It reads the comments of the C++, JavaScript, CMake and shell files (and of the other files
# whose comments start with #) and the whole text of the Markdown pages, among the files git
# tracks (or, outside a git checkout, every file but build/, out/ and web/node_modules/).
# A cited path is a word of path characters, and it is checked three ways:
#   - from the top: a word that starts with a top-level folder (lib/src/math/spatial.hpp,
#     docs/grader.md, scripts/regrade, .ci/run) or is a top-level file (problems.txt) names a
#     file or folder of the repository, or a program built from a .cpp of the same name
#     (bench/bench_control); a :line or #anchor after it is not part of it;
#   - a relative link of a Markdown page ([grader.md](grader.md#adding-a-problem)) names a
#     file or folder from the page's folder;
#   - a partial path to a source or a doc (math/spatial.hpp, <opspace/algorithms/dynamics.hpp>)
#     is the end of a repository path, or names one from the citing file's folder
#     (../support/script.sh).
# A word with a placeholder or a pattern is no path: problems/<key>/, *.cpp, {1b,2}, $VAR, @VAR@,
# "..."; nor is a path in another tree, written after a colon as git writes a file of a commit
# (sai2-model:tests/Tests_SaiModel.cpp); nor what git ignores (build/, out/, web/node_modules/),
# an absolute path, or a relative one that climbs out of the repository. A few paths are made:
# what scripts/handout writes into a handout (below, "made" and "placed").
#
# A student handout (scripts/handout) leaves out the reference, the instructor's pages and
# tools, which the comments it keeps still cite: there (no solutions/) the check says SKIPPED.
set -euo pipefail

root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
cd "$root"
if [ ! -d solutions ]; then
  echo "SKIPPED: $root has no solutions/: a student handout leaves out files its comments cite"
  exit 0
fi

list=$(mktemp)
trap 'rm -f "$list"' EXIT
if [ "$(git rev-parse --show-toplevel 2>/dev/null || true)" = "$(pwd -P)" ]; then
  # Tracked files and new ones not yet added (but not ignored ones), as they are on disk.
  git ls-files -z --cached --others --exclude-standard | tr '\0' '\n' | sort -u |
    while IFS= read -r f; do [ -f "$f" ] && printf '%s\n' "$f"; done > "$list"
else
  find . \( -path ./.git -o -path ./build -o -path ./out -o -path ./web/node_modules \) -prune \
    -o -type f -print | sed 's|^\./||' | sort > "$list"
fi

# The top-level folders (those of the files found count too) and files.
folders="lib exercises solutions robots tests docs apps bench scripts web grader problems deploy"
awk -v top_folders="$folders .ci .devcontainer" \
    -v top_files="README.md CMakeLists.txt CMakePresets.json problems.txt" '
# The repository: its files, their folders, and for the partial paths every end of a path.
{
  have[$0] = 1
  path = $0
  while ((slash = index(path, "/")) > 0) {
    ends[path] = 1
    path = substr(path, slash + 1)
  }
  ends[path] = 1
  n = split($0, part, "/")
  dir = ""
  for (i = 1; i < n; i++) {
    dir = (i == 1) ? part[1] : dir "/" part[i]
    have[dir] = 1
    top[part[1]] = 1
  }
  files[++nfiles] = $0
}
END {
  split(top_folders, t, " ")
  for (i in t) top[t[i]] = 1
  split(top_files, t, " ")
  for (i in t) top_file[t[i]] = 1
  # Made: what scripts/handout writes into a handout: the recorded suite, and the summaries of
  # the reference runs (which the build writes too, in its apps/reference/).
  make("grader/suite/visible/suite.txt")
  make("apps/reference/reference_runs.hpp")
  # Placed: the files of deploy/handout/ are read where scripts/handout copies them.
  placed["deploy/handout/README.md"] = ""
  placed["deploy/handout/grader.md"] = "docs"
  placed["deploy/handout/replay_suite.cpp"] = "grader/suite"
  placed["deploy/handout/recorded.hpp"] = "grader/suite"
  placed["deploy/handout/no_catalogue.cpp"] = "grader/suite"
  for (k = 1; k <= nfiles; k++) scan(files[k])
  if (missing) {
    printf "%d cited path(s) name no file of the repository: ", missing
    printf "point them at the real file, or reword\n"
    exit 1
  }
  printf "all %d repository paths cited in the comments and docs of %d files exist\n", checked, scanned
}

function make(path,   n, part, i, dir) {
  have[path] = ends[path] = 1
  n = split(path, part, "/")
  dir = part[1]
  for (i = 2; i < n; i++) { have[dir] = 1; dir = dir "/" part[i] }
  have[dir] = 1
  while ((i = index(path, "/")) > 0) { path = substr(path, i + 1); ends[path] = 1 }
}

function kind_of(f,   base, first) {
  base = f
  sub(/.*\//, "", base)
  if (f ~ /\.md$/) return "md"
  if (f ~ /\.(cpp|hpp|h|inc|cpp\.in|js|mjs)$/) return "slash"
  if (f ~ /\.(cmake|sh|dict|in)$/ || base == "CMakeLists.txt" || base == "problems.txt" ||
      base == "Dockerfile" || base ~ /^\.git(ignore|attributes)$/ || base == ".dockerignore")
    return "hash"
  if (base !~ /\./) {
    first = ""
    getline first < f
    close(f)
    if (first ~ /^#!.*(ba)?sh/) return "hash"
  }
  return ""
}

function scan(f,   kind, line, lineno, text, dir) {
  kind = kind_of(f)
  if (kind == "") return
  scanned++
  if (f in placed) dir = placed[f]
  else {
    dir = f
    if (!sub(/\/[^\/]*$/, "", dir)) dir = ""
  }
  in_block = 0
  fence = 0
  lineno = 0
  while ((getline line < f) > 0) {
    lineno++
    if (kind == "md") {
      text = line
      if (line ~ /^ *(```|~~~)/) fence = !fence
      else if (!fence) links(f, lineno, dir, line)
    } else if (kind == "slash") text = slash_comment(line)
    else text = hash_comment(line)
    if (text != "") words(f, lineno, dir, text)
  }
  close(f)
}

# The comment text of a line of C++ or JavaScript: after //, or inside /* */ (across lines).
function slash_comment(line,   out, i, n, c, q, j) {
  if (!in_block && index(line, "//") == 0 && index(line, "/*") == 0) return ""
  out = ""
  q = ""
  n = length(line)
  i = 1
  while (i <= n) {
    if (in_block) {
      j = index(substr(line, i), "*/")
      if (j == 0) return out " " substr(line, i)
      out = out " " substr(line, i, j - 1)
      i += j + 1
      in_block = 0
      continue
    }
    c = substr(line, i, 1)
    if (q != "") {
      if (c == "\\") i++
      else if (c == q) q = ""
      i++
      continue
    }
    if (c == "\"" || c == "`") q = c
    else if (c == "'\''" && substr(line, i - 1, 1) !~ /[0-9A-Za-z]/) q = c
    else if (c == "/" && substr(line, i + 1, 1) == "/") return out " " substr(line, i + 2)
    else if (c == "/" && substr(line, i + 1, 1) == "*") { in_block = 1; i++ }
    i++
  }
  return out
}

# The comment text of a line of CMake or shell: after a # that starts a word, outside quotes.
function hash_comment(line,   i, n, c, q) {
  if (index(line, "#") == 0) return ""
  q = ""
  n = length(line)
  for (i = 1; i <= n; i++) {
    c = substr(line, i, 1)
    if (q != "") {
      if (c == "\\" && q == "\"") i++
      else if (c == q) q = ""
      continue
    }
    if (c == "\"" || c == "'\''") q = c
    else if (c == "#" && (i == 1 || substr(line, i - 1, 1) ~ /[ \t(]/)) return substr(line, i + 1)
  }
  return ""
}

# A Markdown link to a relative path: [text](path) or [text](path#anchor), from the page.
function links(f, lineno, dir, line,   rest, target) {
  rest = line
  while (match(rest, /\]\([^)]*\)/)) {
    target = substr(rest, RSTART + 2, RLENGTH - 3)
    rest = substr(rest, RSTART + RLENGTH)
    sub(/#.*/, "", target)
    # Not a URL (https:, mailto:), an absolute path, a pattern, nor (x, y) after brackets.
    if (target == "" || target ~ /^[a-z]+:/ || target ~ /^\// || target ~ /[ ,<*{$]/) continue
    target = resolve(dir, target)
    if (target == "") continue
    checked++
    if (!(target in have)) report(f, lineno, target, "a link to a missing file")
  }
}

# The path words of a line of comment or doc.
function words(f, lineno, dir, text,   w, first, resolved, after_colon) {
  while (match(text, /[-A-Za-z0-9_.\/<>*{}$@,+~]+/)) {
    w = substr(text, RSTART, RLENGTH)
    after_colon = RSTART > 1 && substr(text, RSTART - 1, 1) == ":"
    text = substr(text, RSTART + RLENGTH)
    if (after_colon) continue
    sub(/^,+/, "", w)
    if (index(w, "...") || w ~ /[*{}$@~]/) continue
    if (w ~ /^<[^<>]*>[.,]*$/) {
      # An include: <opspace/algorithms/dynamics.hpp>.
      sub(/^</, "", w)
      sub(/>[.,]*$/, "", w)
    }
    if (w ~ /</) continue
    sub(/[.,>]+$/, "", w)
    if (w == "") continue
    if (index(w, "/") == 0) {
      if (w in top_file) { checked++; if (!(w in have)) report(f, lineno, w, "missing") }
      continue
    }
    if (w ~ /^\// || w ~ /\/\//) continue
    sub(/\/+$/, "", w)
    first = w
    sub(/\/.*/, "", first)
    # What git ignores (.gitignore) is no repository path.
    if (first == "build" || first == "out" || w ~ /^web\/node_modules(\/|$)/) continue
    if (first in top) {
      checked++
      # A file or a folder, or a program by its source: bench/bench_control (.cpp).
      if (w in have || (w !~ /\.[A-Za-z0-9]+$/ && (w ".cpp") in have)) continue
      report(f, lineno, w, "missing")
      continue
    }
    # A partial path to a source or a doc.
    if (w !~ /\.(hpp|cpp|inc|cmake|sh|md|mjs|js|urdf)$/) continue
    checked++
    if (first == "." || first == "..") {
      resolved = resolve(dir, w)
      if (resolved != "" && !(resolved in have))
        report(f, lineno, w, "missing from " (dir == "" ? "the top" : dir "/"))
      continue
    }
    if (w in ends || (dir != "" && (dir "/" w) in have)) continue
    report(f, lineno, w, "no repository path ends so")
  }
}

# dir/path with its . and .. folded; "" where it climbs out of the repository.
function resolve(dir, path,   n, part, i, out, m, stack) {
  path = (dir == "" ? "" : dir "/") path
  n = split(path, part, "/")
  m = 0
  for (i = 1; i <= n; i++) {
    if (part[i] == "" || part[i] == ".") continue
    if (part[i] == "..") { if (m == 0) return ""; m--; continue }
    stack[++m] = part[i]
  }
  out = ""
  for (i = 1; i <= m; i++) out = (i == 1) ? stack[1] : out "/" stack[i]
  return out
}

function report(f, lineno, w, why) {
  printf "%s:%d: %s (%s)\n", f, lineno, w, why
  missing++
}
' "$list"
