#!/usr/bin/env bash
# A black-box stepper behind the line protocol is a child vibook ends (chapter "Verify your own
# integrator", "Any stepper as a black box"): however vibook's run ends (a timeout, a refused
# first step, --max-seconds, a signal, a flood of output), no process the stepper started is
# left running, vibook stops within its limits, and its message is one line that carries the
# stepper's last line on stderr.
# Usage: stepper_children.sh VIBOOK
set -u
V=$1
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"  # tmp, pass/fail, ok, bad
trap 'pkill -KILL -f "$tmp/" 2>/dev/null; rm -rf "$tmp"' EXIT
# No process whose command line names this test's directory may outlive vibook.
survivors() { sleep 0.3; pgrep -f "$tmp/" >/dev/null; }
P=(--problem pendulum --expected-order 2 --steps 2048 --h-list 0.1,0.05,0.025)

# A stepper that never answers (and ignores end of input).
cat >"$tmp/hang.sh" <<'SH'
#!/bin/sh
trap '' TERM HUP INT
exec sleep 100000
SH
# A stepper that forks a child which outlives it, then refuses its first step.
cat >"$tmp/fork.sh" <<SH
#!/bin/sh
sh -c 'exec sleep 100001' "$tmp/child" &
read line
echo "error: no"
SH
# A stepper that answers a few steps correctly (explicit Euler, right or wrong does not
# matter here), then hangs: --max-seconds must end it.
cat >"$tmp/slow.py" <<'PY'
import sys, math, time
for k, line in enumerate(sys.stdin):
    if k >= 3:
        time.sleep(100000)
    h, n, q, p = line.split()
    h, n, q, p = float(h), int(n), float(q), float(p)
    for _ in range(n):
        q, p = q + h * p, p - h * math.sin(q)
    print(f"{q!r} {p!r}", flush=True)
PY
# A stepper that dies with a Python traceback on stderr.
cat >"$tmp/crash.py" <<'PY'
import sys
sys.stdin.readline()
raise RuntimeError("the stepper broke down here")
PY
# A flood of lines nobody asked for, and one endless line: each process named after this
# test's directory (exec -a), so that a survivor would be found.
cat >"$tmp/flood.sh" <<SH
#!/bin/bash
exec -a "$tmp/yes" yes '0.1 0.1'
SH
cat >"$tmp/endless.sh" <<SH
#!/bin/bash
(exec -a "$tmp/yes" yes) | (exec -a "$tmp/tr" tr -d '\\n')
SH
chmod +x "$tmp/hang.sh" "$tmp/fork.sh" "$tmp/flood.sh" "$tmp/endless.sh"

t0=$(date +%s)
"$V" verify --stepper-cmd "$tmp/hang.sh" "${P[@]}" --stepper-timeout 0.5 >"$tmp/o1" 2>"$tmp/e1"
s=$?
[ $s != 0 ] && [ "$(wc -l <"$tmp/e1")" = 1 ] && grep -q "did not answer within 0.5 s" "$tmp/e1" &&
  ! survivors && ok || bad "hang: status $s, $(cat "$tmp/e1"), survivors: $(pgrep -af "$tmp/")"

"$V" verify --stepper-cmd "$tmp/fork.sh" "${P[@]}" >"$tmp/o2" 2>"$tmp/e2"
s=$?
[ $s != 0 ] && [ "$(wc -l <"$tmp/e2")" = 1 ] && ! survivors && ok ||
  bad "forked child: status $s, $(cat "$tmp/e2"), survivors: $(pgrep -af "$tmp/")"

"$V" verify --stepper-cmd "python3 $tmp/slow.py" "${P[@]}" --max-seconds 2 >"$tmp/o3" 2>"$tmp/e3"
s=$?
[ $s = 3 ] && grep -q "stopped by --max-seconds 2" "$tmp/e3" && ! survivors && ok ||
  bad "--max-seconds: status $s, $(cat "$tmp/e3"), survivors: $(pgrep -af "$tmp/")"

"$V" verify --stepper-cmd "python3 $tmp/slow.py" "${P[@]}" >"$tmp/o4" 2>"$tmp/e4" &
pid=$!
sleep 1.5
kill -TERM $pid
wait $pid
s=$?
[ $s = 143 ] && grep -q "interrupted by SIGTERM" "$tmp/e4" && ! survivors && ok ||
  bad "SIGTERM: status $s, $(cat "$tmp/e4"), survivors: $(pgrep -af "$tmp/")"

# A flood: an endless stream of lines, read without a request; vibook must stop within its
# timeout, not hang writing requests nobody reads.
start=$(date +%s)
timeout 60 "$V" verify --stepper-cmd "$tmp/flood.sh" "${P[@]}" --stepper-timeout 2 \
  >"$tmp/o5" 2>"$tmp/e5"
s=$?
[ $s != 124 ] && [ $s != 0 ] && [ "$(wc -l <"$tmp/e5")" = 1 ] && [ $(($(date +%s) - start)) -le 20 ] &&
  ! survivors && ok || bad "flood: status $s, $(cat "$tmp/e5")"
# One endless line.
timeout 60 "$V" verify --stepper-cmd "$tmp/endless.sh" "${P[@]}" --stepper-timeout 2 \
  >"$tmp/o6" 2>"$tmp/e6"
