# The secret side of the repository, decided by place alone: every folder named grade/ below
# problems/ or grader/, whatever it holds (a problem's graded tests, answers and known mistakes,
# problems/<key>/grade/; the graded suite's gatherers of them, grader/suite/grade/). Its two
# readers leave out the same files by this one rule, never by a list of names: scripts/handout
# (a student handout has none of it) and deploy/setup.sh (the autograder's image deletes it once
# built). tests/deploy/handout_secret_side.sh checks that both leave out exactly it.
#   source scripts/secret_side.sh
opspace_secret_roots=(problems grader)
opspace_secret_folder=grade

# The repository paths on stdin (one a line) that are not on the secret side, on stdout.
opspace_without_secret_side() {
  awk -v roots="${opspace_secret_roots[*]}" -v name="$opspace_secret_folder" '
    BEGIN { n = split(roots, r, " "); for (i = 1; i <= n; ++i) root[r[i]] = 1 }
    {
      k = split($0, part, "/"); secret = 0
      if (part[1] in root) for (i = 2; i < k; ++i) if (part[i] == name) secret = 1
      if (!secret) print
    }'
}

# The secret folders of the checkout at $1, one a line (none: nothing is printed).
opspace_secret_folders() {
  local top
  for top in "${opspace_secret_roots[@]}"; do
    [ ! -d "$1/$top" ] || find "$1/$top" -type d -name "$opspace_secret_folder" -prune -print
  done
}

# Removes the secret side from the checkout at $1.
opspace_remove_secret_side() {
  local folder
  while IFS= read -r folder; do rm -rf "$folder"; done < <(opspace_secret_folders "$1")
}
