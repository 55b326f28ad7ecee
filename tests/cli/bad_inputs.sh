#!/usr/bin/env bash
# Bad and edge inputs of the `vibook` command, as a table: each row gives the exit status, a
# word the single stderr line must contain (the argument it names), and the arguments. Every
# row is also checked to leave no file behind in the working directory (a numerical failure,
# status 3, may leave only FILE.partial, which its message names).
# Usage: bad_inputs.sh path/to/vibook
set -u
V=$(realpath "$1")
work=$(mktemp -d)
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
cd "$work" || exit 2
pass=0 fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# row STATUS WORD ARGS...
row() {
  local want=$1 word=$2; shift 2
  rm -rf out && mkdir out && cd out || exit 2
  ln -s target.csv link.csv
  printf 'x\n' > readonly.csv && chmod a-w readonly.csv
  local before; before=$(ls -A | sort)
  "$V" "$@" >../stdout 2>../stderr
  local got=$?
  local after; after=$(ls -A | sort)
  cd .. || exit 2
  local lines; lines=$(wc -l <stderr)
  if [ "$got" != "$want" ]; then
    bad "vibook $* -> exit $got, expected $want: $(cat stderr)"; return
  fi
  if [ "$lines" != 1 ] || ! grep -qF -- "$word" stderr; then
    bad "vibook $*: want one stderr line naming '$word', got $lines: $(cat stderr)"; return
  fi
  if [ "$want" = 2 ] && [ -s stdout ]; then
    bad "vibook $*: status 2 must come before any output, but stdout has: $(head -c 200 stdout)"
    return
  fi
  local extra; extra=$(comm -13 <(echo "$before") <(echo "$after"))
  if [ -n "$extra" ] && { [ "$want" != 3 ] || echo "$extra" | grep -qv '\.partial$'; }; then
    bad "vibook $*: left files behind: $extra"; return
  fi
  pass=$((pass + 1))
}

