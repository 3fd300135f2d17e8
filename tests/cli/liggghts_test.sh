#!/usr/bin/env bash
# The whole trip of a study run by LIGGGHTS (docs/dem-engine.md, "LIGGGHTS"): demscale settles each
# fill, exports the deck, LIGGGHTS lifts and spreads it under `mpirun -np 2`, demscale measures the
# dump and judges the ensembles. Installs LIGGGHTS and Open MPI from Debian's archive when they are
# missing (as root); exit 77 (skipped) where they cannot be had. Usage: liggghts_test.sh DEMSCALE SOURCE_DIR
set -u
demscale=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL [liggghts]: $*" >&2; exit 1; }

# shellcheck source=need_liggghts.sh
. "$(dirname "$0")/need_liggghts.sh"
need_liggghts || { echo "skipped: $why_no_liggghts"; exit 77; }

# Two seeds per ensemble, fine and S_f 1.4 at k = 1, raw comparison: four LIGGGHTS runs of 2 ranks.
args=(check-exponent --exponent 1 --scene "$src/data/scenes/small_wet.toml" --sf 1.4 --seeds 2 --baseline none
      --engine liggghts --ranks 2 --cache "$work/cache" --out "$work/c" --no-png --jobs 1)
"$demscale" "${args[@]}" >"$work/out" 2>&1; rc=$?
cat "$work/out"
case $rc in 0 | 1 | 4) ;; *) fail "check-exponent --engine liggghts exited $rc" ;; esac
grep -Eq 'verdict: (PASS|FAIL|INCONCLUSIVE)' "$work/out" || fail "no verdict"
grep -q '4 distinct runs' "$work/out" || fail "not the four runs (2 seeds, fine and S_f 1.4)"
runs="$work/c/check_k1_runs.csv"
[ "$(grep -c '^1\(\.4\)\?,' "$runs")" -eq 4 ] || fail "the runs file does not hold the 4 runs"
folders=("$work"/cache/liggghts/*/)
[ "${#folders[@]}" -eq 4 ] || fail "${#folders[@]} LIGGGHTS folders in the cache, expected 4"
# Each run's deck asked for 2 ranks, and LIGGGHTS ran it on 2 processors.
for d in "${folders[@]}"; do
  [ -s "$d/final.dump" ] && [ -s "$d/settled.csv" ] || fail "$d lacks its dump or fill"
  grep -Eq '^(Loop time|  [0-9]+ by [0-9]+ by [0-9]+ MPI processor grid)' "$d/log.liggghts" || fail "no LIGGGHTS log in $d"
  grep -q 'on 2 procs' "$d/log.liggghts" || fail "$d: LIGGGHTS did not run on 2 ranks"
done
# The decks stop at rest by demscale's criterion: the small wet piles rest well within 0.2 s.
rested=$(grep -l '^demscale: at rest at step' "$work"/cache/liggghts/*/log.liggghts | wc -l)
[ "$rested" -ge 3 ] || fail "only $rested of 4 LIGGGHTS runs came to rest"
[ "$(grep -v '^#' "$runs" | awk -F, 'NR > 1 && $6 == "yes"' | wc -l)" -eq "$rested" ] || fail "came_to_rest in the runs file differs from the logs"
# The dump measured by `pile` gives each run's own row, to the bit: the same reader and measures.
for d in "${folders[@]}"; do
  sf=1; "$demscale" pile --scene "$src/data/scenes/small_wet.toml" --dump "$d/final.dump" --fill "$d/settled.csv" --sf 1 >"$work/pile.json" 2>/dev/null ||
    { sf=1.4; "$demscale" pile --scene "$src/data/scenes/small_wet.toml" --dump "$d/final.dump" --fill "$d/settled.csv" --sf 1.4 >"$work/pile.json" 2>"$work/pile.err" ||
      { cat "$work/pile.err" >&2; fail "pile refused $d"; }; }
  s=$(grep '"slump_over_fill_height"' "$work/pile.json" | sed 's/.*: *//; s/,$//')
  w=$(grep '"spread_over_d0"' "$work/pile.json" | sed 's/.*: *//; s/,$//')
  grep -v '^#' "$runs" | awk -F, -v sf="$sf" -v s="$s" -v w="$w" '
    NR > 1 && $1 + 0 == sf + 0 && sprintf("%.17g", $4) == sprintf("%.17g", s) && sprintf("%.17g", $5) == sprintf("%.17g", w) { found = 1 }
    END { exit !found }' || { cat "$runs" >&2; fail "$d: pile measured slump $s, spread $w, which no S_f $sf run of the study has"; }
done
# A second call reuses the cached LIGGGHTS runs; a scene LIGGGHTS cannot express is refused first.
"$demscale" "${args[@]}" >"$work/out" 2>&1
grep -q '0 to run' "$work/out" || { cat "$work/out" >&2; fail "the cached LIGGGHTS runs were not reused"; }
{ cat "$src/data/scenes/small_wet.toml"; printf '[liquid]\nwet_walls = true\n'; } >"$work/walls.toml"
"$demscale" check-exponent --exponent 1 --scene "$work/walls.toml" --engine liggghts --cache "$work/c2" --out "$work/o2" >"$work/out" 2>&1; rc=$?
[ "$rc" -eq 2 ] && grep -q 'liquid.wet_walls = true: accepted false with --engine liggghts' "$work/out" || { cat "$work/out" >&2; fail "wet walls not refused"; }
[ ! -e "$work/c2" ] && [ ! -e "$work/o2" ] || fail "a refused study wrote output"
echo "ok [liggghts]: 4 runs by LIGGGHTS on 2 ranks, judged; their dumps measured by pile give their rows to the bit"
