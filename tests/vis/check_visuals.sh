#!/usr/bin/env bash
# The pictures of a run, checked as a user meets them: run a program, read the paths it
# prints, open the files. Called by ctest (tests/vis/CMakeLists.txt):
#   check_visuals.sh plots      PROGRAM WORKDIR             PNG + SVG named as printed, non-empty
#   check_visuals.sh plots-p2   PROGRAM WORKDIR             the same for hw2-p2
#   check_visuals.sh plots-p3   PROGRAM WORKDIR             the same for hw2-p3's figures
#   check_visuals.sh plots-p4   PROGRAM WORKDIR             the same for hw2-p4 (both directions)
#   check_visuals.sh no-gnuplot PROGRAM WORKDIR             without gnuplot: a note, exit 0, data kept
#   check_visuals.sh compare    PROGRAM WORKDIR             hw2-p1 compare draws the drift overlay
#   check_visuals.sh replay     PROGRAM WORKDIR NODE CHECK_SCRIPT SCREENSHOT MIN_ROBOT_SHARE ARG...
#                               runs PROGRAM ARG... in WORKDIR; the one page it prints on its
#                               'replay:' line must pass CHECK_SCRIPT (web/test/check_replay.mjs)
#                               in headless Chromium, the robot covering > MIN_ROBOT_SHARE of it
#   check_visuals.sh explorer   PROGRAM WORKDIR NODE CHECK_SCRIPT EXPLORER ARTEFACTS ARG...
#                               runs PROGRAM ARG...; the page on its 'explorer:' line must pass
#                               CHECK_SCRIPT (web/test/check_explorer.mjs), which compares its
#                               numbers with the native EXPLORER's and keeps screenshots in ARTEFACTS
#   check_visuals.sh judged     PROGRAM WORKDIR ARG...  a reference (-sol) run at its default
#                               duration: every row of its table ok, and this run's value equal
#                               to the reference column (computed at build time)
#   check_visuals.sh misses     PROGRAM WORKDIR ARG...  a run of the exercise stubs: its table
#                               says MISSES and where the grader explains it
#   check_visuals.sh out-dir    PROGRAM WORKDIR         the default outputs land in $OPSPACE_OUT
#                               (the repository's out/ by default) wherever the program runs from
#   check_visuals.sh report-page PAGE WORKDIR NODE CHECK_SCRIPT SCREENSHOT TEST
#                               the grader's report page PAGE (written by the test "grader: a
#                               PART3 with the pseudo-inverse projector ...") must pass
#                               CHECK_SCRIPT (web/test/check_report_page.mjs) offline in headless
#                               Chromium; SCREENSHOT is TEST's section
# The programs write their default outputs into $OPSPACE_OUT: WORKDIR/out here, never the
# repository's out/.
# Exit 77 (ctest: skipped) when gnuplot, node, the viewer bundle or Chromium is missing,
# unless CI is set: CI installs them (scripts/setup.sh), so there a missing tool fails.
set -uo pipefail
mode=$1 program=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
export OPSPACE_OUT="$work/out"
fail() { echo "FAIL: $*"; exit 1; }
skip() {
  if [ -n "${CI:-}" ]; then fail "$* (CI is set: scripts/setup.sh should have installed it)"; fi
  echo "SKIP: $*"; exit 77
}
# The magic bytes a viewer checks before drawing: PNG signature, SVG/XML opening tag.
looks_like() {
  case "$1" in
    *.png) [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] ;;
    *.svg) head -c 300 "$1" | grep '<svg\|<?xml' >/dev/null ;;
    *) return 1 ;;
  esac
}
# run NAME ARG...: runs the program in $work, its output printed and kept in $work/out.txt;
# "NAME failed" when it fails.
run() {
  local name=$1; shift
  (cd "$work" && "$program" "$@") > "$work/out.txt" 2>&1 || { cat "$work/out.txt"; fail "$name failed"; }
  cat "$work/out.txt"
}
need_gnuplot() { command -v gnuplot >/dev/null || skip "gnuplot is not installed (apt-get install gnuplot-nox)"; }
check_images() {  # check_images LOG EXPECTED_NAME...
  local log=$1; shift
  mapfile -t images < <(sed -n 's/^plot: *//p' "$log")
  [ ${#images[@]} -gt 0 ] || fail "the program printed no 'plot:' line"
  for want in "$@"; do
    # Not grep -q: it stops reading at the first match, and under pipefail the writer's SIGPIPE
    # would fail the pipe.
    printf '%s\n' "${images[@]}" | grep -x "$want" >/dev/null || fail "expected $want among the printed plots: ${images[*]}"
  done
  for image in "${images[@]}"; do
    [ -s "$image" ] || fail "$image was printed but is missing or empty"
    looks_like "$image" || fail "$image is not a PNG/SVG file"
    echo "ok   $image ($(stat -c %s "$image") bytes)"
  done
}
# check_plots LOG PREFIX NAME...: check_images for PREFIX-NAME.png and PREFIX-NAME.svg of each NAME.
check_plots() {
  local log=$1 prefix=$2 name expected=()
  shift 2
  for name in "$@"; do expected+=("$prefix-$name.png" "$prefix-$name.svg"); done
  check_images "$log" "${expected[@]}"
}

case "$mode" in
  plots)
    need_gnuplot
    # 3 simulated seconds: every figure has data, the test stays short.
    run "$program 3" 3 --duration 3 --csv run/p3.csv --no-replay
    cd "$work"
    check_plots out.txt run/p3 tip error q2 torques
    ;;
  plots-p2)
    need_gnuplot
    run "$program" --duration 2 --csv run/p2.csv --no-replay
    cd "$work"
    check_plots out.txt run/p2 position error lambda torques
    ;;
  plots-p3)
    need_gnuplot
    # 2 simulated seconds: every figure has data after the first second.
    run "$program" --duration 2 --csv run/p3.csv --no-replay
    cd "$work"
    check_plots out.txt run/p3 force tracking tilt
    ;;
  plots-p4)
    need_gnuplot
    run "$program" --duration 1 --no-replay
    cd "$work"
    # Named after the program: hw2-p4-sol's files never overwrite a student's hw2-p4 run.
    check_plots out.txt "out/$(basename "$program")-z" reach torques torques-plain
    check_plots out.txt "out/$(basename "$program")-y" reach torques torques-plain
    ;;
  no-gnuplot)
    (cd "$work" && OPSPACE_GNUPLOT=/nonexistent/gnuplot "$program" 1 --duration 1 --csv run/p1.csv --no-replay) \
      > "$work/out.txt" 2>&1 || { cat "$work/out.txt"; fail "$program must not fail without gnuplot"; }
    cat "$work/out.txt"
    grep -q '^note: .*gnuplot was not found' "$work/out.txt" || fail "no note that gnuplot is missing"
    ! grep -q '^plot:' "$work/out.txt" || fail "a plot was printed although gnuplot is missing"
    [ -s "$work/run/p1-tip.gp" ] && [ -s "$work/run/p1-tip.dat" ] || fail "the gnuplot script and data were not kept"
    ;;
  compare)
    need_gnuplot
    # 3 s: PART2's tip drifts from the first second on (problems/1b/guide.md).
    run "$program compare" compare --duration 3 --csv run/cmp.csv
    cd "$work"
    check_images out.txt run/cmp-drift.png run/cmp-drift.svg
    [ -s run/cmp-part2.csv ] && [ -s run/cmp-part3.csv ] || fail "the two logs were not written"
    ;;
  report-page)
    [ $# -eq 7 ] || fail "report-page needs PAGE WORKDIR NODE CHECK_SCRIPT SCREENSHOT TEST"
    page=$program node=$4 check=$5 screenshot=$6 focus=$7
    [ -x "$node" ] || skip "node is not installed: the page cannot be checked in Chromium"
    [ -x "${CHROMIUM:-/usr/bin/chromium}" ] || skip "Chromium is not installed (apt-get install chromium)"
    [ -f "$check" ] || skip "$check is missing: the viewer's npm packages were not installed"
    [ -s "$page" ] || fail "$page is missing: the grader's test that writes it did not run or failed"
    mkdir -p "$(dirname "$screenshot")"
    "$node" "$check" "$page" "$screenshot" "$focus"
    status=$?
    [ $status -eq 77 ] && skip "Chromium could not be started"
    [ $status -eq 0 ] || fail "the report page failed in headless Chromium"
    [ -s "$screenshot" ] || fail "no screenshot"
    ;;
  replay)
    [ $# -ge 7 ] || fail "replay needs NODE CHECK_SCRIPT SCREENSHOT MIN_ROBOT_SHARE and the program's arguments"
    node=$4 check=$5 screenshot=$6 share=$7
    shift 7
    [ -x "$node" ] || skip "node is not installed: the replay viewer cannot be bundled or checked"
    [ -x "${CHROMIUM:-/usr/bin/chromium}" ] || skip "Chromium is not installed (apt-get install chromium)"
    # The durations are chosen per program in tests/vis/CMakeLists.txt (short, but the arm
    # moves); --no-plots: this test is about the page.
    run "$program $*" "$@" --no-plots
    if grep -q '^note: *no 3D replay' "$work/out.txt"; then skip "the viewer bundle was not built (see the note above)"; fi
    mapfile -t pages < <(sed -n 's/^replay: *//p' "$work/out.txt")
    [ ${#pages[@]} -gt 0 ] || fail "no 'replay:' line printed"
    [ ${#pages[@]} -eq 1 ] || fail "expected one 'replay:' line, got ${#pages[@]}: ${pages[*]}"
    page=${pages[0]}
    case "$page" in /*) ;; *) page=$work/$page ;; esac  # printed relative to the program's directory
    [ -s "$page" ] || fail "$page was printed but is missing or empty"
    [ -f "$check" ] || skip "$check is missing: the viewer's npm packages were not installed"
    mkdir -p "$(dirname "$screenshot")"
    "$node" "$check" "$page" "$screenshot" "$share"
    status=$?
    [ $status -eq 77 ] && skip "Chromium could not be started"
    [ $status -eq 0 ] || fail "the replay page failed in headless Chromium"
    [ -s "$screenshot" ] || fail "no screenshot"
    ;;
  explorer)
    [ $# -ge 7 ] || fail "explorer needs NODE CHECK_SCRIPT EXPLORER ARTEFACTS and the program's arguments"
    node=$4 check=$5 explorer=$6 artefacts=$7
    shift 7
    [ -x "$node" ] || skip "node is not installed: the explorer's viewer cannot be bundled or checked"
    [ -x "${CHROMIUM:-/usr/bin/chromium}" ] || skip "Chromium is not installed (apt-get install chromium)"
    run "$program $*" "$@" --no-plots
    mapfile -t pages < <(sed -n 's/^explorer: *//p' "$work/out.txt")
    [ ${#pages[@]} -gt 0 ] || skip "no 'explorer:' line: the page was not built (it needs em++, Debian's emscripten, and the viewer bundle: see the build's messages)"
    [ ${#pages[@]} -eq 1 ] || fail "expected one 'explorer:' line, got ${#pages[@]}: ${pages[*]}"
    [ -s "${pages[0]}" ] || fail "${pages[0]} was printed but is missing or empty"
    [ -f "$check" ] || skip "$check is missing: the viewer's npm packages were not installed"
    "$node" "$check" "${pages[0]}" "$explorer" "$artefacts"
    status=$?
    [ $status -eq 77 ] && skip "Chromium could not be started"
    [ $status -eq 0 ] || fail "the explorer page failed in headless Chromium"
    ;;
  judged)
    shift 3
    run "$program $*" "$@" --no-plots --no-replay
    grep -q '  reference (' "$work/out.txt" || fail "no table with a reference column"
    ! grep -E '  (MISSES|DIFFERS)$' "$work/out.txt" || fail "the reference run misses its own bounds"
    # Rows are indented by two spaces, their columns separated by two or more: what, this run,
    # [what it should be,] reference[, verdict]. The reference column is the build's reference
    # run, which this very run repeats.
    rows=0
    while IFS= read -r line; do
      mapfile -t field < <(printf '%s\n' "${line#  }" | sed 's/   */\n/g')
      [ ${#field[@]} -ge 3 ] || continue
      last=${field[-1]}
      case "$last" in ok|MISSES|DIFFERS) reference=${field[-2]} ;; *) reference=$last ;; esac
      [ "${field[1]}" = "$reference" ] || fail "this run's '${field[1]}' differs from the reference '$reference' in: $line"
      rows=$((rows + 1))
    done < <(grep '^  [^ ]' "$work/out.txt")
    [ $rows -ge 3 ] || fail "only $rows rows compared"
    echo "ok   $rows rows equal to the reference"
    ;;
  misses)
    shift 3
    run "$program $*" "$@" --no-plots --no-replay
    grep -qE '  MISSES$' "$work/out.txt" || fail "no row says MISSES"
    grep -qE 'miss(es)? what (it|they) should be: bash scripts/grade --problem' "$work/out.txt" ||
      fail "no pointer to the grader"
    ;;
  out-dir)
    # From a directory outside $OPSPACE_OUT's parent: absolute paths into $OPSPACE_OUT.
    mkdir -p "$work/elsewhere"
    (cd "$work/elsewhere" && "$program" z --duration 0.2 --no-plots --no-replay) > "$work/out.txt" 2>&1 ||
      { cat "$work/out.txt"; fail "$program failed"; }
    cat "$work/out.txt"
    name=$(basename "$program")
    grep -qx "  logs: $work/out/$name-z.csv, $work/out/$name-z-plain.csv" "$work/out.txt" ||
      fail "expected the logs in $work/out, printed as absolute paths"
    [ -s "$work/out/$name-z.csv" ] || fail "$work/out/$name-z.csv was not written"
    [ ! -e "$work/elsewhere/out" ] || fail "the program wrote into the directory it ran from"
    # From the folder holding out/: the short relative path.
    (cd "$work" && "$program" z --duration 0.2 --no-plots --no-replay) > "$work/out.txt" 2>&1 ||
      { cat "$work/out.txt"; fail "$program failed"; }
    grep -qx "  logs: out/$name-z.csv, out/$name-z-plain.csv" "$work/out.txt" ||
      { cat "$work/out.txt"; fail "expected the logs printed as out/$name-z.csv"; }
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo "passed"