R=(run --problem kepler --method sv)
# --- the command word and the subcommands' own options ------------------------------------
row 2 "nosuchcmd"        nosuchcmd
row 2 "--frobnicate"     run --frobnicate
row 2 "--problem"        run --problem foo --method sv --csv a.csv
row 2 "--method"         run --problem kepler --method rk4 --csv a.csv
row 2 "--problem"        run --method sv --csv a.csv
# --- numbers: empty, garbage, non-finite, out of range, out of domain ------------------------
row 2 "--h"              "${R[@]}" --h "" --csv a.csv
row 2 "--h"              "${R[@]}" --h abc --csv a.csv
row 2 "--h"              "${R[@]}" --h 0.01x --csv a.csv
row 2 "--h"              "${R[@]}" --h 0 --csv a.csv
row 2 "--h"              "${R[@]}" --h -0.1 --csv a.csv
row 2 "--h"              "${R[@]}" --h nan --csv a.csv
row 2 "--h"              "${R[@]}" --h inf --csv a.csv
row 2 "--h"              "${R[@]}" --h 1e400 --csv a.csv
row 2 "--h"              "${R[@]}" --h 1e-18 --csv a.csv
row 2 "--h"              "${R[@]}" --h 1e300 --csv a.csv
row 2 "--t-end"          "${R[@]}" --t-end 1e300 --csv a.csv
row 2 "--t-end"          "${R[@]}" --t-end 0 --csv a.csv
row 2 "--t-end"          "${R[@]}" --t-end "" --csv a.csv
row 2 "--periods"        "${R[@]}" --periods -1 --csv a.csv
row 2 "--periods"        "${R[@]}" --periods 1e15 --csv a.csv
row 2 "--t-end"          "${R[@]}" --t-end 1 --periods 1 --csv a.csv
row 2 "--periods"        run --problem pendulum --method sv --periods 1 --csv a.csv
row 2 "--e"              "${R[@]}" --e "" --csv a.csv
row 2 "--e"              "${R[@]}" --e 1 --csv a.csv
row 2 "--e"              "${R[@]}" --e -0.1 --csv a.csv
row 2 "--e"              "${R[@]}" --e nan --csv a.csv
row 2 "--e"              run --problem harmonic --method sv --e 0.5 --csv a.csv
row 2 "--every"          "${R[@]}" --every 0 --csv a.csv
row 2 "--every"          "${R[@]}" --every 1.5 --csv a.csv
row 2 "--every"          "${R[@]}" --every "" --csv a.csv
# --- vectors ------------------------------------------------------------------------------
row 2 "--q0"             "${R[@]}" --q0 1,,0 --p0 0,1 --csv a.csv
row 2 "--q0"             "${R[@]}" --q0 "" --p0 0,1 --csv a.csv
row 2 "--q0"             "${R[@]}" --q0 1, --p0 0,1 --csv a.csv
row 2 "--q0"             "${R[@]}" --q0 1 --p0 0,1 --csv a.csv
row 2 "--q0"             "${R[@]}" --q0 1,0,0 --p0 0,1 --csv a.csv
row 2 "--p0"             "${R[@]}" --q0 1,0 --csv a.csv
row 2 "--p0"             "${R[@]}" --q0 1,0 --p0 0,nan --csv a.csv
row 2 "--q0"             run --problem harmonic --method sv --q0 1,2 --csv a.csv
row 2 "--q0/--p0"        "${R[@]}" --q0 1,0 --p0 0,2 --periods 1 --csv a.csv
# --- options of another method ---------------------------------------------------------------
row 2 "--h0"             "${R[@]}" --h0 0.1 --csv a.csv
row 2 "--discrete-lagrangian" "${R[@]}" --discrete-lagrangian sv --csv a.csv
row 2 "--tol"            "${R[@]}" --tol 1e-3 --csv a.csv
row 2 "--energy-target"  "${R[@]}" --energy-target initial --csv a.csv
row 2 "--solver"         "${R[@]}" --solver generic --csv a.csv
row 2 "--precision"      "${R[@]}" --precision quad --csv a.csv
row 2 "--digits"         run --problem kepler --method epavi --digits 30 --csv a.csv
row 2 "--digits"         run --problem kepler --method epavi --precision mpfr --digits x --csv a.csv
# Ranges that depend on the precision are checked before the CSV header (--csv -: stdout).
E=(run --problem kepler --method epavi --periods 0.01 --csv -)
row 2 "--digits"         "${E[@]}" --precision mpfr --digits 1
row 2 "--digits"         "${E[@]}" --precision mpfr --digits 2
row 2 "--digits"         "${E[@]}" --precision mpfr --digits 301
row 2 "--digits"         "${E[@]}" --precision mpfr --digits 100000
row 2 "--tol"            "${E[@]}" --tol 1
row 2 "--tol"            "${E[@]}" --tol 1e-30
row 2 "--tol"            "${E[@]}" --precision mpfr --digits 30 --tol 1e-40
row 2 "--h0"             "${E[@]}" --h 0.01 --h0 0.02
row 2 "--h"              "${E[@]}" --e 0.999999
row 2 "--h0"             "${E[@]}" --e 0.99 --h0 0.01
row 2 "--alpha"          "${R[@]}" --alpha 0.5 --csv a.csv
row 2 "--alpha"          run --problem kepler --method vi1 --alpha "" --csv a.csv
row 2 "--alpha"          run --problem kepler --method vi1 --alpha 1.5 --csv a.csv
row 2 "--e"              run --problem kepler --method epavi --e 0.5 --q0 1,0 --p0 0,1 --csv a.csv
row 2 "--e"              "${R[@]}" --e 0.5 --q0 1,0 --p0 0,1 --csv a.csv
row 2 "--h0"             run --problem kepler --method epavi --h0 1e-300 --csv a.csv
row 2 "--h0"             run --problem kepler --method avi1 --h0 -1 --csv a.csv
row 2 "--tol"            run --problem kepler --method epavi --tol 1e-20 --csv a.csv
row 2 "--q0/--p0"        run --problem kepler --method avi2 --q0 1,0 --p0 0,2 --csv a.csv
row 2 "--c"              run --problem relativistic-kepler --method vi --csv a.csv
row 2 "--c"              run --problem relativistic-kepler --method vi --c 1e155 --csv a.csv
row 2 "--c"              run --problem relativistic-kepler --method vi --c "" --csv a.csv
row 2 "--c"              "${R[@]}" --c 5 --csv a.csv
row 2 "--t-end"          run --problem relativistic-kepler --method vi --c 5 --t-end 3 --csv a.csv
row 2 "--tau-end"        "${R[@]}" --tau-end 3 --csv a.csv
row 2 "not bound"        run --problem relativistic-kepler --method vi --c 5 --p0 0,3 --csv a.csv
# --- output paths: checked before any work -----------------------------------------------------
row 2 "--csv"            "${R[@]}" --csv ""
row 2 "--csv"            "${R[@]}" --csv .
row 2 "--csv"            "${R[@]}" --csv link.csv
row 2 "--csv"            "${R[@]}" --csv readonly.csv
row 2 "--csv"            "${R[@]}" --csv nodir/a.csv
row 2 "--csv"            "${R[@]}" --csv a.csv/
row 2 "--json-out"       claims --json-out nodir/c.json
row 2 "--json-out"       claims --json-out .
row 2 "--figures-dir"    claims --figures-dir nodir
row 2 "ID"               figure no-such-figure --out f
# --- numerical failures: status 3, where and from which state ----------------------------------
row 3 "at step 1"        run --problem kepler --method del-generic --q0 1,0 --p0 0,1.4 --h 2 --t-end 100 --csv d.csv
row 2 "--q0/--p0"        run --problem harmonic --method sv --q0 1e300 --csv a.csv  # H = inf: before any work (#27)
row 3 "step"             run --problem kepler --method avi1 --e 0.99 --h0 0.0005 --csv a.csv
row 3 "no admissible time step" run --problem kepler --method epavi --e 0.99 --h0 0.0005 --csv a.csv
# --- the symbolic engine -----------------------------------------------------------------------
M=(modified --method sv)
row 2 "--order"          "${M[@]}"
row 2 "--order"          "${M[@]}" --order 11
row 2 "--order"          "${M[@]}" --order x
row 2 "--dim"            "${M[@]}" --order 2 --dim 0
row 2 "--dim"            "${M[@]}" --order 2 --dim 4
row 2 "--what"           "${M[@]}" --order 2 --what everything
row 2 "--format"         "${M[@]}" --order 2 --format maple
row 2 "--cross-check"    "${M[@]}" --order 2 --what lagrangian --cross-check
row 2 "--components"     "${M[@]}" --order 2 --dim 2 --components
row 2 "--alpha"          modified --method vi1 --potential kepler --order 1 --alpha 1/2x
row 2 "--alpha"          modified --method vi1 --potential kepler --order 1 --alpha ""
row 2 "--alpha"          modified --method vi1 --potential kepler --order 1 --alpha 2
row 2 "--alpha"          modified --method vi1 --potential kepler --order 1 --alpha 1/0
row 2 "--alpha"          modified --method sv --potential kepler --order 1 --alpha 1/2
# modified --ld: the user's own discrete Lagrangian, checked before any work
TRAP='h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)'
row 2 "--method"         modified --order 2
row 2 "--ld"             modified --method sv --ld "$TRAP" --potential 'x^4' --order 2
row 2 "--ld"             modified --ld 'h*((q1-q0)^2/(2*h^2) - V(q0' --potential 'x^4' --order 2
row 2 "--ld"             modified --ld 'h*(q1[4]-q0[4])^2/(2*h^2)' --order 2
row 2 "--potential"      modified --ld "$TRAP" --potential kepler --order 2
row 2 "--alpha"          modified --ld "$TRAP" --potential 'x^4' --order 2 --alpha 1/2
row 2 "--order"          modified --ld "$TRAP" --potential 'x^4' --order 11
# modified --method M --lagrangian EXPR: the user's continuous Lagrangian
row 2 "--lagrangian"     modified --method vi1 --lagrangian 'v^2/2 - V(q)' --potential 'x^4' --order 2
row 2 "--lagrangian"     modified --method sv --ld "$TRAP" --lagrangian 'v^2/2' --potential 'x^4' --order 2
row 2 "--lagrangian"     modified --method sv --lagrangian 'q^2/2' --order 2
row 2 "--lagrangian"     modified --method sv --lagrangian 'v^2/2 - (q' --order 2
row 2 "--lagrangian"     modified --method sv --lagrangian 'v[4]^2/2' --order 2
row 2 "--potential"      modified --method sv --lagrangian 'v^2/2 - V(q)' --order 2
row 2 "--alpha"          modified --method sv --lagrangian 'v^2/2' --order 2 --alpha 1/2
# --param: symbolic constants of the typed texts
row 2 "--param"          modified --method sv --potential generic --order 2 --param k
row 2 "--param"          modified --method sv --lagrangian 'v^2/2 - k*q^2/2' --order 2 --param k-1
row 2 "--param"          modified --method sv --lagrangian 'v^2/2 - q^2/2' --order 2 --param q
row 2 "--param"          modified --method sv --lagrangian 'v^2/2 - k*q^2/2' --order 2 --param k,k
row 2 "--lagrangian"     modified --method sv --lagrangian 'v^2/2 - k*q^2/2' --order 2 --param c
# --- verify: typed expressions ------------------------------------------------------------------
SIMPSON='h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)'
HH='x^2/2+y^2/2+x^2*y-y^3/3'
VF=(verify --t-end 0.5 --h-list 0.1,0.05,0.025 --steps 1024)
row 2 "--ld"             verify --potential "$HH"
row 2 "--potential"      verify --ld "$SIMPSON"
row 2 "--ld"             "${VF[@]}" --ld 'h*(q1-q0)^2/(2*h^2' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)^2/h - w' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)^2/h - W(q0)' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)^2/h + q0' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)/h' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)^2/h - h*V(q0)/0' --potential "$HH"
row 2 "--potential"      "${VF[@]}" --ld "$SIMPSON" --potential 'x^2 + t'
row 2 "--potential"      "${VF[@]}" --ld "$SIMPSON" --potential 'x^2 +'
row 2 "--dim"            "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --dim 1
row 2 "--dim"            "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --dim 7
row 2 "--dim"            "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --dim 0
row 2 "--lagrangian"     "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --lagrangian 'v^2/2 - q0'
row 2 "--lagrangian"     "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --lagrangian 'v^2/2' --hamiltonian 'p^2/2'
row 2 "--hamiltonian"    "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --hamiltonian 'p^2/2 - v'
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)^2/(2*h) - h*q0[7]' --potential "$HH"
row 2 "--ld"             "${VF[@]}" --ld '(q1-q0)^2/(2*h) - h*grad(W)(q0)' --potential "$HH"
row 2 "--q0"             "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --q0 1,2,3
row 2 "--p0"             "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --p0 1,,2
row 2 "--h-list"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --h-list 0.1,0.05
row 2 "--steps"          "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --steps 10
row 2 "--modified-order" "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --modified-order 9
row 2 "--format"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --format python
row 2 "--json-out"       "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --json-out link.csv
row 2 "--json-out"       "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --json-out ""
row 2 "--report"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report link.csv
row 2 "--report"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report readonly.csv
row 2 "--report"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report /nonexistent/r
row 2 "--report"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report .
row 2 "--report"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report ..
row 2 "--report"         "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report ""
# A discrete Lagrangian without the velocity coupling D1 D2 L_d: degenerate, status 3.
row 3 "degenerate"       "${VF[@]}" --ld 'q0^2 + q1^2 - h*V(q0)' --potential "$HH"
row 3 "not finite"       "${VF[@]}" --ld 'h*((q1-q0)^2/(2*h^2) - log(-q0^2))' --potential "$HH"
row 3 "not finite"       "${VF[@]}" --ld 'h*((q1-q0)^2/(2*h^2) - V(1e300*q0))' --potential "$HH"
row 2 "divides by zero"  "${VF[@]}" --ld 'h*((q1-q0)^2/(2*h^2) - 0^(-1)*V(q0))' --potential "$HH"
row 2 "twice"            verify --ld "$SIMPSON" --potential "$HH" --h-list 0.1,0.1,0.1
row 2 "--json-out"       "${VF[@]}" --ld "$SIMPSON" --potential "$HH" --report rr --json-out rr/v.json
row 2 "claims --check"   figure check-modified
row 2 "given twice"      figure vermeeren-fig1 vermeeren-fig1
# The initial state is checked before any output (#27: these exited 3 after the CSV header).
row 2 "--q0/--p0"        run --problem kepler --method sv --q0 0,0 --p0 1,0 --csv out.csv
row 2 "--q0/--p0"        run --problem kepler --method sv --q0 1e308,0 --p0 1e308,0 --csv out.csv
row 2 "--q0/--p0"        run --problem pendulum --method sv --q0 1e308 --p0 1e308 --csv out.csv
# --- integers: whole, base 10 (#27: "010" was octal, "0x2", " 2", "+2" and "" were accepted) --
row 2 "--order"          modified --method sv --order 0x2
row 2 "--order"          modified --method sv --order ' 2'
row 2 "--order"          modified --method sv --order +2
row 2 "--order"          modified --method sv --order ''
row 2 "out of range"     modified --method sv --order 99999999999999999999
row 2 "--dim"            modified --method sv --order 1 --dim 0x1
# --- a closed or full standard error never turns an error into a crash (#27: SIGABRT, 134) ------
for args in "run --problem kepler --method sv --h 0" "bogus" "modified --method sv --order x"; do
  # shellcheck disable=SC2086
  "$V" $args 2>&- >/dev/null; st=$?
  [ "$st" = 2 ] && pass=$((pass + 1)) || bad "vibook $args 2>&-: status $st, want 2"
  if [ -w /dev/full ]; then
    # shellcheck disable=SC2086
    "$V" $args 2>/dev/full >/dev/null; st=$?
    [ "$st" = 2 ] && pass=$((pass + 1)) || bad "vibook $args 2>/dev/full: status $st, want 2"
  fi
