#!/usr/bin/env bash
# demscale's threads, quiet and contended: the scene's lift and spread from one settled state
# (settled once, by `export liggghts`), the whole spread time, on 1 and on 2 threads (explicit
# --threads), alternating over ROUNDS rounds (the order flips each round). Quiet: before each run
# the script logs the cores busy with other work (2 s of /proc/stat) and gives no ratio for a pair
# above BUSY_LIMIT (default 0.3). Contended: the same pairs with a busy loop holding one core
# (started 5 s before; the load it adds is logged). Each run's line also logs the cross-core cost
# of a cache line just before it (`demscale bench --core-link`, crossing ns): on a virtual machine
# the second thread's gain follows it (docs/performance.md). Prints every run, the quiet 2-thread speed-up
# (1-thread time over 2-thread time) and the contended 2-thread time over the contended 1-thread
# time, per round and their medians. SPREAD=seconds shortens the spread (default: the scene's).
# Usage: [ROUNDS=2] [SPREAD=s] [BUSY_LIMIT=0.3] bench/threads.sh [SCENE] (default kantro_dry.toml)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-data/scenes/kantro_dry.toml}
. bench/measure.sh  # busy, median, json
[ -x build/demscale ] || { tools/install-deps.sh && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null && cmake --build build -j2 >/dev/null; }

work=$(mktemp -d)
spinner=
trap '[ -n "$spinner" ] && kill "$spinner" 2>/dev/null; rm -rf "$work"' EXIT
if [ -n "${SPREAD:-}" ]; then  # the scene's line, or a new one in its [run] table, or a new [run] table
  if grep -q '^spread_time_s *=' "$scene"; then sed "s/^spread_time_s *=.*/spread_time_s = $SPREAD/" "$scene"
  elif grep -q '^\[run\]' "$scene"; then sed "s/^\[run\].*/&\nspread_time_s = $SPREAD/" "$scene"
  else cat "$scene"; printf '\n[run]\nspread_time_s = %s\n' "$SPREAD"; fi >"$work/scene.toml"
  scene="$work/scene.toml"
fi
echo "scene: $scene; settling once ..." >&2
build/demscale export liggghts --scene "$scene" --out "$work/settle" >/dev/null 2>&1
rounds=${ROUNDS:-2} busy_limit=${BUSY_LIMIT:-0.3}
run() {  # threads label
  build/demscale slump --scene "$scene" --start "$work/settle/settled.csv" --fixed-time --threads "$1" \
    --format json --out "$work/$2" --no-png >"$work/$2.json" 2>/dev/null
  json "$work/$2.json" wall_s
}
printf '%-10s %-6s %-8s %10s %8s %10s\n' machine round threads busy_cores link_ns wall_s >&2
quiet_ratios= contended_ratios=
for machine in quiet contended; do
  if [ "$machine" = contended ]; then
    (while :; do :; done) &
    spinner=$!
    sleep 5
  fi
  for r in $(seq 1 "$rounds"); do
    order=(1 2); [ $((r % 2)) -eq 0 ] && order=(2 1)
    loaded=0
    declare -A wall=()
    for t in "${order[@]}"; do
      b=$(busy)
      [ "$machine" = quiet ] && awk -v b="$b" -v l="$busy_limit" 'BEGIN {exit !(b > l)}' && loaded=1
      l=$(link)
      wall[$t]=$(run "$t" "${machine}_${t}_$r")
      printf '%-10s %-6s %-8s %10s %8s %10s\n' "$machine" "$r" "$t" "$b" "$l" "${wall[$t]}" >&2
    done
    if [ "$machine" = quiet ]; then
      if [ "$loaded" -eq 1 ]; then echo "round $r: other work on the cores; no ratio" >&2; continue; fi
      quiet_ratios+="$(awk -v a="${wall[1]}" -v b="${wall[2]}" 'BEGIN {printf "%.3f", a / b}') "
    else
      contended_ratios+="$(awk -v a="${wall[1]}" -v b="${wall[2]}" 'BEGIN {printf "%.3f", b / a}') "
    fi
  done
  [ -n "$spinner" ] && kill "$spinner" && spinner=
done
for t in 1 2; do
  cmp -s "$work/quiet_${t}_1/slump_particles.csv" "$work/quiet_1_1/slump_particles.csv" ||
    echo "warning: the $t-thread final state differs from the 1-thread one" >&2
done
echo "particles: $(json "$work/quiet_1_1.json" particles), steps: $(json "$work/quiet_1_1.json" steps)"
echo "quiet, 1-thread time over 2-thread time, per round: ${quiet_ratios:-none}"
echo "contended, 2-thread time over 1-thread time, per round: ${contended_ratios:-none}"
echo "speedup_2threads_quiet=$(median "$quiet_ratios")"
echo "contended_2threads_over_1thread=$(median "$contended_ratios")"
