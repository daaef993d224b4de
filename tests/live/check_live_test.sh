#!/usr/bin/env bash
# `--test NAME --live` starts the live lab at that graded test's scenario (issue 41, docs/live.md):
# the report's replay command of TEST, read from a grader's REPORT (report.txt), is run twice on
# PROGRAM (the program the command names, built here):
#   1. as printed, with --no-plots --no-replay: the replay's log OFFLINE_CSV (under OPSPACE_OUT);
#   2. with --live --port 0 added: the program must print "live: http://127.0.0.1:PORT/" and
#      that it replays TEST, its page must answer on PORT; its event stream is then opened (the
#      run waits for it to start, docs/live.md) and read, and after LIVE_SECONDS of real time
#      SIGINT must end it with status 0. Its session log LIVE_CSV must start as the replay's log:
#      every column the two logs share, row by row, equal to 1e-9 (relative, at least 1e-12
#      absolute) over the rows the live run made, 100 at least (0.1 s of a 1 ms step: a slow
#      machine still steps that many in LIVE_SECONDS). Both logs come from the same scenario
#      functions stepped one dt at a time, so a live run of the same scenario repeats the
#      replay's arithmetic (tests/live's "the unpaced session against the offline run" shows
#      the same for the session without a server).
#   3. the control: PROGRAM DEFAULT_ARG... --live (the default live run, without the test's
#      arguments) must NOT start as the replay's log: otherwise check 2 could not tell a test's
#      scenario from the default one.
#   check_live_test.sh PROGRAM REPORT TEST WORK OFFLINE_CSV LIVE_CSV DEFAULT_LIVE_CSV [DEFAULT_ARG...]
# With OFFLINE_CSV "-" (a test whose replay is no single live run: hw2-p1 compare), only: the
# command with --live added either serves a page (check 2's "live: ..." line, then SIGINT) or is
# refused (status 2, a message naming --live); never the offline run alone with status 0.
# Exit 77 (ctest: skipped) when the program was built without the live lab.
# Seen to fail: with check 3's arguments the test's own (y for problem 4's Y0 test: "the default
# live run (y --live) starts as the replay too: 2147 rows ... agree"); with the replay's log taken
# from the plain controller's run of the same target (hw2-p4-sol-y-plain.csv): check 2 says
# "row 1 differs in tau1"; with the ratio test's `compare` command before the program refused
# its --live (tests/live's compare case): "neither served a page nor refused --live (status 0)".
set -uo pipefail
program=$1 report=$2 test_name=$3 work=$4 offline_csv=$5 live_csv=$6 default_csv=$7
shift 7
default_args=("$@")
live_seconds=2  # about 2000 steps of 1 ms paced to the wall clock; the comparison needs 100

fail() {
  echo "FAIL: $*" >&2
  exit 1
}
rm -rf "$work" && mkdir -p "$work"