done
# A closed pipe is an output that could not be written: status 4, not SIGPIPE (141).
"$V" run --problem kepler --method sv --t-end 200 --csv - 2>/dev/null | head -1 >/dev/null
st=${PIPESTATUS[0]}
[ "$st" = 4 ] && pass=$((pass + 1)) || bad "run --csv - | head -1: status $st, want 4"
"$V" run --problem kepler --method sv --csv - >&- 2>&-; st=$?
[ "$st" = 4 ] && pass=$((pass + 1)) || bad "run --csv - with stdout and stderr closed: $st"
if [ -w /dev/full ]; then
  "$V" --help >/dev/full 2>/dev/null; st=$?
  [ "$st" = 4 ] && pass=$((pass + 1)) || bad "--help > /dev/full: status $st, want 4"
fi
# --- a signal during a run: 128 + signal, the rows kept in FILE.partial, nothing hidden left ----
for sig in INT TERM; do
  rm -rf sg && mkdir sg
  (cd sg && exec "$V" run --problem kepler --method sv --h 0.0001 --t-end 100000 --csv long.csv \
     2>../sg.err) & pid=$!
  sleep 1
  kill -"$sig" "$pid"; wait "$pid"; st=$?
  want=$((128 + $(kill -l "$sig")))
  [ "$st" = "$want" ] && [ -s sg/long.csv.partial ] && [ "$(ls -A sg)" = "long.csv.partial" ] &&
    grep -q "interrupted by SIG$sig at step .*long.csv.partial" sg.err && pass=$((pass + 1)) ||
    bad "SIG$sig during run: status $st (want $want), left $(ls -A sg), said $(cat sg.err)"
