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

echo "stepper children: $pass passed, $fail failed"
[ "$fail" = 0 ]
