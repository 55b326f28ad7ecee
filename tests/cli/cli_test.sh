#!/usr/bin/env bash
# The `vibook` command as a user calls it: exit statuses, one-line errors, CSV columns,
# figures on disk. Usage: cli_test.sh path/to/vibook
set -u
V=$(realpath "$1")
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)  # the source tree
# Under ASan/UBSan (VIBOOK_SANITIZED=1, set by CTest in the sanitize preset) the extended-
# precision runs are shorter.
SAN=${VIBOOK_SANITIZED:-0}
PERIODS=0.5
[ "$SAN" = 1 ] && PERIODS=0.1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# expect STATUS PATTERN -- ARGS...: exit status and a one-line stderr matching PATTERN.
expect() {
  local want=$1 pattern=$2; shift 3
  "$V" "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" != "$want" ]; then bad "vibook $* -> exit $got, expected $want ($(cat "$tmp/err"))"; return; fi
  if [ -n "$pattern" ]; then
    if [ "$(wc -l <"$tmp/err")" != 1 ] || ! grep -q -- "$pattern" "$tmp/err"; then
      bad "vibook $*: stderr should be one line matching '$pattern', got: $(cat "$tmp/err")"; return
    fi
  fi
  ok
}

# --- help and version ---------------------------------------------------------------------
expect 0 "" -- --help
expect 0 "" -- run --help
expect 0 "" -- --version
grep -q "vibook" "$tmp/out" && ok || bad "--version prints the name"

# --- bad arguments: exit 2, one line naming the argument ----------------------------------
expect 2 "--problem" -- run --problem foo --method sv --csv "$tmp/a.csv"
expect 2 "--method" -- run --problem kepler --method rk4 --csv "$tmp/a.csv"
expect 2 "--h" -- run --problem kepler --method sv --h 0 --csv "$tmp/a.csv"
expect 2 "--h" -- run --problem kepler --method sv --h -0.1 --csv "$tmp/a.csv"
expect 2 "--h" -- run --problem kepler --method sv --h nan --csv "$tmp/a.csv"
expect 2 "--h" -- run --problem kepler --method sv --h
expect 2 "--e" -- run --problem kepler --method sv --e 1 --csv "$tmp/a.csv"
expect 2 "--e" -- run --problem kepler --method sv --e -0.1 --csv "$tmp/a.csv"
expect 2 "--e" -- run --problem kepler --method sv --e nan --csv "$tmp/a.csv"
expect 2 "--problem" -- run --method sv --csv "$tmp/a.csv"
expect 2 "--csv" -- run --problem kepler --method sv --csv /nonexistent/dir/out.csv
expect 2 "--q0" -- run --problem harmonic --method sv --q0 1,2 --csv "$tmp/a.csv"
expect 2 "--t-end" -- run --problem kepler --method sv --t-end 1 --periods 1 --csv "$tmp/a.csv"
expect 2 "initial state" -- run --problem kepler --method sv --q0 1,0 --p0 0,2 --periods 1 --csv "$tmp/a.csv"
expect 2 "ID" -- figure no-such-figure --out "$tmp/f"
expect 2 "" -- frobnicate
[ ! -e "$tmp/a.csv" ] && ok || bad "a rejected run must not leave an output file"

# --- every method on every problem --------------------------------------------------------
for p in harmonic pendulum kepler; do
  for m in se se-adjoint sv midpoint del-generic; do
    expect 0 "" -- run --problem "$p" --method "$m" --h 0.05 --t-end 2 --every 10 --csv "$tmp/$p-$m.csv"
  done
done
head -1 "$tmp/kepler-sv.csv" | grep -qx "step,t,q1,q2,p1,p2,H,L,ecc,omega" && ok || bad "kepler CSV header"
head -1 "$tmp/kepler-midpoint.csv" | grep -qx "step,t,q1,q2,p1,p2,H,L,ecc,omega,residual,iterations" && ok || bad "implicit CSV header"
head -1 "$tmp/harmonic-sv.csv" | grep -qx "step,t,q,p,H" && ok || bad "harmonic CSV header"
# 40 steps, every 10th: rows 0,10,20,30,40 (+ header), ending exactly at t = 2.
[ "$(wc -l <"$tmp/kepler-sv.csv")" = 6 ] && ok || bad "--every rows: $(wc -l <"$tmp/kepler-sv.csv")"
tail -1 "$tmp/kepler-sv.csv" | grep -q "^40,2," && ok || bad "last row at step 40, t = 2"
# A step that does not divide T: the last step is shortened and the run still ends at T.
expect 0 "" -- run --problem harmonic --method sv --h 0.3 --t-end 1 --csv "$tmp/b.csv"
tail -1 "$tmp/b.csv" | grep -q "^4,1," && ok || bad "shortened last step ends at t = 1"
# --periods for Kepler: 2π·a^{3/2}; from --e, a = 1 and one period is 2π (629 steps of 0.01,
# the last one shortened).
expect 0 "" -- run --problem kepler --method sv --e 0.3 --h 0.01 --periods 1 --every 100000 --csv "$tmp/c.csv"
tail -1 "$tmp/c.csv" | grep -q "^629,6.2831853071795862," && ok || bad "one Kepler period: $(tail -1 "$tmp/c.csv")"

