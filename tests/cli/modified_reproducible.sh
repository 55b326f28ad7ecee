#!/usr/bin/env bash
# `vibook modified` gives one byte string per derivation, whatever the run (#27): every method x
# potential x what, the format cycling through text/latex/python, plus --alpha, --dim 2 and 3 and
# a higher order; each run four times (VIBOOK_REPRO_RUNS or the second argument for more), under
# a different allocation pattern each time (MALLOC_PERTURB_; an environment of another size
# moves the stack), with address randomisation on, and once off (run 3, where setarch exists). Standard output and standard error and the exit status are compared.
# Usage: modified_reproducible.sh path/to/vibook [RUNS]
set -u
V=$(realpath "$1")
runs=${2:-${VIBOOK_REPRO_RUNS:-4}}
pass=0 fail=0
one() {  # one derivation, run $runs times
  local first="" i s
  for i in $(seq 1 "$runs"); do
    local pad; pad=$(head -c $((i * 700)) /dev/zero | tr '\0' x)
    if [ $((i % 3)) = 0 ] && command -v setarch >/dev/null && setarch "$(uname -m)" -R true 2>/dev/null; then
      s=$(env MALLOC_PERTURB_=$((i * 29 % 255 + 1)) VIBOOK_PAD="$pad" setarch "$(uname -m)" -R \
            "$V" modified "$@" 2>&1; echo "status $?")
    else
      s=$(env MALLOC_PERTURB_=$((i * 29 % 255 + 1)) VIBOOK_PAD="$pad" "$V" modified "$@" 2>&1
          echo "status $?")
    fi
    s=$(printf '%s' "$s" | md5sum)
    if [ -z "$first" ]; then first=$s
    elif [ "$s" != "$first" ]; then
      fail=$((fail + 1)); echo "FAIL: vibook modified $*: run $i differs from run 1"; return
    fi
  done
  pass=$((pass + 1))
}
formats=(text latex python)
k=0
for m in sv se se-adjoint midpoint vi1 vi1-adjoint vi2; do
  for pot in generic kepler pendulum harmonic; do
    for what in equation lagrangian hamiltonian meshed disc; do
      one --method "$m" --potential "$pot" --order 3 --what "$what" --format "${formats[$((k % 3))]}"
      k=$((k + 1))
    done
  done
done
for m in vi1 vi1-adjoint vi2; do
  one --method "$m" --potential kepler --order 3 --alpha 1/3 --what lagrangian
  one --method "$m" --potential pendulum --order 2 --alpha 3/10 --format latex
done
one --method sv --dim 2 --order 4 --what lagrangian
one --method midpoint --dim 2 --order 3 --what hamiltonian --format python
one --method sv --dim 3 --order 3
one --method sv --potential kepler --order 4 --what hamiltonian
echo "modified reproducible: $pass derivations x $runs runs identical, $fail differ"
[ "$fail" = 0 ]