line=$(grep -F -- "--test \"$test_name\"" "$report" | grep -F "replay it: bash scripts/run " | head -n 1)
[ -n "$line" ] || fail "$report names no replay command for '$test_name'"
arguments=${line#*bash scripts/run }
eval "set -- $arguments"  # the grader's own text: PROGRAM-NAME [PART|TARGET] --test "NAME" --seed N
shift                      # the program's name: PROGRAM runs in its place
test_args=("$@")
echo "ok   the report's command: ${line#*replay it: }"

if [ "$offline_csv" = - ]; then
  OPSPACE_OUT="$work/served" OPSPACE_WATCHDOG=0 timeout 120 "$program" "${test_args[@]}" --live --port 0 --no-plots \
    --no-replay > "$work/served.txt" 2>&1 &
  pid=$!
  for ((k = 0; k < 1200; ++k)); do  # 120 s: the offline comparison simulates 2 x 10 s before it exits
    grep -q '^live: http://127\.0\.0\.1:[0-9]*/$' "$work/served.txt" && break
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
  done
  if grep -q '^live: http://127\.0\.0\.1:[0-9]*/$' "$work/served.txt"; then
    kill -INT "$pid"
    wait "$pid" || fail "the live run ended with status $? after SIGINT:$(cat "$work/served.txt")"
    echo "ok   '${test_args[*]} --live' serves a live page"
    exit 0
  fi
  wait "$pid"
  code=$?
  if [ "$code" -eq 2 ] && grep -q -- '--live' "$work/served.txt"; then
    echo "ok   '${test_args[*]} --live' is refused: $(grep -- '--live' "$work/served.txt" | head -n 1)"
    exit 0
  fi
  fail "'${test_args[*]} --live' neither served a page nor refused --live (status $code):$(cat "$work/served.txt")"
fi

# --- 1. the replay -----------------------------------------------------------------------------
OPSPACE_OUT="$work/offline" OPSPACE_WATCHDOG=0 "$program" "${test_args[@]}" --no-plots --no-replay \
  > "$work/offline.txt" 2>&1 || true
[ -s "$work/offline/$offline_csv" ] || fail "the replay wrote no $offline_csv:$(cat "$work/offline.txt")"

# live NAME ARG...: runs PROGRAM ARG... --live --port 0 in $work/NAME, fetches its page, opens its
# event stream (the run starts then) for $live_seconds s of real time, then SIGINT; its output in
# $work/NAME.txt.
live() {
  local name=$1
  shift
  mkdir -p "$work/$name"
  OPSPACE_OUT="$work/$name" OPSPACE_WATCHDOG=0 "$program" "$@" --live --port 0 --no-plots --no-replay \
    > "$work/$name.txt" 2>&1 &
  local pid=$! port="" k
  for ((k = 0; k < 600; ++k)); do  # 60 s for the address: a loaded machine loads the URDF slowly
    port=$(sed -n 's|^live: http://127\.0\.0\.1:\([0-9]*\)/$|\1|p' "$work/$name.txt")
    [ -n "$port" ] && break
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
  done
  if [ -z "$port" ]; then
    kill -INT "$pid" 2> /dev/null
    wait "$pid"
    grep -q "no live lab" "$work/$name.txt" && { echo "SKIP: $program was built without the live lab"; exit 77; }
    fail "'$program $* --live --port 0' printed no 'live: http://127.0.0.1:PORT/':$(cat "$work/$name.txt")"
  fi
  # The page answers on that port (bash's /dev/tcp: no client needed).
  if ! exec 3<> "/dev/tcp/127.0.0.1/$port"; then
    kill -INT "$pid"
    fail "nothing answers on port $port"
  fi
  printf 'GET / HTTP/1.0\r\nHost: 127.0.0.1:%s\r\n\r\n' "$port" >&3
  local status
  status=$(head -n 1 <&3)
  exec 3<&-
  # Then its event stream, as the page opens it: the run starts then (it waits for the page),
  # and the frames are read until the program ends.
  exec 3<> "/dev/tcp/127.0.0.1/$port"
  printf 'GET /events HTTP/1.1\r\nHost: 127.0.0.1:%s\r\n\r\n' "$port" >&3
  cat <&3 > /dev/null &
  local reader=$!
  exec 3<&-
  sleep "$live_seconds"
  kill -INT "$pid"
  wait "$pid"
  local code=$?
  kill "$reader" 2> /dev/null
  wait "$reader" 2> /dev/null
  [ "$code" -eq 0 ] || fail "'$program $* --live' ended with status $code after SIGINT:$(cat "$work/$name.txt")"
  case $status in
    "HTTP/1."?" 200"*) ;;
    *) fail "port $port answered GET / with '$status'" ;;
  esac
}

# same_start A B: every column A and B share by name, row by row over A's rows, equal to 1e-9
# relative (1e-12 absolute at least); prints what differs first, or how many rows and columns agree.
same_start() {
  awk -F, -v a="$1" -v b="$2" 'BEGIN {
    if ((getline line < a) <= 0 || (getline head < b) <= 0) { print "an empty log"; exit 1 }
    na = split(line, ha, ","); nb = split(head, hb, ",")
    for (j = 1; j <= nb; ++j) col[hb[j]] = j
    shared = 0
    for (i = 1; i <= na; ++i) if (ha[i] in col) { ia[++shared] = i; ib[shared] = col[ha[i]]; name[shared] = ha[i] }
    if (shared < 2) { print "the logs share " shared " columns"; exit 1 }
    rows = 0
    while ((getline la < a) > 0) {
      if ((getline lb < b) <= 0) break
      split(la, va, ","); split(lb, vb, ",")
      for (k = 1; k <= shared; ++k) {
        x = va[ia[k]] + 0; y = vb[ib[k]] + 0; d = x - y; if (d < 0) d = -d
        m = (x < 0 ? -x : x); if (m < 1e-3) m = 1e-3
        if (d > 1e-9 * m) { printf "row %d differs in %s: %s against %s\n", rows + 1, name[k], va[ia[k]], vb[ib[k]]; exit 1 }
      }
      ++rows
    }
    printf "%d rows of %d shared columns agree\n", rows, shared
    exit rows >= 100 ? 0 : 2 }'
}

# --- 2. the live run of the test ---------------------------------------------------------------
live test "${test_args[@]}"
grep -qF "replaying the graded test \"$test_name\"" "$work/test.txt" ||
  fail "the live run does not say it replays '$test_name':$(cat "$work/test.txt")"
[ -s "$work/test/$live_csv" ] || fail "the live run wrote no $live_csv:$(cat "$work/test.txt")"
result=$(same_start "$work/test/$live_csv" "$work/offline/$offline_csv")
case $? in
  0) echo "ok   the live run starts as the test's replay: $result" ;;
  2) fail "the live run made too few steps to compare (100 at least): $result" ;;
  *) fail "the live run of '$test_name' does not start as its replay: $result" ;;
esac

# --- 3. the control: the default live run starts elsewhere ----------------------------------------
live default "${default_args[@]}"
[ -s "$work/default/$default_csv" ] || fail "the default live run wrote no $default_csv:$(cat "$work/default.txt")"
result=$(same_start "$work/default/$default_csv" "$work/offline/$offline_csv")
[ $? -eq 1 ] || fail "the default live run (${default_args[*]} --live) starts as the replay too: $result"
echo "ok   the default live run (${default_args[*]} --live) starts elsewhere: $result"