# --- adaptive methods (Sharma et al. 2022) on Kepler ----------------------------------------
for m in epavi avi1 avi2; do
  expect 0 "" -- run --problem kepler --method "$m" --e 0.7 --h0 0.001 --periods 1 --every 100 --csv "$tmp/ad-$m.csv"
done
# As a new user types it: --problem follows from the method (kepler), the CSV goes to standard
# output. One period at e = 0.1, h0 = 1e-3 with the paper's marching: |E_d − E_1| <= 1e-13.
expect 0 "" -- run --method epavi --e 0.1 --h0 0.001 --periods 1
python3 - "$tmp/out" <<'PY' && ok || bad "epavi, one period at e = 0.1: |E_d - E_1| <= 1e-13 on stdout"
import sys, csv
rows = list(csv.DictReader(open(sys.argv[1])))
drift = max(abs(float(r["E_d_drift"])) for r in rows)
assert len(rows) > 5000 and drift <= 1e-13, (len(rows), drift)
PY
head -1 "$tmp/ad-epavi.csv" | grep -qx "step,t,dt,q1,q2,p1,p2,H,L,ecc,omega,E_d,E_d_drift,residual,iterations" && ok || bad "epavi CSV header"
# Precisions: each runs half a period at e = 0.5; the drift E_k − E_1 shrinks with the precision.
for pr in double long-double double-double quad; do
  expect 0 "" -- run --problem kepler --method epavi --e 0.5 --h0 0.01 --periods $PERIODS --precision "$pr" --every 100000 --csv "$tmp/pr-$pr.csv"
done
expect 0 "" -- run --problem kepler --method epavi --e 0.5 --h0 0.01 --periods $PERIODS --precision mpfr --digits 25 --every 100000 --csv "$tmp/pr-mpfr.csv"
python3 - "$tmp" <<'PY' && ok || bad "drift should shrink with the precision"
import sys, csv
t = sys.argv[1]
d = {p: abs(float(list(csv.DictReader(open(f"{t}/pr-{p}.csv")))[-1]["E_d_drift"]))
     for p in ["double", "long-double", "double-double", "quad", "mpfr"]}
assert d["double-double"] < 1e-24 and d["quad"] < 1e-24 and d["mpfr"] < 1e-18, d
assert d["long-double"] < 1e-15 and d["double"] < 1e-12, d
PY
expect 0 "" -- run --problem kepler --method epavi --e 0.5 --h0 0.01 --periods $PERIODS --energy-target initial --tol 1e-10 --every 100000 --csv "$tmp/target.csv"
expect 2 "--precision" -- run --problem kepler --method epavi --precision octuple --csv "$tmp/r.csv"
expect 2 "--precision" -- run --problem kepler --method avi1 --precision quad --csv "$tmp/r.csv"
expect 2 "--digits" -- run --problem kepler --method epavi --digits 30 --csv "$tmp/r.csv"
expect 2 "--digits" -- run --problem kepler --method epavi --precision mpfr --digits 1 --csv "$tmp/r.csv"
expect 2 "--tol" -- run --problem kepler --method epavi --tol 0 --csv "$tmp/r.csv"
expect 2 "--tol" -- run --problem kepler --method epavi --tol 1e-20 --csv "$tmp/r.csv"
expect 2 "--energy-target" -- run --problem kepler --method epavi --energy-target final --csv "$tmp/r.csv"
expect 2 "--solver" -- run --problem kepler --method epavi --solver newton --csv "$tmp/r.csv"
# The closed-form step (the default): the discrete energy of one period at e = 0.1, h0 = 1e-3
# stays within 1e-13 of E_1 (issue 11's criterion); the generic path runs the same orbit.
expect 0 "" -- run --problem kepler --method epavi --e 0.1 --h0 0.001 --periods 1 --csv "$tmp/ep01.csv"
awk -F, 'NR > 1 { d = $13 < 0 ? -$13 : $13; if (d > m) m = d } END { exit !(NR > 5000 && m <= 1e-13) }' \
  "$tmp/ep01.csv" && ok || bad "epavi e = 0.1: |E_d - E_1| above 1e-13 over one period"