done
rm -rf sg sg.err
# --- a signal during figures or claims: 128 + signal, no hidden temporary left, and a directory
# the command created (still empty) removed; what the user had stays ---------------------------
for sig in INT TERM HUP; do
  rm -rf sg && mkdir -p sg/D && echo mine > sg/D/notes.txt
  (cd sg && exec "$V" figures --out D 2>../sg.err) & pid=$!
  sleep 2
  kill -"$sig" "$pid"; wait "$pid"; st=$?
  want=$((128 + $(kill -l "$sig")))
  hidden=$(find sg -name '.*' | head -3)
  [ "$st" = "$want" ] && [ -z "$hidden" ] && [ "$(cat sg/D/notes.txt)" = mine ] &&
    [ "$(wc -l <sg.err)" = 1 ] && grep -q "interrupted by SIG$sig" sg.err && pass=$((pass + 1)) ||
    bad "SIG$sig during figures: status $st (want $want), hidden: $hidden, said $(cat sg.err)"
  rm -rf sg && mkdir sg
  (cd sg && exec "$V" claims --html-dir new/H 2>../sg.err) & pid=$!
  sleep 2
  kill -"$sig" "$pid"; wait "$pid"; st=$?
  [ "$st" = "$want" ] && [ -z "$(ls -A sg)" ] && pass=$((pass + 1)) ||
    bad "SIG$sig during claims --html-dir: status $st (want $want), left $(ls -A sg)"
