#!/usr/bin/env bash
# demscale against LIGGGHTS on the same slump scene: both engines lift the cone from the same
# settled fill (settled by demscale, exported with `demscale export liggghts`, whose deck fits the
# box to the scene) and let the pile spread for the scene's full spread time. The engines
# alternate (ROUNDS rounds, default 2; the order flips each round), on 1 and on 2 threads/ranks.
# Before each run the script measures how busy the cores are (2 s of /proc/stat, nothing of ours
# running) and logs it; a pair whose runs started with more than BUSY_LIMIT cores (default 0.3)
# busy with other work gets no ratio. Prints every run, every pair's ratio (LIGGGHTS time over
# demscale time) and the median per thread count, and both final piles. Each run's line also logs
# the cross-core cost of a cache line just before it (link_ns, `demscale bench --core-link`).
# A wet scene runs wet on both (LIGGGHTS' cohesion easo/capillary/viscous at the same surface
# tension, liquid and viscosity; the deck's header lists what differs). SPREAD_S shortens the
# spread to that many seconds for both engines (the wet reference scene allows 8 s for its rest
# criterion; timed runs have none).
# Usage: [ROUNDS=2] [BUSY_LIMIT=0.3] [SPREAD_S=0.4] bench/vs_liggghts.sh [SCENE]
# (default data/scenes/kantro_dry.toml, 4 800 spheres: several minutes per round;
# data/scenes/kantro_dry_large.toml, 16 600 spheres: about 16 minutes per round;
# SPREAD_S=0.4 bench/vs_liggghts.sh data/scenes/kantro_wet.toml: about 6 minutes per round).
# Last lines: ratio_KIND_2threads=X.XX, ratio_KIND_1thread=X.XX (KIND: dry or wet).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-data/scenes/kantro_dry.toml}

missing=()
command -v liggghts >/dev/null || missing+=(liggghts)
command -v mpirun >/dev/null || missing+=(openmpi-bin)
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then as_root=(); else as_root=(sudo); fi
  "${as_root[@]}" apt-get update -qq
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
tools/install-deps.sh
[ -x build/demscale ] || { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null && cmake --build build -j2 >/dev/null; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -n "${SPREAD_S:-}" ]; then
  grep -q '^spread_time_s *=' "$scene" || { echo "SPREAD_S: $scene has no spread_time_s line to change" >&2; exit 2; }
  sed "s/^spread_time_s *=.*/spread_time_s = $SPREAD_S/" "$scene" >"$work/scene.toml"
  scene="$work/scene.toml"
fi
echo "scene: $scene; work folder: $work" >&2
build/demscale export liggghts --scene "$scene" --out "$work/lig" >/dev/null 2>&1

. bench/measure.sh  # busy, median, json
rounds=${ROUNDS:-2} busy_limit=${BUSY_LIMIT:-0.3}
run_demscale() {  # threads round
  OMP_NUM_THREADS=$1 build/demscale slump --scene "$scene" --start "$work/lig/settled.csv" --fixed-time \
    --format json --out "$work/ds$1_$2" --no-png >"$work/ds$1_$2.json" 2>/dev/null
  json "$work/ds$1_$2.json" wall_s
}
run_liggghts() {  # ranks round; loop time only (setup excluded)
  (cd "$work/lig" && mpirun --allow-run-as-root --oversubscribe -np "$1" liggghts -in in.slump >"log$1_$2" 2>&1)
  cp "$work/lig/final.dump" "$work/lig/final$1.dump"
  awk '/^Loop time of/ {s += $4} END {printf "%.3f", s}' "$work/lig/log$1_$2"
}
printf '%-6s %-8s %-9s %10s %8s %12s\n' round threads engine busy_cores link_ns wall_s >&2
declare -A ratios
for t in 1 2; do
  for r in $(seq 1 "$rounds"); do
    order=(demscale liggghts); [ $((r % 2)) -eq 0 ] && order=(liggghts demscale)
    loaded=0
    for e in "${order[@]}"; do
      b=$(busy); awk -v b="$b" -v l="$busy_limit" 'BEGIN {exit !(b > l)}' && loaded=1
      n=$(link)
      if [ "$e" = demscale ]; then d=$(run_demscale "$t" "$r"); w=$d; else l=$(run_liggghts "$t" "$r"); w=$l; fi
      printf '%-6s %-8s %-9s %10s %8s %12s\n' "$r" "$t" "$e" "$b" "$n" "$w" >&2
    done
    if [ "$loaded" -eq 1 ]; then
      echo "round $r, $t thread(s): other work on the cores; no ratio" >&2
    else
      ratios[$t]+="$(awk -v l="$l" -v d="$d" 'BEGIN {printf "%.3f", l / d}') "
      echo "round $r, $t thread(s): liggghts/demscale = $(awk -v l="$l" -v d="$d" 'BEGIN {printf "%.2f", l / d}')" >&2
    fi
  done
done
particles=$(json "$work/ds1_1.json" particles)
steps=$(( $(json "$work/ds1_1.json" steps) ))
kind=wet; grep -q '"bridge_law": "none"' "$work/ds1_1.json" && kind=dry
echo "particles: $particles, steps: $steps (lift and spread), $kind, liggghts $(dpkg-query -W -f='${Version}' liggghts)"
piles='"(fill_height_mm|final_height_mm|slump_over_fill_height|spread_mm|final_height_top_mm|spread_d95_mm|repose_angle_deg)"'
echo "final pile, demscale (1 thread):"
grep -E "$piles" "$work/ds1_1.json"
echo "final pile, liggghts (1 rank), measured by demscale from the same fill:"
build/demscale pile --dump "$work/lig/final1.dump" --fill "$work/lig/settled.csv" --scene "$scene" | grep -E "$piles"
echo "pairs without other work: 1 thread: ${ratios[1]:-none}; 2 threads: ${ratios[2]:-none}"
echo "ratio_${kind}_2threads=$(median "${ratios[2]:-}")"
echo "ratio_${kind}_1thread=$(median "${ratios[1]:-}")"