expect 0 "" -- run --problem kepler --method epavi --solver generic --e 0.1 --h0 0.001 --periods $PERIODS --every 1000 --csv "$tmp/ep01g.csv"
expect 2 "--precision" -- run --problem kepler --method sv --precision quad --csv "$tmp/r.csv"
# No admissible step (e = 0.9 from perihelion, see the EpAVI chapter): exit 3, time and state.
expect 3 "no admissible time step" -- run --problem kepler --method epavi --e 0.9 --h0 0.001 --periods 1 --csv "$tmp/r.csv"
grep -q "at t = 0.07.*q = (.*), p = (" "$tmp/err" && ok || bad "failure names time and state: $(cat "$tmp/err")"
head -1 "$tmp/ad-avi2.csv" | grep -qx "step,t,dt,q1,q2,p1,p2,H,L,ecc,omega,residual,iterations" && ok || bad "avi CSV header"
expect 2 "--method" -- run --problem pendulum --method epavi --csv "$tmp/r.csv"
expect 2 "--h0" -- run --problem kepler --method avi1 --h0 -1 --csv "$tmp/r.csv"

expect 2 "--figures-dir" -- claims --figures-dir "$tmp/does-not-exist"

# --- splitting variational integrators (Shen & Sun 2025) on Kepler ---------------------------
for m in vi1 vi1-adjoint vi2 vi2-adjoint; do
  expect 0 "" -- run --problem kepler --method "$m" --e 0.6 --h 0.05 --periods 1 --every 1000 --csv "$tmp/split-$m.csv"
done
expect 0 "" -- run --problem kepler --method vi2 --alpha 0.3 --e 0.6 --h 0.05 --periods 1 --every 1000 --csv "$tmp/split-a.csv"
expect 2 "--alpha" -- run --problem kepler --method vi2 --alpha 1.5 --csv "$tmp/r.csv"
expect 2 "--alpha" -- run --problem kepler --method sv --alpha 0.5 --csv "$tmp/r.csv"
expect 2 "--method" -- run --problem pendulum --method vi1 --csv "$tmp/r.csv"
expect 2 "--method" -- run --problem kepler --method k-symplectic --csv "$tmp/r.csv"

# --- relativistic Kepler (Shen & Sun (3.16)–(3.22)), proper time ----------------------------
for m in k-symplectic vi vi2; do
  expect 0 "" -- run --problem relativistic-kepler --method "$m" --c 5 --q0 0.4,0 --p0 0,2 --h 0.05 --tau-end 40 --every 100 --csv "$tmp/rel-$m.csv"
done
head -1 "$tmp/rel-vi.csv" | grep -qx "step,tau,t,x1,x2,gamma,u1,u2,energy,L,shell" && ok || bad "relativistic CSV header"
tail -1 "$tmp/rel-vi2.csv" | grep -q "^800,40," && ok || bad "relativistic run ends at tau = 40"
expect 2 "--c" -- run --problem relativistic-kepler --method vi --c 0 --csv "$tmp/r.csv"
expect 2 "--c" -- run --problem relativistic-kepler --method vi --c -2 --csv "$tmp/r.csv"
expect 2 "--c" -- run --problem relativistic-kepler --method vi --csv "$tmp/r.csv"
expect 2 "not bound" -- run --problem relativistic-kepler --method vi --c 5 --p0 0,3 --csv "$tmp/r.csv"
expect 2 "centre" -- run --problem relativistic-kepler --method vi --c 1 --csv "$tmp/r.csv"
expect 2 "--method" -- run --problem relativistic-kepler --method sv --c 5 --csv "$tmp/r.csv"
expect 2 "--method" -- run --problem kepler --method vi --csv "$tmp/r.csv"
expect 2 "--tau-end" -- run --problem relativistic-kepler --method vi --c 5 --t-end 3 --csv "$tmp/r.csv"
[ ! -e "$tmp/r.csv" ] && ok || bad "a rejected relativistic run must not leave an output file"