done
rm -rf sg sg.err
# --- a gnuplot that never returns is stopped after VIBOOK_GNUPLOT_TIMEOUT seconds -----------------
mkdir -p slow && printf '#!/bin/sh\nexec sleep 600\n' > slow/gnuplot && chmod +x slow/gnuplot
start=$(date +%s)
PATH="$PWD/slow:$PATH" VIBOOK_GNUPLOT_TIMEOUT=2 "$V" figure vermeeren-fig1 --out gp >/dev/null 2>stderr
st=$?
took=$(($(date +%s) - start))
[ "$st" = 1 ] && [ "$took" -lt 60 ] && grep -q "did not finish .* within 2 s" stderr &&
  pass=$((pass + 1)) || bad "hanging gnuplot: status $st after ${took}s: $(cat stderr)"
PATH="$PWD/slow:$PATH" VIBOOK_GNUPLOT_TIMEOUT=x "$V" figure vermeeren-fig1 --out gp >/dev/null 2>stderr
[ $? = 1 ] && grep -q "VIBOOK_GNUPLOT_TIMEOUT='x'" stderr && pass=$((pass + 1)) ||
  bad "VIBOOK_GNUPLOT_TIMEOUT=x: $(cat stderr)"
rm -rf slow gp
# --- standard output that cannot be written: status 4 ------------------------------------------
if [ -w /dev/full ]; then
  "$V" run --problem kepler --method sv --csv - >/dev/full 2>stderr
  [ $? = 4 ] && [ "$(wc -l <stderr)" = 1 ] && grep -q "I/O error" stderr && pass=$((pass + 1)) ||
    bad "--csv - > /dev/full: want status 4 and one line, got: $(cat stderr)"
  "$V" modified --method sv --order 2 >/dev/full 2>stderr
  [ $? = 4 ] && pass=$((pass + 1)) || bad "modified > /dev/full: want status 4: $(cat stderr)"