s=$?
[ $s != 124 ] && [ $s != 0 ] && [ "$(wc -l <"$tmp/e6")" = 1 ] && ! survivors && ok ||
  bad "endless line: status $s, $(cat "$tmp/e6")"

# The stepper's traceback is not passed through: its last line joins vibook's one line.
"$V" verify --stepper-cmd "python3 $tmp/crash.py" "${P[@]}" >"$tmp/o7" 2>"$tmp/e7"
s=$?
[ $s != 0 ] && [ "$(wc -l <"$tmp/e7")" = 1 ] &&
  grep -q "its last line on stderr: 'RuntimeError: the stepper broke down here'" "$tmp/e7" &&
  ok || bad "traceback: status $s, $(cat "$tmp/e7")"

# An answer with a NUL byte is refused.
printf '%s\n' '#!/bin/sh' 'while read l; do printf "1\0 0.5\n"; done' >"$tmp/nul.sh"
chmod +x "$tmp/nul.sh"
"$V" verify --stepper-cmd "$tmp/nul.sh" "${P[@]}" >"$tmp/o8" 2>"$tmp/e8"
s=$?
[ $s != 0 ] && grep -q "NUL byte" "$tmp/e8" && ok || bad "NUL: status $s, $(cat "$tmp/e8")"

# --- a library (--stepper-lib) runs in a child of its own: its crash is a status, not vibook's
# end (#50). Explicit Euler on the pendulum, which calls abort() after ABORT_AFTER steps, prints
# to its standard output on every step, or hangs on its first step (symplectic Euler on the
# pendulum otherwise: a correct first-order method).
cat >"$tmp/lib.cpp" <<'CPP'
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>
struct Ctx { long steps; long abort_after; bool chatty, hang; };
extern "C" {
int vibook_stepper_abi_version() { return 1; }
void* vibook_stepper_create(int dof, const char* arg) {
  if (dof != 1) return nullptr;
  return new Ctx{0, std::strncmp(arg, "abort", 5) == 0 ? std::atol(arg + 5) : -1,
                 std::strcmp(arg, "chatty") == 0, std::strcmp(arg, "hang") == 0};
}
int vibook_stepper_step(void* c, double h, double* q, double* p) {
  Ctx* x = static_cast<Ctx*>(c);
  if (x->hang) sleep(100000);
  if (x->abort_after >= 0 && x->steps++ >= x->abort_after) std::abort();
  if (x->chatty) std::printf("step %ld\n", x->steps++);
  *p -= h * std::sin(*q);
  *q += h * *p;
  return 0;
}
void vibook_stepper_destroy(void* c) { delete static_cast<Ctx*>(c); }
}
CPP
PL=(--problem pendulum --expected-order 1 --steps 2048 --h-list 0.1,0.05,0.025)
if ${CXX:-g++} -shared -fPIC -O1 -o "$tmp/lib.so" "$tmp/lib.cpp" 2>"$tmp/cc.err"; then
  "$V" verify --stepper-lib "$tmp/lib.so" --stepper-arg abort0 "${PL[@]}" >"$tmp/o9" 2>"$tmp/e9"
  s=$?
  [ $s = 3 ] && [ "$(wc -l <"$tmp/e9")" = 1 ] && grep -q "first step.*SIGABRT" "$tmp/e9" &&
    ok || bad "abort at the first step: status $s, $(cat "$tmp/e9")"
  "$V" verify --stepper-lib "$tmp/lib.so" --stepper-arg abort3000 "${PL[@]}" >"$tmp/o10" 2>"$tmp/e10"
  s=$?
  [ $s = 3 ] && [ "$(wc -l <"$tmp/e10")" = 1 ] && grep -q "SIGABRT" "$tmp/e10" && ok ||
    bad "abort later: status $s, $(cat "$tmp/e10")"
  "$V" verify --stepper-lib "$tmp/lib.so" --stepper-arg chatty "${PL[@]}" >"$tmp/o11" 2>"$tmp/e11"
  s=$?
  [ $s = 0 ] && ! grep -q "^step " "$tmp/o11" && grep -Eq "^verdict +PASS" "$tmp/o11" && ok ||
    bad "a library printing on stdout: status $s, $(head -c 300 "$tmp/e11")"
  "$V" verify --stepper-lib "$tmp/lib.so" --stepper-arg hang "${PL[@]}" --stepper-timeout 0.5 \
    >"$tmp/o12" 2>"$tmp/e12"
  s=$?
  [ $s = 2 ] && grep -q "did not answer within 0.5 s" "$tmp/e12" && ! pgrep -f "$tmp/lib" >/dev/null &&
    ok || bad "a library that hangs: status $s, $(cat "$tmp/e12")"
  head -c 3000 "$tmp/lib.so" >"$tmp/truncated.so"
  "$V" verify --stepper-lib "$tmp/truncated.so" "${PL[@]}" >"$tmp/o13" 2>"$tmp/e13"
  s=$?
  [ $s = 2 ] && [ "$(wc -l <"$tmp/e13")" = 1 ] && grep -q -- "--stepper-lib" "$tmp/e13" && ok ||
    bad "a truncated library: status $s, $(cat "$tmp/e13")"
else
  bad "the test library did not compile: $(head -c 300 "$tmp/cc.err")"
fi

echo "stepper children: $pass passed, $fail failed"
[ "$fail" = 0 ]