# --- numerical failure: exit 3, the reason, the partial file named -------------------------
expect 3 "partial" -- run --problem kepler --method del-generic --q0 1,0 --p0 0,1.4 --h 2 --t-end 100 --csv "$tmp/d.csv"
[ ! -e "$tmp/d.csv" ] && [ -e "$tmp/d.csv.partial" ] && ok || bad "failed run leaves only FILE.partial"

# --- the modified-equation engine (Vermeeren 2017, Shen & Sun 2025 §4) --------------------------
# A rational --alpha stays exact through the Kepler potential (it printed 18014398509481983/
# 18014398509481984 for 1 and warned about binary64 literals before constant<ex> was exact).
expect 0 "" -- modified --method vi1 --potential kepler --dim 2 --alpha 3/10 --order 1
grep -q "^h^1: -9/10\*r^(-5)\*v2\*x1\*x2" "$tmp/out" && [ ! -s "$tmp/err" ] && ok || bad "modified --alpha 3/10 not exact: $(head -5 "$tmp/out")"
expect 0 "" -- modified --help
expect 2 "--method" -- modified --method rk4 --order 2
expect 2 "--potential" -- modified --method sv --potential morse --order 2
expect 2 "--order" -- modified --method sv --order 11
expect 2 "--order" -- modified --method sv --order -1
expect 2 "--order" -- modified --method sv
expect 2 "--dim" -- modified --method sv --potential kepler --dim 3 --order 2
expect 2 "--dim" -- modified --method sv --potential generic --dim 4 --order 2
expect 2 "--what" -- modified --method sv --order 2 --what everything
expect 2 "--format" -- modified --method sv --order 2 --format maple
expect 2 "--alpha" -- modified --method sv --potential kepler --order 2 --alpha 0.5
expect 2 "--alpha" -- modified --method vi1 --potential kepler --order 1 --alpha half
expect 0 "" -- modified --method vi2 --potential kepler --order 2 --alpha 1/2 --cross-check
grep -q "cross-check" "$tmp/out" && ok || bad "vi2 cross-check"
# Vermeeren (22), cross-checked against the direct route, as text.
expect 0 "" -- modified --method sv --order 4 --cross-check
grep -q "cross-check: the direct route" "$tmp/out" && grep -q "h^2: " "$tmp/out" && ok || bad "modified text output"
# Python output is SymPy source: executed, it gives (22) exactly.
for what in equation lagrangian hamiltonian meshed disc; do
  expect 0 "" -- modified --method sv --order 3 --what $what --format python
  /usr/bin/python3 -c "exec(open('$tmp/out').read())" 2>"$tmp/pyerr" && ok || bad "python output of --what $what does not run: $(cat "$tmp/pyerr")"
done
expect 0 "" -- modified --method sv --order 2 --format python
/usr/bin/python3 - "$tmp/out" <<'PY' && ok || bad "python output of (22) differs"
import sys
from sympy import simplify
exec(open(sys.argv[1]).read())
assert simplify(a - (-U_1 + h**2 * (U_111 * v1**2 - U_1 * U_11) / 12)) == 0, a
PY
expect 0 "" -- modified --method vi1 --potential kepler --order 1 --alpha 1/2 --format python
grep -q "h,p1\|h,x1\|symbols" "$tmp/out" && ok || bad "vi1 kepler python"
expect 0 "" -- modified --method midpoint --potential pendulum --order 2 --what hamiltonian --format latex
grep -q "H_{\\\\mathrm{mod}}" "$tmp/out" && ok || bad "latex hamiltonian"
# an abstract potential in two dimensions: Shen & Sun's vector notation, (4.21) as printed;
# --components gives the component form
expect 0 "" -- modified --method vi1 --potential generic --dim 2 --order 2 --what lagrangian --format latex
grep -qF '\frac{h^{2}}{24}\Bigl(|\nabla \phi|^{2} - 2 \phi_{xx}\langle \dot{x},\dot{x}\rangle + 12 {\phi^{[1]}_{12}} \dot{x}_{1} \dot{x}_{2}\Bigr)' "$tmp/out" &&
  ok || bad "vector notation of (4.21): $(cat "$tmp/out")"
expect 0 "" -- modified --method vi1 --potential generic --dim 2 --order 2 --what lagrangian --format latex --components
grep -qF '{\phi^{[2]}_{1}}' "$tmp/out" && ! grep -qF '\nabla' "$tmp/out" && ok || bad "--components"