fi
# A device is written through, never replaced.
"$V" "${R[@]}" --t-end 1 --csv /dev/null 2>stderr && [ -c /dev/null ] && pass=$((pass + 1)) ||
  bad "--csv /dev/null: $(cat stderr)"
# A link is refused and left alone; its target is not created.
mkdir -p lk && ln -sf target.csv lk/l.csv && "$V" "${R[@]}" --csv lk/l.csv 2>/dev/null
[ -L lk/l.csv ] && [ ! -e lk/target.csv ] && pass=$((pass + 1)) || bad "symlink replaced"

# --- --max-seconds: status 3 naming the limit and the stage reached (run keeps FILE.partial) ------
row 3 "--max-seconds 0.5 in: " modified --method sv --dim 3 --order 8 --max-seconds 0.5
row 3 "stopped by --max-seconds" run --problem kepler --method sv --h 1e-6 --t-end 1e6 --csv a.csv --max-seconds 0.5
row 3 "--max-seconds 0.5 in: " verify --ld "$SIMPSON" --potential "$HH" --steps 100000000 --max-seconds 0.5
for bad_limit in 0 -1 x 1e9 nan; do
  row 2 "--max-seconds" modified --method sv --order 2 --max-seconds "$bad_limit"
done
row 2 "--max-seconds" run --problem kepler --method sv --csv a.csv --max-seconds 0
row 2 "--max-seconds" verify --ld "$SIMPSON" --potential "$HH" --max-seconds -2
# --- claims --figures-dir with a claims.json vibook did not write: status 2 naming the file --------
mkdir -p fdir/vermeeren-fig1 && printf '{bad' > fdir/vermeeren-fig1/claims.json
row 2 "fdir/vermeeren-fig1/claims.json" claims --figures-dir ../fdir
printf '{"claims": []}\n' > fdir/vermeeren-fig1/claims.json
row 2 "does not hold claim" claims --figures-dir ../fdir
rm -rf fdir
# claims --json-out writes the JSON *and* prints the ledger, as its help says.
"$V" claims --check check-s-eq39 --json-out cj.json >stdout 2>stderr &&
  grep -q "S-" stdout && [ -s cj.json ] && pass=$((pass + 1)) ||
  bad "claims --json-out: the ledger was not printed: $(head -3 stdout) $(cat stderr)"
