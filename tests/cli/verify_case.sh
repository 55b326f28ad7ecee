# Shared by the verify suites and book_examples.sh (sourced, with V set to the vibook command): a
# temporary directory, the pass/fail counters; case_, one run of `vibook verify` checked for its
# exit status, its stderr line, lines of its report and its JSON verdict; book_case, the same
# checks on an example the book build ran; arg, one bad argument.
# VERIFY_PHASES=1 also checks that every phase that ran is in the JSON (the --ld route has
# phases; the --composition route has none).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# case NAME STATUS 'FAILED-CHECKS' 'REGEX...' -- ARGS: exit status (0 passes, 5 a verdict
# failed, with one stderr line naming which), the JSON verdict's failed checks (comma-separated,
# "" when it passes) and each regex among the report's lines.
case_() {
  local name=$1 want=$2 failed=$3; shift 3
  local pats=()
  while [ "$1" != "--" ]; do pats+=("$1"); shift; done
  shift
  "$V" verify "$@" --json-out "$tmp/v.json" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" != "$want" ]; then
    bad "$name: exit $got, expected $want: $(cat "$tmp/err") $(cat "$tmp/out")"; return
  fi
  judged "$name" "$want" "$failed" "$tmp/out" "$tmp/err" "$tmp/v.json" "${pats[@]}"
}

# book_case NAME FILE STATUS 'FAILED-CHECKS' 'REGEX...': the same checks on an example the book
# build ran (book/build_book.cmake, vibook_verify_case: FILE, its .json and .stderr in the
# directory BOOK_GEN), instead of running it a second time. Its exit status is the book build's
# to check (it stops on any other).
book_case() {
  local name=$1 file=$2 want=$3 failed=$4; shift 4
  local stem=$BOOK_GEN/${file%.txt}
  if [ ! -f "$BOOK_GEN/$file" ] || [ ! -f "$stem.json" ] || [ ! -f "$stem.stderr" ]; then
    bad "$name: no $BOOK_GEN/$file with its .json and .stderr: build the book first"; return
  fi
  judged "$name" "$want" "$failed" "$BOOK_GEN/$file" "$stem.stderr" "$stem.json" "$@"
}

# judged NAME STATUS FAILED OUT ERR JSON REGEX...: the stderr line, the report's lines and the
# JSON verdict of one run whose exit status was STATUS.
judged() {
  local name=$1 want=$2 failed=$3 out=$4 err=$5 json=$6; shift 6
  if [ "$want" = 0 ]; then
    [ -s "$err" ] && { bad "$name: stderr not empty: $(cat "$err")"; return; }
  elif [ "$(wc -l <"$err")" != 1 ] || ! grep -q "^vibook: " "$err"; then
    bad "$name: want one stderr line, got: $(cat "$err")"; return
  fi
  for p in "$@"; do
    grep -Eq -- "$p" "$out" || { bad "$name: report lacks /$p/: $(cat "$out")"; return; }
  done
  python3 - "$json" "$failed" <<'PY' || { bad "$name: JSON verdict"; return; }
import json, os, sys
j = json.load(open(sys.argv[1]))
want = [w for w in sys.argv[2].split(",") if w]
v = j["verdict"]
assert v["failed"] == want and v["passed"] == (not want), (v, want)
# every phase that ran is in the JSON with its status
if os.environ.get("VERIFY_PHASES") == "1":
    assert all(p["status"] in ("ok", "failed", "skipped") for p in j["phases"]), j["phases"]
PY
  ok
}

# arg NAME OPTION ARGS...: a bad argument: exit 2, one line naming the argument, nothing on stdout.
arg() {
  local name=$1 opt=$2; shift 2
  "$V" verify "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" != 2 ] || [ -s "$tmp/out" ] || ! grep -q -- "$opt" "$tmp/err" ||
     [ "$(wc -l <"$tmp/err")" != 1 ]; then
    bad "$name: exit $got, stdout $(wc -c <"$tmp/out") bytes, stderr: $(cat "$tmp/err")"
  else
    ok
  fi
}

# same_errors NAME A.json B.json MIN [FLOOR]: two runs of one method on one system (a typed one
# and a built-in one) give the same order-study errors: the same step sizes, and where B's error
# exceeds FLOOR (default 1e-9) the two agree to 1e-4 (relative), at MIN or more step sizes (a step
# size at which either run failed is left out). Below 1e-9 a typed step's own round-off may show
# (see verify_composition.sh).
same_errors() {
  python3 - "$2" "$3" "$4" "${5:-1e-9}" <<'PY' && ok || bad "$1: order-study errors differ"
import json, sys
a, b = (json.load(open(f))["order"] for f in sys.argv[1:3])
n = 0
for h, g, x, y in zip(a["h"], b["h"], a["error"], b["error"]):
    assert h == g, (h, g)
    if x is None or y is None:  # a step size at which a run failed (too large a step)
        continue
    if y > float(sys.argv[4]):
        assert abs(x - y) <= 1e-4 * y, (h, x, y)
        n += 1
assert n >= int(sys.argv[3]), n
PY
}
