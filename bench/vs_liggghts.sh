#!/usr/bin/env bash
# demscale against LIGGGHTS on the same slump scene: both engines lift the cone from the same
# settled fill (settled by demscale, exported with `demscale export liggghts`) and let the pile
# spread for the scene's full spread time. Prints rates (particle-steps/s), their ratio, and both
# final piles. Usage: bench/vs_liggghts.sh [SCENE] (default data/scenes/kantro_dry.toml; takes
# several minutes). Last line: ratio_dry_1thread=X.XX
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
echo "scene: $scene; work folder: $work" >&2
build/demscale export liggghts --scene "$scene" --out "$work/lig" >/dev/null 2>&1

json() { sed -n "s/^ *\"$2\": \\([^,]*\\),\\?$/\\1/p" "$1" | head -1; }
# demscale: lift and spread from the settled fill, whole spread time.
for t in 1 2; do
  OMP_NUM_THREADS=$t build/demscale slump --scene "$scene" --start "$work/lig/settled.csv" --fixed-time \
    --format json --out "$work/ds$t" --no-png >"$work/ds$t.json" 2>/dev/null
done
# LIGGGHTS: the exported deck, 1 and 2 MPI ranks; loop times only (setup excluded).
particles=$(json "$work/ds1.json" particles)
steps=$(( $(json "$work/ds1.json" steps) ))
for n in 1 2; do
  (cd "$work/lig" && mpirun --allow-run-as-root --oversubscribe -np $n liggghts -in in.slump >"log$n" 2>&1)
  cp "$work/lig/final.dump" "$work/lig/final$n.dump"
done
loop() { awk '/^Loop time of/ {s += $4} END {printf "%.3f", s}' "$work/lig/log$1"; }

rate() { awk -v p="$particles" -v s="$steps" -v w="$1" 'BEGIN {printf "%.3g", p * s / w}'; }
ds1=$(json "$work/ds1.json" wall_s); ds2=$(json "$work/ds2.json" wall_s)
lg1=$(loop 1); lg2=$(loop 2)
printf '%-28s %12s %12s %22s\n' engine threads/ranks wall_s particle_steps_per_s
printf '%-28s %12s %12.2f %22s\n' demscale 1 "$ds1" "$(rate "$ds1")" demscale 2 "$ds2" "$(rate "$ds2")"
printf '%-28s %12s %12.2f %22s\n' "liggghts $(dpkg-query -W -f='${Version}' liggghts)" 1 "$lg1" "$(rate "$lg1")" \
  liggghts 2 "$lg2" "$(rate "$lg2")"
echo "particles: $particles, steps: $steps (lift and spread)"
echo "final pile, demscale (1 thread):"
grep -E '"(final_height_mm|spread_d95_mm|spread_max_mm|repose_angle_deg)"' "$work/ds1.json"
echo "final pile, liggghts (1 rank), measured by demscale:"
build/demscale pile --dump "$work/lig/final1.dump" --scene "$scene" | grep -E 'height|spread|repose'
awk -v l="$lg2" -v d="$ds2" 'BEGIN {printf "ratio_dry_2threads=%.2f\n", l / d}'
awk -v l="$lg1" -v d="$ds1" 'BEGIN {printf "ratio_dry_1thread=%.2f\n", l / d}'