rm -f cj.json

# An empty step or step count is refused on every route (the map routes once read it as "the
# default").
row 2 "--h"              verify --method gauss:1 --problem pendulum --h ""
row 2 "--steps"          verify --splitting leapfrog --problem pendulum --steps ""

# The same limits on every route: the --ld route's order study and energy run too.
row 2 "(0, 1e4]"         verify --ld "$SIMPSON" --potential "$HH" --t-end 1e5
row 2 "at most 1e9"      verify --ld "$SIMPSON" --potential "$HH" --h 1e4 --steps 1000000
row 2 "(0, 20]"          verify --ld "$SIMPSON" --potential "$HH" --expected-order 21
row 2 "(0, 20]"          verify --method gauss:2 --problem pendulum --expected-order 21

# --- inputs read forever (the fourth probe): a device, a FIFO, a deep nesting ------------------
row 2 "is not a regular file" verify --tableau /dev/zero
row 2 "is not a regular file" verify --tableau /dev/urandom
mkfifo fifo.json
row 2 "is not a regular file" verify --tableau ../fifo.json
rm -f fifo.json
head -c 1100000 /dev/zero | tr '\0' ' ' > big.json
row 2 "is larger than 1048576 bytes" verify --tableau ../big.json
rm -f big.json
deep=x
for _ in $(seq 100); do deep="sin($deep)"; done
row 2 "nests deeper than 64 levels" verify --ld "h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)" --potential "$deep"
# --- statuses as promised: an inconsistent method never passes (a verdict, 5) -------------------
row 5 "consistency" verify --composition sv --coefficients 1,1 --problem pendulum --steps 2048
row 5 "consistency" verify --ld '(q1-q0)^2/2 - V(q1)' --potential='-cos(x)' --q0 1 --p0 0.5 --steps 2048
# --- an argument's fault is 2, never 3 --------------------------------------------------------
row 2 "--coefficients" verify --composition sv --coefficients 1e9223372036854775808
row 2 "--problem: is empty" verify --problem '' --composition sv --coefficients yoshida4
row 2 "--q0: is empty" verify --ld "$SIMPSON" --potential "$HH" --q0 ''
row 2 "--lagrangian='-v^2/2 - q^2/2'" verify --method gauss:2 --lagrangian '-v^2/2 - q^2/2'
row 2 "expected ')'" verify --ld "$SIMPSON" --potential '((((x'
row 2 "--stepper-cmd: is empty" verify --stepper-cmd ' ' --expected-order 2
# --- one line, of readable length: an argument echoed whole is cut (#50) ---------------------
long=$(printf 'x+%.0s' $(seq 1500))w
row 2 "characters cut ...] " verify --ld "$SIMPSON" --potential "$long"
[ "$(wc -c <stderr)" -le 320 ] && grep -q "unknown symbol 'w'" stderr && pass=$((pass + 1)) ||
  bad "a 3000-character argument's message: $(wc -c <stderr) characters: $(cat stderr)"

echo "bad inputs: $pass passed, $fail failed"
[ "$fail" = 0 ]
