#!/usr/bin/env bash
# The tape cache is trusted only if it is ours (chapter "Verify your own integrator", "How the
# typed method is stepped"): a shared object planted under the name vibook computes is never
# loaded, a cache writable by others is refused with one line, a copy of a cache is compiled
# again, and two runs compiling the same tape at once both succeed.
# Usage: tape_cache.sh VIBOOK
set -u
V=$1
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"  # tmp, pass/fail, ok, bad
ld=(--ld 'h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)' --potential='-cos(x)' --q0 1 --p0 0.5
  --h-list 0.2,0.1,0.05,0.025 --steps 2048)
native() { grep -q "^evaluation  *compiled tape, run as native code" "$1"; }

# 1. A cache of our own: compiled once, the object and its record 0600/0700, then reused.
mkdir -m 700 "$tmp/c1"
VIBOOK_CACHE_DIR="$tmp/c1" "$V" verify "${ld[@]}" >"$tmp/o1" 2>"$tmp/e1"
s=$?
so=$(ls "$tmp/c1/tapes/"*.so 2>/dev/null | head -1)
if [ $s = 0 ] && native "$tmp/o1" && [ ! -s "$tmp/e1" ] && [ -n "$so" ] && [ -f "${so%.so}.id" ] &&
  [ "$(stat -c %a "$tmp/c1/tapes")" = 700 ] && [ "$(stat -c %a "$so")" = 600 ]; then ok; else
  bad "own cache: status $s, $(ls -l "$tmp/c1/tapes" 2>&1) $(cat "$tmp/e1")"
fi
if [ -z "$so" ]; then
  echo "tape cache: 0 passed, 1 failed (no object was compiled; the rest needs one)"
  exit 1
fi
ino=$(stat -c %i "$so")
VIBOOK_CACHE_DIR="$tmp/c1" "$V" verify "${ld[@]}" >"$tmp/o1b" 2>&1
[ $? = 0 ] && [ "$(stat -c %i "$so")" = "$ino" ] && ok || bad "the cached object was not reused"

# 2. A planted object under the right name: its constructor would write a marker. It must be
# compiled again, not loaded.
cat >"$tmp/plant.c" <<C
#include <stdio.h>
__attribute__((constructor)) static void planted(void) {
  FILE* f = fopen("$tmp/marker", "w");
  if (f) fclose(f);
}
void vibook_newton_prefix(void) {}
void vibook_newton_prefix_carried(void) {}
void vibook_newton_first(void) {}
void vibook_newton_rest(void) {}
void vibook_momentum(void) {}
C
if cc -shared -fPIC -o "$tmp/plant.so" "$tmp/plant.c" 2>"$tmp/cc.err"; then
  cp "$tmp/plant.so" "$so.new" && chmod 600 "$so.new" && mv "$so.new" "$so"
  VIBOOK_CACHE_DIR="$tmp/c1" "$V" verify "${ld[@]}" >"$tmp/o2" 2>"$tmp/e2"
  s=$?
  [ $s = 0 ] && native "$tmp/o2" && [ ! -e "$tmp/marker" ] && ! cmp -s "$so" "$tmp/plant.so" && ok ||
    bad "planted object: status $s, marker $([ -e "$tmp/marker" ] && echo written || echo absent)"
else
  bad "cannot build the planted object: $(cat "$tmp/cc.err")"
fi

# 3. A copy of the cache (restored from elsewhere): the record no longer matches, so the
# object is compiled again (a new inode), and the run passes.
cp -a "$tmp/c1" "$tmp/c3"
so3="$tmp/c3/tapes/$(basename "$so")"
ino3=$(stat -c %i "$so3")
VIBOOK_CACHE_DIR="$tmp/c3" "$V" verify "${ld[@]}" >"$tmp/o3" 2>&1
[ $? = 0 ] && native "$tmp/o3" && [ "$(stat -c %i "$so3")" != "$ino3" ] && ok ||
  bad "a copied cache was loaded as it was"

# 4. A cache writable by others (mode 777, as in the probe), with a planted object under the
# right name: refused in one line, compiled privately, the planted constructor never runs.
mkdir -m 777 "$tmp/c4"
mkdir -m 755 "$tmp/c4/tapes"
cp "$tmp/plant.so" "$tmp/c4/tapes/$(basename "$so")"
cp "${so%.so}.id" "$tmp/c4/tapes/"
chmod 777 "$tmp/c4"
VIBOOK_CACHE_DIR="$tmp/c4" "$V" verify "${ld[@]}" >"$tmp/o4" 2>"$tmp/e4"
s=$?
if [ $s = 0 ] && native "$tmp/o4" && [ ! -e "$tmp/marker" ] && [ "$(wc -l <"$tmp/e4")" = 1 ] &&
  grep -q "^vibook: the tape cache is not used: $tmp/c4 is writable by group or others; compiling in a private temporary directory$" "$tmp/e4"; then
  ok
else
  bad "world-writable cache: status $s, $(cat "$tmp/e4")"
fi
# Nothing is created inside a refused directory (the check comes before any mkdir).
mkdir -m 777 "$tmp/c4e"
chmod 777 "$tmp/c4e"
VIBOOK_CACHE_DIR="$tmp/c4e" "$V" verify "${ld[@]}" >"$tmp/o4e" 2>"$tmp/e4e"
s=$?
if [ $s = 0 ] && [ -z "$(ls -A "$tmp/c4e")" ] && grep -q "writable by group or others" "$tmp/e4e"; then
  ok
else
  bad "a refused cache directory was written in: status $s, $(ls -A "$tmp/c4e")"
fi
# A cache directory that is a link to one of ours is refused too.
ln -s "$tmp/c1/tapes" "$tmp/c5"
mkdir -m 700 "$tmp/c5p"
ln -s "$tmp/c1/tapes" "$tmp/c5p/tapes"
VIBOOK_CACHE_DIR="$tmp/c5p" "$V" verify "${ld[@]}" >"$tmp/o5" 2>"$tmp/e5"
[ $? = 0 ] && grep -q "is not a directory (a link is refused)" "$tmp/e5" && ok ||
  bad "linked cache: $(cat "$tmp/e5")"

# 5. Two runs compiling the same tape at once, in a new cache: both succeed natively.
mkdir -m 700 "$tmp/c6"
VIBOOK_CACHE_DIR="$tmp/c6" "$V" verify "${ld[@]}" >"$tmp/o6a" 2>"$tmp/e6a" &
pa=$!
VIBOOK_CACHE_DIR="$tmp/c6" "$V" verify "${ld[@]}" >"$tmp/o6b" 2>"$tmp/e6b" &
pb=$!
wait $pa
sa=$?
wait $pb
sb=$?
[ "$sa$sb" = 00 ] && native "$tmp/o6a" && native "$tmp/o6b" && [ ! -s "$tmp/e6a" ] && [ ! -s "$tmp/e6b" ] &&
  ok || bad "concurrent compiles: $sa $sb $(cat "$tmp/e6a" "$tmp/e6b")"

echo "tape cache: $pass passed, $fail failed"
[ "$fail" = 0 ]
