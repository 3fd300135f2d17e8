#!/usr/bin/env bash
# The bad-input catalogue: one case per class of bad input, run against every command that reads
# that kind of input. Each must exit 2 with one line naming the file (and line), the key, the value
# and what is accepted, and must leave no output behind (no --out folder, no cache).
# Usage: bad_input_test.sh CLASS DEMSCALE SOURCE_DIR
set -u
class=$1 demscale=$2 src=$3
work=$(mktemp -d)
trap 'chmod -R u+rwx "$work" 2>/dev/null; rm -rf "$work"' EXIT
checked=0

fail() { echo "FAIL [$class]: $*" >&2; exit 1; }
# refused PATTERN command...: exit 2, PATTERN (grep -E) in the output, exactly one error line.
refused() {
  local pattern=$1; shift
  "$@" >"$work/log" 2>&1 </dev/null; local rc=$?
  [ "$rc" -eq 2 ] || { cat "$work/log" >&2; fail "exit $rc, expected 2: $*"; }
  grep -Eq -- "$pattern" "$work/log" || { cat "$work/log" >&2; fail "message lacks /$pattern/: $*"; }
  [ "$(grep -c 'error' "$work/log")" -eq 1 ] || { cat "$work/log" >&2; fail "not one error line: $*"; }
  checked=$((checked + 1))
}
# refuse PATTERN -- command...: refused, with --out, and nothing written (no folder, no cache).
refuse() {
  local pattern=$1; shift 2
  refused "$pattern" "$@" --out "$work/out"
  [ ! -e "$work/out" ] || fail "output written despite the error: $*"
  [ ! -e "$work/cache" ] || fail "cache written despite the error: $*"
}
# refuse_keeping PATTERN -- command...: refused, into an --out folder that already holds earlier
# results: they must be left exactly as they were, and nothing added.
refuse_keeping() {
  local pattern=$1; shift 2
  rm -rf "$work/kept" && mkdir "$work/kept"
  for f in slump_profile.csv slump_history.csv check_k1.csv fig3.csv report.html; do echo "earlier $f" >"$work/kept/$f"; done
  (cd "$work/kept" && ls -l --time-style=+%s.%N && md5sum ./*) >"$work/kept.before"
  refused "$pattern" "$@" --out "$work/kept"
  (cd "$work/kept" && ls -l --time-style=+%s.%N && md5sum ./*) >"$work/kept.after"
  diff "$work/kept.before" "$work/kept.after" >&2 || fail "earlier results changed by a refused run: $*"
}
# Commands without --out (they print to stdout).
refuse_no_out() {
  local pattern=$1; shift 2
  refused "$pattern" "$@"
}

# Every command that reads a scene file, and every command that reads a Table 1 config.
printf 'ITEM: ATOMS id x y z radius\n1 0 0 0.001 0.001\n' >"$work/dump.txt"
scene_commands() {  # pattern file [no-pile: pile only measures, it never runs the scene]
  local p=$1 f=$2 pile=${3:-}
  refuse "$p" -- "$demscale" slump --scene "$f"
  refuse "$p" -- "$demscale" check-exponent --exponent 1 --scene "$f" --cache "$work/cache"
  refuse "$p" -- "$demscale" sweep --scene "$f" --cache "$work/cache"
  refuse "$p" -- "$demscale" estimate-exponent --scene "$f" --cache "$work/cache"
  refuse "$p" -- "$demscale" report --scene "$f" --cache "$work/cache"
  refuse "$p" -- "$demscale" export liggghts --scene "$f"
  [ "$pile" = no-pile ] || refuse_no_out "$p" -- "$demscale" pile --scene "$f" --dump "$work/dump.txt"
  refuse_no_out "$p" -- "$demscale" bench --dem --scene "$f"
}
config_commands() {  # pattern file
  local p=$1 f=$2
  refuse_no_out "$p" -- "$demscale" table --config "$f"
  refuse "$p" -- "$demscale" curves --figure 3 --config "$f"
  refuse_no_out "$p" -- "$demscale" regress --config "$f"
  refuse "$p" -- "$demscale" report --config "$f" --cache "$work/cache"
}
scene() { printf '%s\n' "$@" >"$work/scene.toml"; }
config() { printf '%s\n' "$@" >"$work/config.toml"; }
small="$src/data/scenes/small_wet.toml"

case $class in
  missing_file)
    scene_commands 'scene.toml: accepted a readable TOML file \(not found\)' "$work/none/scene.toml"
    config_commands 'config.toml: accepted a readable TOML file \(not found\)' "$work/none/config.toml"
    refuse_no_out '--dump = .*nope.txt: accepted a readable pile file \(LIGGGHTS/LAMMPS text dump or CSV\) \(not found\)' -- "$demscale" pile --dump "$work/nope.txt"
    refuse 'nope.csv: accepted a readable CSV file \(not found\)' -- "$demscale" slump --scene "$small" --start "$work/nope.csv"
    refuse '--resume = .*nope.ckpt: accepted a checkpoint .*\(not found\)' -- "$demscale" slump --scene "$small" --resume "$work/nope.ckpt"
    refuse_no_out 'nope.csv: accepted a readable CSV file \(not found\)' -- "$demscale" bridge --model table --table "$work/nope.csv"
    refuse 'nope.csv: accepted a readable CSV file \(not found\)' -- "$demscale" bridge-error --quick --table "$work/nope.csv"
    refuse_no_out 'reference = .*fig3.csv: accepted an existing reference CSV' -- "$demscale" regress --reference-dir "$work/none" ;;
  unreadable_file)
    # A directory where a file is expected; and, when not running as root (root reads anything),
    # a file without read permission.
    mkdir "$work/dir.toml"
    scene_commands 'dir.toml: accepted a readable TOML file \(this is a directory\)' "$work/dir.toml"
    config_commands 'dir.toml: accepted a readable TOML file \(this is a directory\)' "$work/dir.toml"
    refuse_no_out '--dump = .*dir.toml: accepted a readable pile file \(LIGGGHTS/LAMMPS text dump or CSV\) \(this is a directory\)' -- "$demscale" pile --dump "$work/dir.toml"
    refuse 'dir.toml: accepted a readable CSV file \(this is a directory\)' -- "$demscale" slump --scene "$small" --start "$work/dir.toml"
    refuse '--resume = .*dir.toml: .*\(this is a directory\)' -- "$demscale" slump --scene "$small" --resume "$work/dir.toml"
    refuse_no_out 'dir.toml: accepted a readable CSV file \(this is a directory\)' -- "$demscale" bridge --model table --table "$work/dir.toml"
    if [ "$(id -u)" -ne 0 ]; then
      cp "$small" "$work/locked.toml" && chmod 000 "$work/locked.toml"
      scene_commands 'locked.toml: accepted a readable TOML file \(unreadable' "$work/locked.toml"
    else
      echo "note: running as root, the permission-denied half is skipped (root can read any file)"
    fi ;;
  malformed_toml)
    scene '[particles' 'radius_mm = 1'
    scene_commands 'scene.toml:1: \(TOML syntax\) = .*: accepted well-formed TOML' "$work/scene.toml"
    config '[particle]' 'radii_mm = [1.0,' ''
    config_commands 'config.toml:[0-9]+: \(TOML syntax\) = .*: accepted well-formed TOML' "$work/config.toml" ;;
  unknown_key)
    scene '[particles]' 'radius = 1'
    scene_commands 'scene.toml:2: particles.radius = \(unknown key\): .*did you mean particles.radius_mm' "$work/scene.toml"
    scene '[particle]' 'radius_mm = 1'
    scene_commands 'scene.toml:1: particle = \(section\): .*did you mean \[particles\]' "$work/scene.toml"
    config '[particle]' 'radii_mm = [1.0]' 'masses_g = [0.01]' 'radius_mm = 2'
    config_commands 'config.toml:4: particle.radius_mm = \(unknown key\): .*did you mean particle.radii_mm' "$work/config.toml" ;;
  wrong_type)
    scene '[particles]' 'radius_mm = "big"'
    scene_commands 'scene.toml:2: particles.radius_mm = \(not a number\): accepted a number' "$work/scene.toml"
    scene '[liquid]' 'wet = 1'
    scene_commands 'scene.toml:2: liquid.wet = .*: accepted (true or false|a boolean)' "$work/scene.toml"
    config '[particle]' 'radii_mm = "one"' 'masses_g = [0.01]'
    config_commands 'config.toml:2: particle.radii_mm = .*: accepted' "$work/config.toml" ;;
  out_of_range)
    scene '[particles]' 'radius_mm = -1'
    scene_commands 'scene.toml:2: particles.radius_mm = -1: accepted a finite number > 0' "$work/scene.toml"
    scene '[particles]' 'density_kg_per_m3 = 0'
    scene_commands 'scene.toml:2: particles.density_kg_per_m3 = 0: accepted a finite number > 0' "$work/scene.toml"
    scene '[liquid]' 'moisture_content = 1'
    scene_commands 'scene.toml:2: liquid.moisture_content = 1: accepted \(0, 1\)' "$work/scene.toml"
    scene '[liquid]' 'contact_angle_deg = 90'
    scene_commands 'scene.toml:2: liquid.contact_angle_deg = 90: accepted \[0, 90\) deg' "$work/scene.toml"
    scene '[liquid]' 'bridge_variant = "exact"'
    scene_commands 'scene.toml:2: liquid.bridge_variant = "exact": accepted one of mikami1998, yun-park-2017, table, willett' "$work/scene.toml" no-pile
    scene '[liquid]' 'wall_bridge = "fit"'
    scene_commands 'scene.toml:2: liquid.wall_bridge = "fit": accepted one of mikami1998, table' "$work/scene.toml" no-pile
    # The exact bridges exist only where the solver finds a concave one (the default wall law too).
    scene '[liquid]' 'bridge_variant = "table"' 'contact_angle_deg = 85'
    scene_commands 'scene.toml: liquid.bridge_variant = "table" at V\^ = 0.05556, theta = 85 deg: accepted .*concave bridge, or bridge_variant = "mikami1998"' "$work/scene.toml" no-pile
    scene '[liquid]' 'wet_walls = true' 'contact_angle_deg = 85'
    scene_commands 'scene.toml: liquid.wall_bridge = "table" at .*: accepted .*concave bridge, or wall_bridge = "mikami1998"' "$work/scene.toml" no-pile
    scene '[particles]' 'distribution = "lognormal"' 'median_radius_mm = 1' 'geometric_sd = 0.8'
    scene_commands 'scene.toml:4: particles.geometric_sd = 0.8: accepted \[1, 3\] \(1: one radius\)' "$work/scene.toml"
    scene '[particles]' 'distribution = "sieve"' 'class_radii_mm = [1.0, 0.8]' 'mass_fractions = [0.5, 0.5]'
    scene_commands 'scene.toml:3: particles.class_radii_mm = 0.8: accepted radii > 0, mm, strictly ascending' "$work/scene.toml"
    scene '[contact]' 'rolling_model = "sideways"'
    scene_commands 'scene.toml:2: contact.rolling_model = sideways: accepted "epsd", "epsd2" or "constant_torque"' "$work/scene.toml"
    scene '[contact]' 'rolling_damping = 1.5'
    scene_commands 'scene.toml:2: contact.rolling_damping = 1.5: accepted \[0, 1\]' "$work/scene.toml"
    scene '[contact]' 'rolling_model = "epsd2"' 'rolling_damping = 0.3'
    scene_commands 'scene.toml:3: contact.rolling_damping = 0.3: accepted 0 unless rolling_model = "epsd"' "$work/scene.toml"
    scene '[contact]' 'cohesion_energy_density_j_per_m3 = -5'
    scene_commands 'scene.toml:2: contact.cohesion_energy_density_j_per_m3 = -5: accepted a finite number >= 0 J/m\^3' "$work/scene.toml"
    scene '[contact]' 'cohesion_energy_density_j_per_m3 = 2e4'
    scene_commands 'scene.toml:2: contact.cohesion_energy_density_j_per_m3 = 20000: accepted 0 in a wet scene' "$work/scene.toml"
    config '[particle]' 'radii_mm = [1.0, -2.0]' 'masses_g = [0.01, 0.07]'
    config_commands 'config.toml:2: particle.radii_mm\[1\] = -2: accepted a finite number > 0' "$work/config.toml"
    refuse '--sf = 0: accepted a finite number > 0' -- "$demscale" slump --scene "$small" --sf 0
    refuse '--sf = "-1": accepted comma-separated numbers in \(0, 100\)' -- "$demscale" check-exponent --exponent 1 --sf -1
    refuse '--sf = "0": accepted comma-separated numbers in \(0, 100\)' -- "$demscale" sweep --sf 0
    refuse '--sf = "0": accepted comma-separated numbers in \(0, 100\)' -- "$demscale" report --sf 0
    refuse '--exponent = 25: accepted \(-20, 20\)' -- "$demscale" slump --scene "$small" --exponent 25
    refuse_no_out '--vhat = -1: accepted a finite number > 0' -- "$demscale" bridge --vhat -1
    refuse_no_out 'contact_angle_deg = 95: accepted \[0, 90\) degrees' -- "$demscale" bridge --theta 95
    refuse_no_out '--length = 0: accepted a finite number > 0' -- "$demscale" scaling --length 0
    refuse '--tol-slump = -1: accepted a finite number > 0' -- "$demscale" check-exponent --exponent 1 --tol-slump -1
    refuse '--seeds = -1: accepted 1 to 64' -- "$demscale" sweep --seeds -1
    refuse_no_out '--atol: value -1; accepted a finite number >= 0' -- "$demscale" regress --atol -1
    # The engine: a known one, ranks only for LIGGGHTS, and a scene LIGGGHTS can express, all
    # refused before any run (none of this needs LIGGGHTS installed).
    refuse '--engine = lammps: accepted demscale or liggghts' -- "$demscale" check-exponent --exponent 1 --scene "$small" --engine lammps --cache "$work/cache"
    refuse '--ranks = 2: accepted only with --engine liggghts' -- "$demscale" sweep --scene "$small" --ranks 2 --cache "$work/cache"
    refuse '--ranks = 65: accepted 1 to 64 MPI ranks' -- "$demscale" slump --scene "$small" --engine liggghts --ranks 65
    refuse '--energy = given: accepted demscale.s engine only' -- "$demscale" slump --scene "$small" --engine liggghts --energy
    scene '[liquid]' 'wet_walls = true'
    walls='scene.toml: liquid.wet_walls = true: accepted false with --engine liggghts'
    refuse "$walls" -- "$demscale" slump --scene "$work/scene.toml" --engine liggghts
    for command in "check-exponent --exponent 1" sweep estimate-exponent report; do
      # shellcheck disable=SC2086
      refuse "$walls" -- "$demscale" $command --scene "$work/scene.toml" --engine liggghts --cache "$work/cache"
    done ;;
  non_finite)
    for v in nan inf -inf; do
      scene '[particles]' "radius_mm = $v"
      scene_commands "scene.toml:2: particles.radius_mm = $v: accepted a finite number" "$work/scene.toml"
      scene '[run]' "dt_s = $v"
      scene_commands "scene.toml:2: run.dt_s = $v: accepted a finite number" "$work/scene.toml"
    done
    config '[particle]' 'radii_mm = [1.0, nan]' 'masses_g = [0.01, 0.07]'
    config_commands 'config.toml:2: particle.radii_mm\[1\] = nan: accepted a finite number' "$work/config.toml"
    refuse '--sf = nan: accepted a finite number > 0' -- "$demscale" slump --scene "$small" --sf nan
    refuse '--exponent = inf: accepted \(-20, 20\)' -- "$demscale" slump --scene "$small" --exponent inf
    refuse '--exponent = "nan": accepted comma-separated numbers' -- "$demscale" check-exponent --exponent nan
    refuse '--exponents = "inf": accepted comma-separated numbers' -- "$demscale" sweep --exponents 1,inf
    refuse '--exponent = "-inf": accepted comma-separated numbers' -- "$demscale" curves --figure 3 --exponent -inf
    refuse_no_out '--vhat = nan: accepted a finite number > 0' -- "$demscale" bridge --vhat nan
    refuse_no_out '--hhat = nan: accepted a finite number' -- "$demscale" bridge --hhat nan
    refuse_no_out '--length = nan: accepted a finite number > 0' -- "$demscale" scaling --length nan
    refuse_no_out '--rtol: value nan; accepted a finite number >= 0' -- "$demscale" regress --rtol nan
    refuse_no_out '--seconds: value nan; accepted a finite number > 0' -- "$demscale" bench --seconds nan
    refuse '--tol-profile = inf: accepted a finite number > 0' -- "$demscale" check-exponent --exponent 1 --tol-profile inf
    refuse '--vtk-every: value nan; accepted a finite number >= 0' -- "$demscale" slump --scene "$small" --vtk-every nan ;;
  inconsistent_scene)
    scene '[particles]' 'radius_mm = 12'
    scene_commands 'scene.toml:2: particles.radius_mm = 12: accepted < 4.75 mm \(a quarter of the top opening\)' "$work/scene.toml"
    scene '[run]' 'dt_s = 1e-3'
    scene_commands 'scene.toml:2: run.dt_s = 0.001 s: accepted <= .* s \(0.2 x the Rayleigh time .*\); pass --force-dt' "$work/scene.toml" no-pile
    scene '[liquid]' 'moisture_content = 0.5'
    scene_commands 'scene.toml:2: liquid.moisture_content = 0.5: accepted \[.*, 0.081\] here: the liquid per bridge V/R\^3 = .* must lie in the Mikami fit' "$work/scene.toml"
    scene '[cone]' 'top_diameter_mm = 40'
    scene_commands 'scene.toml:2: cone.top_diameter_mm = 40: accepted < cone.bottom_diameter_mm' "$work/scene.toml"
    scene '[floor]' 'rough = true' 'rough_diameter_mm = 30'
    scene_commands 'scene.toml:3: floor.rough_diameter_mm = 30: accepted >= cone.bottom_diameter_mm = 38' "$work/scene.toml"
    scene '[particles]' 'distribution = "sieve"' 'radius_mm = 1' 'class_radii_mm = [0.8, 1.0]' 'mass_fractions = [0.5, 0.5]'
    scene_commands 'scene.toml:3: particles.radius_mm = given: accepted absent with particles.distribution = "sieve"' "$work/scene.toml"
    scene '[particles]' 'distribution = "lognormal"' 'median_radius_mm = 4' 'geometric_sd = 2'
    scene_commands 'scene.toml:4: particles.geometric_sd = largest sphere 12.51 mm: accepted spheres that pass the cone.s top opening \(radius < 9.5 mm\)' "$work/scene.toml"
    scene '[particles]' 'fill_height_mm = 60'
    scene_commands 'scene.toml:2: particles.fill_height_mm = 60: accepted <= cone.height_mm = 57' "$work/scene.toml"
    # Earlier results in the --out folder survive a refused run untouched.
    refuse_keeping 'scene.toml:2: particles.fill_height_mm = 60' -- "$demscale" slump --scene "$work/scene.toml"
    refuse_keeping 'scene.toml:2: particles.fill_height_mm = 60' -- "$demscale" check-exponent --exponent 1 --scene "$work/scene.toml" --cache "$work/cache"
    refuse_keeping 'scene.toml:2: particles.fill_height_mm = 60' -- "$demscale" report --scene "$work/scene.toml" --cache "$work/cache"
    config '[particle]' 'radii_mm = [1.0, -2.0]' 'masses_g = [0.01, 0.07]'
    refuse_keeping 'config.toml:2: particle.radii_mm\[1\] = -2' -- "$demscale" curves --figure 3 --config "$work/config.toml"
    # A coarse particle that cannot pass the cone's top opening (2 R S_f >= 19 mm).
    refuse '--sf = 10: accepted .*opening' -- "$demscale" slump --sf 10
    refuse '--sf = 10: accepted .*opening' -- "$demscale" check-exponent --exponent 1 --sf 10 --cache "$work/cache" ;;
  malformed_pile)
    # A pile from another engine: the file, line and column of the bad field; no runs file written
    # (or an existing one left as it was).
    pile() { refused "$1" "$demscale" pile "${@:2}"; [ ! -e "$work/runs.csv" ] || fail "runs file written despite the error: ${*:2}"; }
    head='ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\nITEM: ATOMS id type radius z y x\n'
    printf "${head}1 1 0.001 0.001 0 0\n2 1 0.001 0.003 abc 0\n" >"$work/bad.dump"
    printf "${head}1 1 0.001 0.001 0 0\n2 1 0.001 0.003 0 0\n" >"$work/ok.dump"
    printf "${head}1 1 0.001 0.001 0 0\n" >"$work/short.dump"
    printf "${head}1 1 0.0014 0.0014 0 0\n2 1 0.0014 0.0042 0 0\n" >"$work/coarse.dump"
    printf 'x,y,z,r\n0,0,0.001,0.001\n0,0,0.003,-1\n' >"$work/bad.csv"
    run=(--append-runs "$work/runs.csv" --seed 1)
    pile 'bad.dump:11:5 \(y\) = abc: accepted a finite number' --dump "$work/bad.dump" --fill "$work/ok.dump" "${run[@]}"
    pile 'bad.dump:11:5 \(y\) = abc: accepted a finite number' --dump "$work/ok.dump" --fill "$work/bad.dump" "${run[@]}"
    pile 'short.dump:9 \(ATOMS\) = 1 rows: accepted 2 rows, as its NUMBER OF ATOMS says' --dump "$work/short.dump"
    pile 'bad.csv:3:4 \(r\) = -1: accepted a finite number > 0' --dump "$work/bad.csv"
    printf 'ITEM: ATOMS id type x y z\n1 1 0 0 0.001\n' >"$work/noradius.dump"
    pile 'noradius.dump:1 \(ATOMS columns\) = id type x y z: accepted a radius \(or diameter\) column' --dump "$work/noradius.dump"
    printf "${head}1 1 0.001 nan 0 0\n2 1 0.001 0.003 0 0\n" >"$work/nan.dump"
    pile 'nan.dump:10:4 \(z\) = nan: accepted a finite number' --dump "$work/nan.dump"
    pile '--sf = 1: accepted the S_f of the file.s spheres: their largest radius 1.4 mm is S_f 1.4' --dump "$work/coarse.dump" "${run[@]}"
    pile '--sf = 0.5: accepted a scale factor >= 1' --dump "$work/ok.dump" --sf 0.5
    pile '--seed = \(not given\)' --dump "$work/ok.dump" --fill "$work/ok.dump" --append-runs "$work/runs.csv"
    pile '--fill = \(not given\)' --dump "$work/ok.dump" "${run[@]}"
    pile '--gamma = \(not given\): accepted the coarse run.s own surface tension' --dump "$work/coarse.dump" --fill "$work/coarse.dump" --sf 1.4 "${run[@]}"
    pile '--exponent = nan: accepted a finite number' --dump "$work/coarse.dump" --fill "$work/coarse.dump" --sf 1.4 --exponent nan "${run[@]}"
    # An existing file that is not a runs file is refused and left as it was.
    printf 'a,b\n1,2\n' >"$work/other.csv"
    refused 'other.csv \(header row\) = other columns: accepted a runs file as demscale writes them' \
      "$demscale" pile --dump "$work/ok.dump" --fill "$work/ok.dump" --append-runs "$work/other.csv" --seed 1
    [ "$(cat "$work/other.csv")" = "$(printf 'a,b\n1,2')" ] || fail "a refused append changed the file" ;;
  *) fail "unknown class" ;;
esac
echo "ok [$class]: $checked bad inputs refused with exit 2, a message naming the input, and no output"