# --- symbolic output, the same bytes in every run (#27: a sum's sign followed GiNaC's hash
# order, which address randomisation changes; 4 texts in 6 runs before) -----------------------
for args in "--method sv --potential kepler --order 2" \
            "--method sv --potential kepler --order 2 --format latex" \
            "--method se --potential kepler --order 2 --what lagrangian" \
            "--method vi2 --potential kepler --order 3 --alpha 1/3" \
            "--method midpoint --potential kepler --order 3 --what hamiltonian --format python" \
            "--method vi2 --potential generic --dim 2 --order 2 --format latex"; do
  sums=$(for i in 1 2 3 4; do
           # shellcheck disable=SC2086
           "$V" modified $args | md5sum
         done | sort -u | wc -l)
  [ "$sums" = 1 ] && ok || bad "modified $args: $sums different texts in 4 runs"
done

# --- verify: a typed discrete Lagrangian (the README's and the chapter's example) -------------
expect 0 "" -- verify --ld 'h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)' \
  --potential 'x^2/2+y^2/2+x^2*y-y^3/3' --q0 0,0.1 --p0 0.35,0 --json-out "$tmp/verify.json"
for want in "order  *\(1\.99\|2\.00\)[0-9] .*: yes" "symplectic .*: yes" "time-reversible .*: yes" \
            "energy .*: bounded" "L_2 = 1/24\*x1^2+" "f_2\[1\] = 1/12\*x1+1/2\*x1\*x2+1/6\*x1\*x2^2+1/6\*x1^3"; do
  grep -q "$want" "$tmp/out" && ok || bad "verify output lacks '$want': $(cat "$tmp/out")"
done
python3 - "$tmp/verify.json" <<'PY' && ok || bad "verify JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["input"]["dim"] == 2 and j["order"]["passed"] and abs(j["order"]["fitted"] - 2) < 0.1, j["order"]
assert j["symplecticity"]["passed"] and j["reversibility"]["passed"], j
assert j["energy"]["verdict"] == "bounded" and j["energy"]["passed"], j["energy"]
assert j["verdict"]["passed"] and j["verdict"]["failed"] == [], j["verdict"]
assert j["modified_equation"][1] == ["0", "0"], j["modified_equation"]
PY
# Two runs, the same bytes (the typed expression keeps its own order of operations).
cp "$tmp/out" "$tmp/verify1.txt"
cp "$tmp/verify.json" "$tmp/verify1.json"
expect 0 "" -- verify --ld 'h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)' \
  --potential 'x^2/2+y^2/2+x^2*y-y^3/3' --q0 0,0.1 --p0 0.35,0 --json-out "$tmp/verify.json"
cmp -s "$tmp/out" "$tmp/verify1.txt" && cmp -s "$tmp/verify.json" "$tmp/verify1.json" && ok ||
  bad "verify: two runs differ"
# --report: a page with the figure, the data and the JSON; twice, the same bytes (the same
# command, run in two directories: the page quotes the command line).
for r in rep1 rep2; do
  mkdir -p "$tmp/$r.d"
  (cd "$tmp/$r.d" && "$V" verify --ld '(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2' --potential 'x^2/2+x^4/4' \
    --q0 0.5 --p0 0 --steps 4096 --report rep >/dev/null 2>"$tmp/err") && mv "$tmp/$r.d/rep" "$tmp/$r" &&
    ok || bad "verify --report: $(cat "$tmp/err")"
done
grep -q "vibook verify --ld" "$tmp/rep1/index.html" && ok || bad "verify --report: no command line"
for f in index.html vibook.css verify-report.svg verify-report.png convergence.csv energy.csv verify.json; do
  [ -s "$tmp/rep1/$f" ] && ok || bad "verify --report: $f missing"
done
diff -r "$tmp/rep1" "$tmp/rep2" >/dev/null && ok || bad "verify --report: two runs differ"
# In the book's style: the book's stylesheet beside the page, the verdicts in its claims table.
cmp -s "$tmp/rep1/vibook.css" "$SRC/book/vibook.css" && grep -q 'table class="vibook-claims"' "$tmp/rep1/index.html" &&
  ok || bad "verify --report: not in the book's stylesheet"
[ -z "$(find "$tmp" -maxdepth 1 -name '.*rep*')" ] && ok || bad "verify --report left a temporary"
# --report on every route (#49): the verdicts' table, the report as printed, the JSON the same
# bytes as --json-out's; a failing method's page says FAIL and names the check.
for route in "method --method gauss:2 --problem pendulum" \
             "tableau --tableau $SRC/examples/tableaus/gauss2.json --problem pendulum" \
             "composition --composition sv --coefficients yoshida4 --problem pendulum" \
             "wrong --composition sv --coefficients 1,1 --problem pendulum"; do
  name=${route%% *}
  args=(${route#* })
  "$V" verify "${args[@]}" --report "$tmp/page-$name" --json-out "$tmp/page-$name.json" \
    >"$tmp/out" 2>"$tmp/err"
  st=$?
  want=0; [ "$name" = wrong ] && want=5
  [ "$st" = "$want" ] && grep -q "^report: $tmp/page-$name/index.html" "$tmp/out" &&
    cmp -s "$tmp/page-$name/verify.json" "$tmp/page-$name.json" &&
    cmp -s "$tmp/page-$name/vibook.css" "$SRC/book/vibook.css" &&
    grep -q 'table class="vibook-claims"' "$tmp/page-$name/index.html" &&
    grep -q "verdict  *$([ $want = 0 ] && echo PASS || echo FAIL)" "$tmp/page-$name/index.html" &&
    ok || bad "verify --report on --$name: status $st, $(head -c 300 "$tmp/err")"
done
grep -q "Verdict: <strong>FAIL</strong> (consistency" "$tmp/page-wrong/index.html" && ok ||
  bad "verify --report: a failing composition's page does not say FAIL (consistency)"
# Wrong and right discrete Lagrangians, verdict by verdict: verify_verdicts.sh.

# --- figures and claims ---------------------------------------------------------------------
expect 0 "" -- figure vermeeren-fig1 --out "$tmp/f"
for f in vermeeren-fig1.svg vermeeren-fig1.png claims.json discrete.csv curves.csv; do
  [ -s "$tmp/f/vermeeren-fig1/$f" ] && ok || bad "figure file $f"
done
# A file of the user's in an output directory is left alone (#27: it was deleted); our own
# files are replaced. A --out that is a symbolic link, or OUT/ID that is a file, is refused
# before any work.
echo "my notes" >"$tmp/f/vermeeren-fig1/notes.txt"
expect 0 "" -- figure vermeeren-fig1 --out "$tmp/f"
grep -q "my notes" "$tmp/f/vermeeren-fig1/notes.txt" && [ -s "$tmp/f/vermeeren-fig1/discrete.csv" ] &&
  ok || bad "figure --out deleted a user's file"
ln -s "$tmp/f" "$tmp/flink"
expect 2 "--out" -- figure vermeeren-fig1 --out "$tmp/flink/"
mkdir -p "$tmp/g2" && touch "$tmp/g2/vermeeren-fig1"
expect 2 "--out" -- figure vermeeren-fig1 --out "$tmp/g2"
echo "my notes" >"$tmp/rep1/notes.txt"
(cd "$tmp" && "$V" verify --ld '(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2' --potential 'x^2/2+x^4/4' \
   --q0 0.5 --p0 0 --steps 4096 --report rep1 >/dev/null 2>&1) &&
  grep -q "my notes" "$tmp/rep1/notes.txt" && [ -s "$tmp/rep1/index.html" ] && ok ||
  bad "verify --report onto an earlier report deleted a user's file"
# list says what there is without running anything (statuses are `claims`' business).
expect 0 "" -- list
grep -q "S-F1" "$tmp/out" && grep -q "check-v-ex1" "$tmp/out" && ok || bad "list shows every check and claim"
# The whole ledger (`claims` without --check) is run by the book build, which ./build.sh test
# does first, through the same code; here one check at a time.
# One check only: its claims measured, the others pending.
expect 0 "" -- claims --json --check check-v-ex1
python3 - "$tmp/out" <<'PY' && ok || bad "claims --check runs only that check"
import json, sys
rows = {r["id"]: r["status"] for r in json.load(open(sys.argv[1]))["claims"]}
assert "V-EX3" in rows, rows
assert rows["V-EX1"] != "pending" and rows["V-P1"] != "pending" and rows["S-F1"] == "pending", rows
PY
expect 2 "--check" -- claims --check no-such-check
# gnuplot missing: a clear error, and the CSV still written.
PATH=/nonexistent "$V" figure vermeeren-fig1 --out "$tmp/g" 2>"$tmp/err"
[ $? = 1 ] && grep -q "gnuplot not found" "$tmp/err" && [ -s "$tmp/g/vermeeren-fig1/discrete.csv" ] && ok || bad "missing gnuplot"

echo "cli: $pass passed, $fail failed"
[ "$fail" = 0 ]
