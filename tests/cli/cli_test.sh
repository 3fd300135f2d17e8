#!/usr/bin/env bash
# End-to-end checks of the demscale command line: exit codes, messages, and that a failing
# command leaves no output file behind. Usage: cli_test.sh CASE DEMSCALE SOURCE_DIR
set -u
case_name=$1 demscale=$2 src=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "FAIL [$case_name]: $*" >&2; exit 1; }
# expect CODE PATTERN -- command...: exit code CODE and PATTERN (grep -E) in stdout+stderr.
expect() {
  local code=$1 pattern=$2; shift 3
  "$@" >"$work/out" 2>&1; local rc=$?
  [ "$rc" -eq "$code" ] || { cat "$work/out" >&2; fail "exit $rc, expected $code: $*"; }
  grep -Eq -- "$pattern" "$work/out" || { cat "$work/out" >&2; fail "output lacks /$pattern/: $*"; }
}
bad_config() { printf '%s\n' "$@" >"$work/bad.toml"; }

case $case_name in
  regress_passes)
    expect 0 '^ok .*fig3.csv' -- "$demscale" regress
    grep -q '^ok .*fig4.csv' "$work/out" || fail "fig4 not compared" ;;
  regress_fails_on_perturbed_reference)
    cp "$src"/data/reference/fig*.csv "$work/"
    # Perturb one stress value of fig4 by 1e-6 relative (row 50 of the data).
    awk -F, -v OFS=, '/^#/ || !h {if(!/^#/) h=1; print; next} {n++; if(n==50) $9=$9*(1+1e-6); print}' \
      "$src/data/reference/fig4.csv" >"$work/fig4.csv"
    expect 1 'FAIL .*fig4.csv: 1 of' -- "$demscale" regress --reference-dir "$work"
    grep -q 'sigma_pa' "$work/out" || fail "report does not name the drifting column"
    grep -q '^ok .*fig3.csv' "$work/out" || fail "unperturbed fig3 should pass"
    grep -qF "demscale regress --reference-dir '$work' --update" "$work/out" || fail "the update hint drops --reference-dir" ;;
  regress_names_changed_input)
    # A changed exponent in the inputs is named before any value: the first line under fig4's FAIL.
    sed 's/^exponents = .*/exponents = [1.0, 2.5]/' "$src/data/table1.toml" >"$work/k25.toml"
    expect 1 'FAIL .*fig4.csv: inputs changed' -- "$demscale" regress --config "$work/k25.toml"
    grep -A1 'FAIL .*fig4.csv: inputs changed' "$work/out" | tail -1 | grep -q '^  exponents: 1, 3 -> 1, 2.5$' ||
      fail "the changed exponent is not the first thing named"
    grep -q 'exponent .*1010' "$work/out" || fail "no per-column summary"
    grep -q '^ok .*fig3.csv' "$work/out" || fail "fig3 does not depend on the exponents and should pass"
    # The same from a scene: a scene and a config that disagree are refused with the differing keys.
    sed 's/^surface_tension_n_per_m = .*/surface_tension_n_per_m = 0.05/' "$src/data/scenes/kantro_wet.toml" >"$work/s.toml"
    expect 2 'liquid.surface_tension_n_per_m = 0.074 in the config, liquid.surface_tension_n_per_m = 0.05 in the scene' -- \
      "$demscale" table --config "$src/data/table1.toml" --scene "$work/s.toml"
    expect 0 'inputs: .*s.toml' -- "$demscale" table --scene "$work/s.toml"
    grep -Eq 'surface_tension_n_per_m: 0.05$' "$work/out" || fail "table --scene ignores the scene's liquid" ;;
  regress_missing_reference)
    expect 2 'reference = .*fig3.csv.*regress --update' -- "$demscale" regress --reference-dir "$work/none" ;;
  regress_ill_formed_reference)
    cp "$src"/data/reference/fig3.csv "$work/"
    printf '# nothing\n' >"$work/fig4.csv"
    expect 2 'fig4.csv.*header' -- "$demscale" regress --reference-dir "$work" ;;
  regress_unknown_column)
    cp "$src"/data/reference/fig3.csv "$work/"
    sed 's/^variant,radius_mm/variant,radius_cm/' "$src/data/reference/fig4.csv" >"$work/fig4.csv"
    expect 2 'fig4.csv.*radius_cm' -- "$demscale" regress --reference-dir "$work" ;;
  regress_update_writes_references)
    expect 0 'updated .*fig3.csv: new' -- "$demscale" regress --update --reference-dir "$work/ref"
    expect 0 '^ok' -- "$demscale" regress --reference-dir "$work/ref" ;;
  table_csv_interface)
    expect 0 '^radius_mm,sf,mass_g,' -- "$demscale" table --format csv --exponent 1,3
    for col in v_mm3 vhat fc_contact_n hhat_rupture gamma_n_per_m_k1 fc_contact_n_k3 sigma_contact_pa_k1; do
      grep -q "$col" "$work/out" || fail "missing column $col"
    done
    grep -q '^# bridge_variant: mikami1998' "$work/out" || fail "no variant metadata" ;;
  table_json_and_markdown)
    expect 0 '"sigma_contact_pa_k1"' -- "$demscale" table --format json
    expect 0 '^\| radius_mm \|' -- "$demscale" table --format markdown ;;
  bad_radius_exit_2)
    bad_config '[particle]' 'radii_mm = [1.0, -2.0]' 'masses_g = [0.01, 0.07]'
    expect 2 'bad.toml:2: particle.radii_mm\[1\] = -2: accepted a finite number > 0' -- \
      "$demscale" curves --figure 3 --config "$work/bad.toml" --out "$work/out_dir"
    [ ! -e "$work/out_dir" ] || fail "a failed run created output" ;;
  bad_theta_exit_2)
    bad_config '[particle]' 'radii_mm = [1.0]' 'masses_g = [0.01]' '[liquid]' 'contact_angle_deg = 95'
    expect 2 'contact_angle_deg = 95: accepted \[0, 90\) degrees' -- "$demscale" table --config "$work/bad.toml" ;;
  bad_moisture_exit_2)
    bad_config '[particle]' 'radii_mm = [1.0]' 'masses_g = [0.01]' '[liquid]' 'moisture_content = -0.1'
    expect 2 'moisture_content = -0.1: accepted \(0, 1\)' -- "$demscale" table --config "$work/bad.toml" ;;
  unknown_key_exit_2)
    bad_config '[particle]' 'radii_mm = [1.0]' 'masses_g = [0.01]' 'radius_mm = 2'
    expect 2 'unknown key.*did you mean particle.radii_mm' -- "$demscale" table --config "$work/bad.toml" ;;
  malformed_file_exit_2)
    bad_config '[particle' 'radii_mm = 1'
    expect 2 'TOML' -- "$demscale" table --config "$work/bad.toml" ;;
  missing_file_exit_2)
    expect 2 'not found' -- "$demscale" table --config "$work/nope.toml" ;;
  bad_exponent_exit_2)
    expect 2 '--exponent = "abc"' -- "$demscale" table --exponent 1,abc
    expect 2 '--exponent = "nan"' -- "$demscale" table --exponent nan ;;
  bad_figure_exit_2)
    expect 2 'figure' -- "$demscale" curves --figure 5 --out "$work/o"
    [ ! -e "$work/o" ] || fail "output created" ;;
  curves_write_png)
    expect 0 'curves collapse' -- "$demscale" curves --figure 4 --out "$work/plots"
    for f in fig4.csv fig4.gp fig4.png; do [ -s "$work/plots/$f" ] || fail "$f missing"; done
    head -c 8 "$work/plots/fig4.png" | od -An -c | grep -q 'P   N   G' || fail "fig4.png is not a PNG"
    ls -a "$work/plots" | grep -q '\.tmp' && fail "temporary file left behind"
    true ;;
  outputs_in_working_folder)
    # Run as a newcomer would, from an empty folder: outputs land there, not in the source tree.
    mkdir "$work/empty" && cd "$work/empty" || fail "no folder"
    before=$(stat -c %Y "$src/plots/fig3.png")
    expect 0 'curves collapse' -- "$demscale" curves --figure 3 --no-png
    [ -s "$work/empty/plots/fig3.csv" ] || fail "curves did not write plots/fig3.csv in the working folder"
    [ "$(stat -c %Y "$src/plots/fig3.png")" = "$before" ] || fail "the source tree's plots/ changed"
    expect 0 '^ok .*fig3.csv' -- "$demscale" regress
    # An installed copy: the binary and the shipped data under the prefix, and it runs.
    cmake --install "$(dirname "$demscale")" --prefix "$work/prefix" >/dev/null || fail "cmake --install failed"
    [ -x "$work/prefix/bin/demscale" ] || fail "no installed binary"
    [ -s "$work/prefix/share/demscale/data/table1.toml" ] || fail "no installed data"
    [ -s "$work/prefix/share/demscale/data/scenes/kantro_wet.toml" ] || fail "no installed scenes"
    expect 0 '^1,1,.*,ok$' -- "$work/prefix/bin/demscale" table --format csv ;;
  installed_three_jobs_in_empty_folder)
    # A newcomer's session: install, then from an empty folder (also HOME) a report for their own
    # scene, a check-exponent and regress against references kept in that folder. Nothing outside
    # the folder may change: not the prefix, not the source tree.
    cmake --install "$(dirname "$demscale")" --prefix "$work/prefix" >/dev/null || fail "cmake --install failed"
    mkdir "$work/mine" && cd "$work/mine" || fail "no folder"
    touch "$work/marker"; sleep 1
    export HOME="$work/mine" XDG_CACHE_HOME="$work/mine/.cache"
    bin="$work/prefix/bin/demscale"
    sed -e 's/^name = .*/name = "my-glass-beads"/' "$src/data/scenes/small_wet.toml" >my.toml
    printf '[liquid]\nsurface_tension_n_per_m = 0.05\ncontact_angle_deg = 20\n[similarity]\nexponents = [1.0, 2.0]\n' >>my.toml
    expect 0 'wrote report/report.html' -- "$bin" report --quick --scene my.toml --seeds 2
    grep -q 'my-glass-beads' report/report.html || fail "the report is not about the user's scene"
    grep -q 'recomputed from my.toml' report/report.html || fail "the similarity table is not the scene's"
    grep -q 'surface_tension_n_per_m</b>: 0.05' report/report.html || fail "the similarity table ignores the scene's liquid"
    "$bin" check-exponent --exponent 2 --scene my.toml --sf 1.4 --seeds 2 --no-png >"$work/out" 2>&1
    case $? in 0 | 1 | 4) ;; *) cat "$work/out" >&2; fail "check-exponent failed" ;; esac
    grep -q 'verdict: ' "$work/out" || fail "check-exponent gave no verdict"
    grep -q '0 to run' "$work/out" || fail "check-exponent did not reuse the report's runs from cache/"
    expect 0 'updated refs/fig4.csv: new' -- "$bin" regress --scene my.toml --reference-dir refs --update
    expect 0 '^ok .*refs/fig4.csv' -- "$bin" regress --scene my.toml --reference-dir refs
    changed_prefix=$(find "$work/prefix" -newer "$work/marker" | head -3)
    [ -z "$changed_prefix" ] || fail "the install tree changed: $changed_prefix"
    changed_src=$(find "$src" -newer "$work/marker" -not -path "$src/build*" -not -path "$src/.git*" -not -path "$work*" | head -3)
    [ -z "$changed_src" ] || fail "the source tree changed: $changed_src" ;;
  scaling_keep_gravity)
    expect 0 'gravity .* 1 +1 +scaled' -- "$demscale" scaling --length 4 --keep gravity,density
    grep -Eq 'time_step .* 2 +2 ' "$work/out" || fail "S_T should be 2 for S_L = 4 with g kept"
    expect 0 'BROKEN' -- "$demscale" scaling --length 4 --density 1 --time 4 --hold gravity
    # Errors name the option the user typed.
    expect 2 '--length = -1' -- "$demscale" scaling --length -1
    expect 2 '--hold = "?gravty' -- "$demscale" scaling --length 4 --hold gravty
    expect 0 'gamma_n_per_m_k2' -- "$demscale" table --exponents 2 --format csv
    expect 2 '--threads = -1' -- "$demscale" slump --threads -1 ;;
  bridge_exact_and_above_rupture)
    expect 0 '^exact,0.05544,0,0,0.8186' -- "$demscale" bridge --vhat 0.05544 --hhat 0 --model exact --format csv
    expect 0 'beyond rupture.*no bridge, force 0' -- "$demscale" bridge --vhat 0.05544 --hhat 0.5 --model mikami1998
    grep -Eq 'mikami1998 +0.05544 +0 +0.5 +0 ' "$work/out" || fail "force above rupture must be 0"
    # A sphere above a wall: the exact bridge (with the footprint on the wall) below the bound
    # F/(2 pi R gamma) = 2 cos theta, and Mikami's wall fit above it at Table 1's V^.
    expect 0 '^model,vhat,theta_deg,hhat,f_over_2pi_r_gamma,hhat_rupture,bridge_exists,validity,neck_radius_over_r,filling_angle_deg,curvature_kappa,volume_check,wall_footprint_over_r$' \
      -- "$demscale" bridge --geometry sphere-wall --vhat 0.05544 --model exact --format csv
    exact=$(awk -F, '$1 == "exact" {print $5}' "$work/out")
    expect 0 '^mikami1998,0.05544' -- "$demscale" bridge --geometry sphere-wall --vhat 0.05544 --model mikami1998 --format csv
    mikami=$(awk -F, '$1 == "mikami1998" {print $5}' "$work/out")
    awk -v e="$exact" -v m="$mikami" 'BEGIN { exit !(e > 1 && e < 2 && m > e) }' || fail "sphere-wall forces: exact $exact, Mikami $mikami"
    grep -q 'above_physical_bound' "$work/out" || fail "Mikami's wall fit above 4 pi R gamma not flagged"
    # A fit outside its range says so, in the row and in a note.
    expect 0 'outside_fitted_range;above_physical_bound' -- "$demscale" bridge --model mikami1998 --vhat 1e-7 --theta 40
    grep -q 'note: outside_fitted_range: mikami1998 is fitted for' "$work/out" || fail "no note for the range" ;;
  bridge_bad_input_exit_2)
    expect 2 'did you mean willett' -- "$demscale" bridge --model wilett
    expect 2 'contact_angle_deg = 95' -- "$demscale" bridge --theta 95
    expect 2 '\-\-vhat = -1' -- "$demscale" bridge --vhat -1
    # Found by the fuzz corpus: outside the exact solver's scope is bad input (exit 2), not a failure.
    expect 2 'concave \(pendular\) bridge' -- "$demscale" bridge --vhat 0.1 --theta 89.9 --model exact
    expect 2 '\-\-geometry = wall: accepted sphere-sphere or sphere-wall' -- "$demscale" bridge --geometry wall
    expect 2 'with --geometry sphere-wall' -- "$demscale" bridge --geometry sphere-wall --model willett
    expect 2 '\-\-theta-wall = 30: accepted only with --geometry sphere-wall' -- "$demscale" bridge --theta-wall 30 ;;
  bridge_error_quick)
    expect 0 'mikami1998' -- "$demscale" bridge-error --quick --out "$work/be"
    for f in bridge_error.csv bridge_error_summary.csv bridge_wall_error.csv bridge_mikami_error.png bridge_speed_error.png; do
      [ -s "$work/be/$f" ] || fail "$f missing"
    done
    head -20 "$work/be/bridge_error.csv" | grep -q '^vhat,theta_deg,x,hhat,fhat_exact,fhat_mikami,fhat_yun_park_2017,fhat_willett' \
      || fail "bridge_error.csv header"
    grep -q '^vhat,theta_deg,x,hhat,fhat_exact,fhat_mikami_wall,rel_error,rupture_ratio$' "$work/be/bridge_wall_error.csv" \
      || fail "bridge_wall_error.csv header"
    grep -q '^mikami1998 sphere-wall' "$work/out" || fail "summary lacks the sphere-wall fit" ;;
  slump_small_json)
    expect 0 '"spread_d95_mm"' -- "$demscale" slump --scene "$src/data/scenes/small_wet.toml" --format json --out "$work/s"
    for key in particles steps dt_s wall_s final_height_mm slump_mm spread_d95_mm spread_max_mm repose_angle_deg; do
      grep -q "\"$key\"" "$work/out" || fail "json lacks $key"
    done
    for f in slump_profile.csv slump_history.csv slump_final.vtp slump_side.png; do [ -s "$work/s/$f" ] || fail "$f missing"; done
    grep -q '"energy_j"' "$work/out" && fail "energy ledger printed without --energy"
    tr -d ' \n' <"$work/out" | grep -q '"contact_laws":\["hertz","mindlin","liquid_bridge"\]' || fail "contact laws not named"
    # With --energy: the same physics, and a ledger that balances (conservation of energy) to 3 %.
    cp "$work/out" "$work/plain.json"
    expect 0 '"energy_balance_error"' -- "$demscale" slump --scene "$src/data/scenes/small_wet.toml" --format json --energy --out "$work/e"
    diff <(grep -E '"(slump_mm|spread_d95_mm|steps)"' "$work/plain.json") <(grep -E '"(slump_mm|spread_d95_mm|steps)"' "$work/out") >&2 ||
      fail "the ledger changed the run"
    err=$(grep '"energy_balance_error"' "$work/out" | sed 's/.*: *//; s/,//')
    awk -v e="$err" 'BEGIN { exit !(e < 0.03 && e > -0.03) }' || fail "energy balance error $err"
    head -2 "$work/e/slump_history.csv" | grep -q 'lost_friction_j,lost_rolling_j,lost_bridges_j' || fail "history lacks the ledger" ;;
  polydisperse_scene)
    # A wet lognormal scene (data/scenes/small_wet_lognormal.toml): the pile keeps each size bin's
    # share of the mass, comes to rest, its ledger balances; a zero-width distribution (sigma_g = 1,
    # or a sieve of one class) is the one-radius run to the bit; check-exponent, report and export
    # take the scene, the fills of every S_f weigh the same, and the report and deck say the sizes.
    poly="$src/data/scenes/small_wet_lognormal.toml"
    "$demscale" slump --scene "$poly" --format json --energy --no-png --out "$work/p" >"$work/p.json" 2>"$work/p.err" ||
      { cat "$work/p.err" >&2; fail "the polydisperse slump failed"; }
    json=$(tr -d ' \n' <"$work/p.json")
    grep -q '"particle_sizes":"lognormalbymass,sigma_g=1.2' <<<"$json" || fail "sizes not said"
    grep -q '"came_to_rest":true' <<<"$json" || fail "the polydisperse pile did not rest"
    grep -q '"contact_laws":\["hertz","mindlin","liquid_bridge"\]' <<<"$json" || fail "contact laws not named"
    # Each of the 8 equal-mass bins near its share: 0.05 is about 3 standard errors of a bin of
    # 0.125 among these 480 spheres (the sampling test is pour_test.cpp's, with the errors written out).
    shares=$(sed 's/.*"distribution_mass_fractions":\[\([^]]*\)\].*/\1/' <<<"$json")
    pile=$(sed 's/.*"pile_mass_fractions":\[\([^]]*\)\].*/\1/' <<<"$json")
    awk -v a="$shares" -v b="$pile" 'BEGIN { n = split(a, e, ","); m = split(b, p, ",");
      if (n != 8 || m != 8) exit 1; for (i = 1; i <= n; ++i) if (p[i] - e[i] > 0.05 || e[i] - p[i] > 0.05) exit 1 }' ||
      fail "the pile's size bins $pile against $shares"
    err=$(sed 's/.*"energy_balance_error":\([^,}]*\).*/\1/' <<<"$json")
    awk -v e="$err" 'BEGIN { exit !(e < 0.03 && e > -0.03) }' || fail "energy balance error $err"
    "$demscale" slump --scene "$src/data/scenes/small_wet.toml" --no-png --out "$work/one" >/dev/null 2>&1 || fail "one radius did not run"
    for width in 'distribution = "lognormal"\nmedian_radius_mm = 2.2\ngeometric_sd = 1' \
                 'distribution = "sieve"\nclass_radii_mm = [2.2]\nmass_fractions = [1]'; do
      sed "s/^radius_mm = 2.2/$width/" "$src/data/scenes/small_wet.toml" >"$work/zero.toml"
      grep -q 'distribution' "$work/zero.toml" || fail "the zero-width scene was not written"
      rm -rf "$work/zero"
      "$demscale" slump --scene "$work/zero.toml" --no-png --out "$work/zero" >/dev/null 2>&1 || fail "zero width did not run"
      for f in slump_particles.csv slump_history.csv slump_profile.csv; do
        cmp <(grep -v '^#' "$work/one/$f") <(grep -v '^#' "$work/zero/$f") || fail "zero width ($width) differs from one radius in $f"
      done
    done
    "$demscale" check-exponent --scene "$poly" --exponent 1 --sf 1.4 --seeds 2 --no-png --cache "$work/cache" --out "$work/ce" \
      --format json >"$work/ce.json" 2>"$work/ce.err"
    rc=$?
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || [ "$rc" -eq 4 ] || { cat "$work/ce.err" >&2; fail "check-exponent exit $rc"; }
    # The fills of every S_f weigh the same: each ensemble's fill_mass_ratio within 1 %.
    ratios=$(tr -d ' \n' <"$work/ce.json" | grep -o '"fill_mass_ratio":[^,}]*' | sed 's/.*://')
    [ "$(wc -w <<<"$ratios")" -ge 2 ] || fail "no fill masses in check-exponent's JSON"
    for r in $ratios; do awk -v r="$r" 'BEGIN { exit !(r > 0.99 && r < 1.01) }' || fail "fill mass ratio $r"; done
    expect 0 'wrote .*report.html' -- "$demscale" report --quick --scene "$poly" --cache "$work/cache" --out "$work/rep"
    grep -q 'particle sizes.*lognormal by mass' "$work/rep/report.md" || fail "the report's scene table lacks the sizes"
    grep -q 'every size scales by S_f alike' "$work/rep/report.md" || fail "the similarity table does not say the sizes"
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$poly" --out "$work/deck"
    grep -q '^# unequal spheres' "$work/deck/in.slump" || fail "the deck does not list the unequal-sphere differences" ;;
  slump_exact_bridges)
    # Exact (tabulated) bridges between spheres and to wet walls: the run names both laws and warns
    # of nothing; with Mikami's wall fit chosen instead it warns of its excess over the exact bridge.
    { cat "$src/data/scenes/small_wet.toml"; printf '[liquid]\nbridge_variant = "table"\nwet_walls = true\n'; } >"$work/exact.toml"
    expect 0 '"bridge_law": "table"' -- "$demscale" slump --scene "$work/exact.toml" --format json --no-png --out "$work/x"
    grep -q '"wall_bridge_law": "table"' "$work/out" || fail "wall law not named"
    grep -q '"bridge_warnings": \[\]' "$work/out" || fail "warnings for exact bridges"
    grep -q '"final_height_mm"' "$work/out" || fail "no result"
    sed -i 's/^wet_walls = true/wet_walls = true\nwall_bridge = "mikami1998"/' "$work/exact.toml"
    "$demscale" slump --scene "$work/exact.toml" --format json --no-png --out "$work/y" >"$work/fit.json" 2>"$work/fit.err" || fail "fit walls failed"
    grep -q '"wall_bridge_law": "mikami1998"' "$work/fit.json" || fail "fit wall law not named"
    grep -q "warning: particle-wall bridges: Mikami's sphere-wall fit pulls" "$work/fit.err" || fail "no wall-fit warning"
    # Willett et al.'s fit as the bridge between spheres: named, run, and said in the LIGGGHTS deck to have no equivalent there.
    { cat "$src/data/scenes/small_wet.toml"; printf '[liquid]\nbridge_variant = "willett"\n'; } >"$work/willett.toml"
    expect 0 '"bridge_law": "willett"' -- "$demscale" slump --scene "$work/willett.toml" --format json --no-png --out "$work/w"
    grep -q '"final_height_mm"' "$work/out" || fail "no result with Willett's bridges" ;;
  backend_bad_input_exit_2)
    # Refused before anything runs or is submitted, with or without Slurm on the machine.
    small=(check-exponent --exponent 1 --scene "$src/data/scenes/small_wet.toml" --sf 1.4 --seeds 2 --out "$work/bad")
    expect 2 '--backend = cluster.*local or slurm' -- "$demscale" "${small[@]}" --backend cluster
    expect 2 '--backend = slurm.*cache' -- "$demscale" "${small[@]}" --backend slurm --no-cache
    expect 2 '--backend = local.*--wait' -- "$demscale" "${small[@]}" --wait
    expect 2 '--backend = local.*--sbatch-option' -- "$demscale" "${small[@]}" --sbatch-option=--time=5
    expect 2 '--key = .*/0123.scene: accepted a scene text' -- "$demscale" cached-run --cache "$work/cache" --key 0123
    [ ! -e "$work/bad" ] || fail "a refused call wrote outputs"
    [ ! -e "$work/cache" ] || fail "a refused cached-run created the cache" ;;
  bench_size_sweep)
    # The size sweep's table: dry and wet, lattice order and shuffled, for each size; bad sizes refused.
    expect 0 '^laws,order,particles,steps,wall_s,particle_steps_per_s,rate_vs_smallest,contacts_per_particle,contact_steps_per_s,contact_rate_vs_smallest,peak_bytes_per_particle$' -- \
      "$demscale" bench --dem --sizes 300,600 --steps 10 --timed 1 --format csv
    # Each row names its laws from the parts that acted (dry, then the scene's bridge with its curve).
    [ "$(grep -c '^hertz+mindlin\(+liquid_bridge(mikami1998)\)\?,\(lattice\|shuffled\),' "$work/out")" -eq 8 ] || { cat "$work/out" >&2; fail "not 8 rows"; }
    grep -qi 'nan\|inf' "$work/out" && fail "NaN or inf in the sweep"
    # A time below the noise (the difference of two runs) is not printed as a negative wall time.
    awk -F, '/^hertz/ && $5 + 0 < 0 { bad = 1 } END { exit bad }' "$work/out" || fail "negative wall_s"
    expect 2 '--sizes = 300: accepted with --dem' -- "$demscale" bench --sizes 300
    expect 2 '--sizes = "5e7".*\(99, 2e\+07\)' -- "$demscale" bench --dem --sizes 5e7
    expect 2 '--steps = 5: accepted 10 to 100000' -- "$demscale" bench --dem --sizes 300 --steps 5
    expect 2 '--timed: value nan; accepted a finite number > 0' -- "$demscale" bench --dem --sizes 300 --timed nan ;;
  bench_core_link)
    # The cross-core probe the bench scripts log: four positive finite numbers; not with --dem.
    expect 0 '^kept_ns_per_line,crossing_ns_per_line,crossing_over_kept,empty_region_us$' -- "$demscale" bench --core-link --format csv
    grep -v '^#' "$work/out" | awk -F, 'NR == 2 {for (i = 1; i <= 4; ++i) if (!($i + 0 > 0) || $i ~ /n|N/) exit 1; ok = 1} END {exit !ok}' ||
      { cat "$work/out" >&2; fail "not four positive finite numbers"; }
    expect 2 '--core-link = given with --dem: accepted on its own' -- "$demscale" bench --core-link --dem ;;
  slump_hooke_dry)
    # A dry column on the linear spring (contact.normal_law = "hooke"): it runs on its engine with
    # small overlaps (the default 400 N/m holds a 2.2 mm column to a few % of R), names its laws, and
    # its LIGGGHTS deck uses model hooke and says how the stiffness differs.
    { cat "$src/data/scenes/small_wet.toml"; printf '[contact]\nnormal_law = "hooke"\n[liquid]\nwet = false\n'; } >"$work/hooke.toml"
    expect 0 '"final_height_mm"' -- "$demscale" slump --scene "$work/hooke.toml" --format json --no-png --out "$work/h"
    tr -d ' \n' <"$work/out" | grep -q '"contact_laws":\["hooke","mindlin"\]' || fail "contact laws not named"
    overlap=$(grep '"fill_max_overlap_r"' "$work/out" | sed 's/.*: *//; s/,//')
    awk -v o="$overlap" 'BEGIN { exit !(o > 0 && o < 0.05) }' || fail "overlap $overlap of R"
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$work/hooke.toml" --out "$work/deck"
    grep -q '^pair_style gran model hooke tangential history rolling_friction epsd3' "$work/deck/in.slump" || fail "no model hooke"
    grep -q 'wall/gran model hooke tangential history' "$work/deck/in.slump" || fail "walls not hooke"
    grep -q 'property/global characteristicVelocity scalar 0.3' "$work/deck/in.slump" || fail "no characteristic velocity"
    grep -q "^# linear spring-dashpot normal contact (Hooke): LIGGGHTS' model hooke derives k_n" "$work/deck/in.slump" || fail "no note" ;;
  pile_measures_any_engine)
    # A demscale run read back through the door for other engines' piles: the same measures as the
    # run's own JSON, from its particle CSV (mm) and from a LAMMPS dump (m, columns shuffled, an
    # earlier snapshot first), and its row in a runs file.
    small="$src/data/scenes/small_wet.toml"
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$small" --out "$work/deck"
    expect 0 '"final_height_mm"' -- "$demscale" slump --scene "$small" --start "$work/deck/settled.csv" --format json --no-png --out "$work/run"
    cp "$work/out" "$work/slump.json"
    n=$(grep -vc '^#\|^x_mm' "$work/run/slump_particles.csv")
    { printf 'ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\nITEM: ATOMS id type x y z radius\n1 1 0 0 0.5 0.002\n'
      printf 'ITEM: TIMESTEP\n30833\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS ff ff ff\n-0.1 0.1\n-0.1 0.1\n-0.001 0.13\nITEM: ATOMS id type radius z y x\n' "$n"
      awk -F, '!/^#/ && !/^x_mm/ { printf "%d 1 %.17g %.17g %.17g %.17g\n", ++i, $4 / 1000, $3 / 1000, $2 / 1000, $1 / 1000 }' "$work/run/slump_particles.csv"
    } >"$work/final.dump"
    value() { grep "\"$2\":" "$1" | head -1 | sed 's/.*: *//; s/,$//'; }
    same() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; m = a < 0 ? -a : a; exit !(a != "" && (d < 0 ? -d : d) <= 1e-9 * m + 1e-12) }'; }
    for pile in "$work/run/slump_particles.csv" "$work/final.dump"; do
      expect 0 '"final_height_mm"' -- "$demscale" pile --scene "$small" --dump "$pile" --fill "$work/deck/settled.csv"
      for pair in initial_height_mm:fill_height_mm final_height_mm:final_height_mm slump_mm:slump_mm \
          slump_over_fill_height:slump_over_fill_height spread_mm:spread_mm fill_mass_g:fill_mass_g particles:particles; do
        a=$(value "$work/slump.json" "${pair%%:*}") b=$(value "$work/out" "${pair##*:}")
        same "$a" "$b" || fail "$(basename "$pile"): ${pair%%:*} $a in the run, ${pair##*:} $b measured by pile"
      done
    done
    grep -q '"snapshots": 2' "$work/out" || fail "the dump's snapshots not counted"
    grep -q '"pile_format": "dump"' "$work/out" || fail "the dump not read as one"
    # Into a runs file: created, a second run added, the same run again refused and the file kept.
    args=(pile --scene "$small" --dump "$work/final.dump" --fill "$work/deck/settled.csv" --append-runs "$work/runs.csv")
    expect 0 'added the run to' -- "$demscale" "${args[@]}" --seed 1
    expect 0 'added the run to' -- "$demscale" "${args[@]}" --seed 2 --gamma 0
    cp "$work/runs.csv" "$work/runs.before"
    expect 2 'seed 1: accepted a run the file does not hold yet' -- "$demscale" "${args[@]}" --seed 1
    cmp -s "$work/runs.csv" "$work/runs.before" || fail "a refused run changed the runs file"
    grep -v '^#' "$work/runs.csv" | awk -F, -v s="$(value "$work/slump.json" slump_over_fill_height)" '
      NR == 1 { ok = $1 == "sf" && $2 == "gamma_n_per_m" && $4 == "slump_over_height"; next }
      { rows++; d = $4 - s; if ((d < 0 ? -d : d) > 1e-9) ok = 0 }
      NR == 2 && !($2 > 0) { ok = 0 }  NR == 3 && $2 != 0 { ok = 0 }
      END { exit !(ok && rows == 2) }' || { cat "$work/runs.csv" >&2; fail "runs rows"; } ;;
  liggghts_missing_exit_3)
    # Without mpirun or LIGGGHTS on PATH a LIGGGHTS run stops before its settle, naming what to install.
    PATH=/nonexistent "$demscale" slump --scene "$src/data/scenes/small_wet.toml" --engine liggghts --out "$work/s" >"$work/out" 2>&1
    rc=$?
    [ "$rc" -eq 3 ] || { cat "$work/out" >&2; fail "exit $rc, expected 3"; }
    grep -q 'mpirun not found on PATH: --engine liggghts needs Open MPI and LIGGGHTS (Debian: apt-get install openmpi-bin liggghts)' "$work/out" ||
      { cat "$work/out" >&2; fail "no message naming what is missing"; }
    ! grep -q 'settle' "$work/out" || fail "the settle ran before the check"
    [ ! -e "$work/s/slump_profile.csv" ] || fail "a failed run wrote results" ;;
  slump_bad_scene_exit_2)
    printf '[particles]\nradius_mm = -1\n' >"$work/bad.toml"
    expect 2 'bad.toml:2: particles.radius_mm = -1' -- "$demscale" slump --scene "$work/bad.toml" --out "$work/s"
    [ ! -e "$work/s" ] || fail "a failed run created output"
    # A wet run from a start state of unequal spheres bridges each pair with its own radius, on an
    # engine line of its own; with a rolling law that line lacks (epsd2) it is refused, naming it.
    printf '# demscale particle state (SI)\nx,y,z,vx,vy,vz,wx,wy,wz,radius,density\n0,0,0.0022,0,0,0,0,0,0,0.0022,2200\n0.006,0,0.003,0,0,0,0,0,0,0.003,2200\n' \
      >"$work/mixed.csv"
    expect 0 'wrote .*slump_particles.csv' -- \
      "$demscale" slump --scene "$src/data/scenes/small_wet.toml" --start "$work/mixed.csv" --no-png --out "$work/mixed"
    { cat "$src/data/scenes/small_wet.toml"; printf '[contact]\nrolling_model = "epsd2"\nrolling_damping = 0\n'; } >"$work/epsd2.toml"
    expect 2 'the contact laws Hertz normal contact, liquid bridge of each pair.s radius, epsd2 rolling: accepted one of the compiled engines' -- \
      "$demscale" slump --scene "$work/epsd2.toml" --start "$work/mixed.csv" --out "$work/s"
    [ ! -e "$work/s" ] || fail "a refused run created output"
    # The ledger with a rolling law the engine list compiles none for: refused naming the list.
    expect 2 'the contact laws Hertz normal contact, liquid bridge, epsd2 rolling, energy ledger: accepted one of the compiled engines \(lib/slump/compiled_engines.hpp\): Hertz normal contact, no cohesion, epsd rolling;' -- \
      "$demscale" slump --scene "$work/epsd2.toml" --energy --out "$work/s"
    [ ! -e "$work/s" ] || fail "a refused run created output" ;;
  check_exponent_pass_and_fail)
    small=(--scene "$src/data/scenes/small_wet.toml" --sf 1.4 --cache "$work/cache" --out "$work/c" --no-png)
    # Loose tolerances pass (exit 0), tight ones fail (exit 1) on the very same runs; one seed cannot
    # decide (INCONCLUSIVE, exit 4).
    expect 0 'verdict: PASS' -- "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 3 --tol-slump 10 --tol-spread 10 --tol-profile 10
    grep -q '12 distinct runs' "$work/out" || fail "study did not say what it runs (3 seeds: fine, S_f 1.4, and both dry)"
    grep -q 'baseline-corrected' "$work/out" && grep -q '(decides)' "$work/out" || fail "the baseline-corrected verdict does not say it decides"
    grep -q 'dry control' "$work/out" || fail "the dry control is not shown beside the verdicts"
    grep -q 'left' "$work/out" || fail "no estimate of the time left"
    expect 1 'verdict: FAIL' -- "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 3 --tol-profile 1e-6
    grep -q '0 to run' "$work/out" || fail "second call did not reuse the cached runs"
    expect 4 'verdict: INCONCLUSIVE' -- "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 1 --tol-slump 10 --tol-spread 10 --tol-profile 10
    grep -q 'fewer than two seeds' "$work/out" || fail "INCONCLUSIVE without its reason"
    # A fourth seed on top of the three cached ones (run before --k-range's levels cache part of it) is a second look (optional stopping): said, and noted in the table.
    "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 4 --tol-slump 10 --tol-spread 10 --tol-profile 10 >"$work/out" 2>&1
    grep -q 'SECOND LOOK: every run of seeds .* came from the cache, seed .* is new' "$work/out" || { cat "$work/out" >&2; fail "adding a seed was not called a second look"; }
    grep -q 'SECOND LOOK' "$work/c/check_k1_verdicts.csv" || fail "the verdict table does not note the second look"
    expect 0 'verdict: PASS' -- "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 3 --tol-slump 10 --tol-spread 10 --tol-profile 10 --baseline none
    grep -q 'dry control' "$work/out" && fail "--baseline none still shows a dry control"
    grep -q 'the raw comparison' "$work/out" || fail "--baseline none does not say the raw comparison decides"
    expect 2 '--baseline = wet' -- "$demscale" check-exponent --exponent 1 "${small[@]}" --baseline wet
    expect 1 '"verdict": "FAIL"' -- "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 3 --tol-profile 1e-6 --format json
    for f in check_k1.csv check_k1_verdicts.csv check_k1_runs.csv check_k1_profiles.csv check_k1_profiles.gp check_k1_error_vs_k.gp; do
      [ -s "$work/c/$f" ] || fail "$f missing"
    done
    [ "$(grep -c '^1\(\.4\)\?,' "$work/c/check_k1_runs.csv")" -eq 12 ] || fail "check_k1_runs.csv does not hold the 12 runs (3 seeds, fine and coarse, wet and dry)"
    # --k-range: the response curves beside the verdict, and the range of k that passes.
    "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 3 --k-range >"$work/out" 2>&1
    grep -q '^  S_f = 1.4: k-hat = .*\[' "$work/out" || { cat "$work/out" >&2; fail "--k-range printed no k-hat"; }
    grep -q 'range of k that passes' "$work/out" || fail "--k-range did not say what it prints"
    [ -s "$work/c/estimate_exponent.csv" ] || fail "--k-range wrote no estimate"
    grep -qi 'nan\|inf' "$work/c/check_k1_verdicts.csv" && fail "NaN or inf in the verdicts"
    # --runs: the study's own runs file judged without running gives the same slump and spread cells.
    "$demscale" check-exponent --exponent 1 "${small[@]}" --seeds 3 --format csv >"$work/ran.csv" 2>/dev/null
    cp "$work/c/check_k1_runs.csv" "$work/runs.csv"
    "$demscale" check-exponent --exponent 1 --runs "$work/runs.csv" --scene "$src/data/scenes/small_wet.toml" --out "$work/fr" >"$work/out" 2>&1
    case $? in 0 | 1 | 4) ;; *) cat "$work/out" >&2; fail "check-exponent --runs failed" ;; esac
    grep -q 'none run; slump and spread judged' "$work/out" || fail "--runs did not say what it judged"
    for comparison in raw baseline-corrected; do
      a=$(grep "^1.4,1,$comparison," "$work/ran.csv" | cut -d, -f5,6)
      b=$(grep -v '^#' "$work/fr/check_k1_from_runs.csv" | grep "^1.4,1,$comparison," | cut -d, -f5,6)
      [ -n "$a" ] && [ "$a" = "$b" ] || fail "$comparison: the runs give '$b', the runs file '$a'"
    done
    grep -q '^1.4,1,raw,3,.*,not judged,' "$work/fr/check_k1_from_runs.csv" || fail "the profile is not marked not judged" ;;
  check_exponent_bad_input_exit_2)
    expect 2 '--sf = "0".*\(0, 100\)' -- "$demscale" check-exponent --exponent 1 --sf 0 --out "$work/c"
    expect 2 '--scale = stiffness' -- "$demscale" check-exponent --exponent 1 --scale stiffness --out "$work/c"
    expect 2 '--tol-profile = -1|--tol-profile = -0.5' -- "$demscale" check-exponent --exponent 1 --tol-profile -0.5 --out "$work/c"
    expect 2 '--sf = 20.*top opening' -- "$demscale" check-exponent --exponent 1 --sf 20 --out "$work/c"
    expect 2 '--seeds = 70.*1 to 64' -- "$demscale" sweep --exponents 1 --seeds 70 --out "$work/c"
    expect 2 '--jobs = -1' -- "$demscale" sweep --jobs -1 --out "$work/c"
    expect 2 '--exponents = "x"' -- "$demscale" report --exponents 1,x --out "$work/c"
    printf '[check]\nslump_tolerance = -1\n' >"$work/bad.toml"
    expect 2 'bad.toml:2: check.slump_tolerance = -1' -- "$demscale" report --quick --scene "$work/bad.toml" --out "$work/c"
    expect 2 '--sf = 20.*top opening' -- "$demscale" report --quick --sf 20 --out "$work/c"
    expect 2 '--seed-base = -3' -- "$demscale" report --quick --seed-base -3 --out "$work/c"
    [ ! -e "$work/c" ] || fail "a refused study or report created output" ;;
  estimate_exponent_small)
    small=(--scene "$src/data/scenes/small_wet.toml" --sf 1.4 --seeds 2 --levels 3 --resamples 100 --cache "$work/cache" --out "$work/e")
    # Exit 0 (k determined) or 4 (undetermined) are both answers; the files and the summary must be there.
    "$demscale" estimate-exponent "${small[@]}" >"$work/out" 2>&1; rc=$?
    [ "$rc" -eq 0 ] || [ "$rc" -eq 4 ] || { cat "$work/out" >&2; fail "exit $rc"; }
    grep -q '16 distinct runs' "$work/out" || fail "did not say what it runs (3 levels x 2 seeds, fine and S_f = 1.4, and the dry control)"
    grep -q 'left' "$work/out" || fail "no estimate of the time left"
    grep -q '^  S_f = 1.4: k-hat = .*standing.*slumped runs' "$work/out" || fail "no estimate printed"
    grep -q 'transition model (decides' "$work/out" || fail "which estimate decides not said"
    grep -q '6 fine runs at 3 levels' "$work/out" || fail "cost of the fine curve not stated"
    for f in estimate_response.csv estimate_exponent.csv estimate_residual.csv estimate_collapse.gp; do
      [ -s "$work/e/$f" ] || fail "$f missing"
    done
    grep -qi 'nan\|inf' "$work/e/estimate_exponent.csv" "$work/e/estimate_response.csv" && fail "NaN or inf in the estimate"
    [ "$(grep -c '^1.4,[0-9]' "$work/e/estimate_response.csv")" -eq 3 ] || fail "not three coarse levels"
    [ "$(grep -c '^1.4,n/a' "$work/e/estimate_response.csv")" -eq 1 ] || fail "no dry control at S_f = 1.4"
    grep -q '^1.4,transition model,baseline-corrected,' "$work/e/estimate_exponent.csv" || fail "no baseline-corrected estimate"
    grep -q '^1.4,transition model,raw,' "$work/e/estimate_exponent.csv" || fail "no raw estimate beside it"
    grep -q '^1.4,means shift,baseline-corrected,' "$work/e/estimate_exponent.csv" || fail "no means shift beside the model"
    # The study's runs, one row per run (6 fine, 6 coarse, 4 dry), read back: the same estimate to the bit.
    [ "$(grep -c '^1\(\.4\)\?,' "$work/e/estimate_runs.csv")" -eq 16 ] || fail "estimate_runs.csv does not hold the 16 runs"
    "$demscale" estimate-exponent --scene "$src/data/scenes/small_wet.toml" --runs "$work/e/estimate_runs.csv" --resamples 100 --out "$work/r" --no-png \
      >"$work/out_r" 2>&1; rc_r=$?
    [ "$rc_r" -eq "$rc" ] || { cat "$work/out_r" >&2; fail "--runs exit $rc_r, the runs themselves $rc"; }
    grep -q 'none run' "$work/out_r" || fail "--runs did not say it ran nothing"
    diff <(grep -v '^#' "$work/e/estimate_exponent.csv") <(grep -v '^#' "$work/r/estimate_exponent.csv") ||
      fail "--runs does not give the same estimate as the runs"
    diff <(grep -v '^#' "$work/e/estimate_runs.csv") <(grep -v '^#' "$work/r/estimate_runs.csv") || fail "estimate_runs.csv does not round-trip"
    grep -v '^#' "$work/e/estimate_response.csv" | head -1 | grep -q ',seeds_split,standing,slumped_mean$' || fail "response table does not say which levels split"
    grep -v '^#' "$work/e/estimate_exponent.csv" | head -1 | grep -q ',split_levels,' || fail "estimates do not count the split levels they rest on"
    "$demscale" estimate-exponent "${small[@]}" >"$work/out" 2>&1
    grep -q '0 to run' "$work/out" || fail "second call did not reuse the cached runs"
    # A dry scene has nothing to vary: the dry control, one level per S_f.
    sed 's/^\[run\]/[liquid]\nwet = false\n[run]/' "$src/data/scenes/small_wet.toml" >"$work/dry.toml"
    expect 0 'dry control' -- "$demscale" estimate-exponent --scene "$work/dry.toml" --sf 1.4 --seeds 2 --cache "$work/cache" --out "$work/d" --no-png
    grep -q 'dry scene: no liquid to vary' "$work/out" || fail "dry scene not said"
    [ -s "$work/d/estimate_dry_control.csv" ] || fail "dry control CSV missing" ;;
  estimate_exponent_bad_input_exit_2)
    expect 2 '--levels = 2.*3 to 12' -- "$demscale" estimate-exponent --levels 2 --out "$work/e"
    expect 2 '--range = 4,1' -- "$demscale" estimate-exponent --range 4,1 --out "$work/e"
    expect 2 '--seeds = 1.*2 to 64' -- "$demscale" estimate-exponent --seeds 1 --out "$work/e"
    expect 2 '--sf = 1.*> 1' -- "$demscale" estimate-exponent --sf 1 --out "$work/e"
    expect 2 '--resamples = 5' -- "$demscale" estimate-exponent --resamples 5 --out "$work/e"
    expect 2 '--seed-base = -3' -- "$demscale" estimate-exponent --seed-base -3 --out "$work/e"
    printf 'sf,gamma_n_per_m,seed,slump_over_height,spread_over_d0\n1,0.07,1,0.5,1.2\n1,0.07,2,abc,1.2\n' >"$work/bad_runs.csv"
    expect 2 'bad_runs.csv:3:4 \(slump_over_height\) = abc' -- "$demscale" estimate-exponent --runs "$work/bad_runs.csv" --out "$work/e"
    printf 'sf,gamma_n_per_m,seed,slump_over_height,spread_over_d0\n0.5,0.07,1,0.5,1.2\n' >"$work/bad_runs.csv"
    expect 2 'bad_runs.csv:2:1 \(sf\) = 0.5.*>= 1' -- "$demscale" estimate-exponent --runs "$work/bad_runs.csv" --out "$work/e"
    printf 'sf,gamma,seed,slump_over_height,spread_over_d0\n1,0.07,1,0.5,1.2\n' >"$work/bad_runs.csv"
    expect 2 'neither gamma_n_per_m nor gamma_factor' -- "$demscale" estimate-exponent --runs "$work/bad_runs.csv" --out "$work/e"
    printf 'sf,gamma_n_per_m,seed,slump_over_height,spread_over_d0\n1,0.07,1,0.5,1.2\n1,0.07,1,0.4,1.2\n' >"$work/bad_runs.csv"
    expect 2 'bad_runs.csv:3.*each run once' -- "$demscale" estimate-exponent --runs "$work/bad_runs.csv" --out "$work/e"
    expect 2 'no_such.csv' -- "$demscale" estimate-exponent --runs "$work/no_such.csv" --out "$work/e"
    printf 'sf,gamma_n_per_m,seed,slump_over_height,spread_over_d0\n1,0.074,1,0.5,1.2\n1,0.074,2,0.52,1.2\n1.4,0.1036,1,0.5,1.2\n' >"$work/bad_runs.csv"
    expect 2 '--runs = .*coarse runs at S_f 1.96' -- "$demscale" check-exponent --exponent 1 --sf 1.4,1.96 --runs "$work/bad_runs.csv" --out "$work/e"
    expect 2 '--k-range = given with --runs' -- "$demscale" check-exponent --exponent 1 --k-range --runs "$work/bad_runs.csv" --out "$work/e"
    printf 'sf,gamma_n_per_m,seed,slump_over_height,spread_over_d0\n1,0.07,1,0.5,1.2\n1,0.07,2,abc,1.2\n' >"$work/bad_runs.csv"
    expect 2 'bad_runs.csv:3:4 \(slump_over_height\) = abc' -- "$demscale" check-exponent --exponent 1 --runs "$work/bad_runs.csv" --out "$work/e"
    [ ! -e "$work/e" ] || fail "a refused estimate created output" ;;
  report_quick_structure)
    expect 0 'wrote .*report.html' -- "$demscale" report --quick --out "$work/r" --cache "$work/cache"
    md="$work/r/report.md" html="$work/r/report.html"
    for s in 'Verdict' 'Inputs' 'Similarity table' 'Curves: Figs. 3 and 4' 'Bridge model accuracy' 'Slump test' 'Caveats'; do
      grep -q "^## $s\$" "$md" || fail "report.md lacks section $s"
      grep -q "<h2>$s</h2>" "$html" || fail "report.html lacks section $s"
    done
    # Every figure the Markdown links exists; the HTML embeds as many, and fetches nothing.
    links=$(grep -o '](figures/[^)]*\.png)' "$md" | sed 's/^](//; s/)$//')
    [ -n "$links" ] || fail "no figures linked"
    for f in $links; do [ -s "$work/r/$f" ] || fail "linked figure $f missing"; done
    [ "$(grep -o 'src="data:image/png;base64,' "$html" | wc -l)" -eq "$(echo "$links" | wc -l)" ] || fail "HTML embeds a different number of figures"
    ! grep -Eq 'src="(http|figures/)' "$html" || fail "HTML refers to outside files"
    # The numbers are the library's: Table 1 and the slump table as the other commands print them.
    # The report shows Table 1 transposed (one column per radius) to 4 significant digits; each
    # quantity's row must be demscale table's full-precision CSV column, rounded by printf.
    "$demscale" table --format csv 2>/dev/null | grep -v '^#' >"$work/table.csv" || fail "table failed"
    # The report heads its rows in words (the CSV keeps the identifiers).
    declare -A heading=([mass_g]='particle mass (g)' [v_mm3]='bridge liquid V (mm³)' [vhat]='V̂ = V/R³' [a]='Mikami A'
      [c]='Mikami C' [fc_contact_n]='bridge force at contact, physical γ (N)' [hhat_rupture]='rupture gap ĥ_c (gap/R)'
      [sigma_contact_pa_k1]='bridge stress F/(π R²) at k = 1 (Pa)' [sigma_contact_pa_k3]='bridge stress F/(π R²) at k = 3 (Pa)')
    for col in "${!heading[@]}"; do
      want=$(awk -F, -v c="$col" 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == c) k = i; next} {printf " %.4g |", $k}' "$work/table.csv")
      tr -s ' ' <"$md" | grep -qF "| ${heading[$col]} |$want" ||
        fail "Table 1's $col in the report differs from demscale table (want | ${heading[$col]} |$want)"
    done
    grep -q 'fhat_\|_pct\b\|smallest_tolerances' "$md" && fail "the report shows CSV identifiers as headings"
    "$demscale" sweep --exponents 1,3 --sf 1.4 --seeds 3 --scene "$src/data/scenes/small_wet.toml" --cache "$work/cache" \
      --out "$work/s" --no-png --format markdown >"$work/sweep.md" 2>"$work/sweep.err" || fail "sweep failed"
    grep -q '0 to run' "$work/sweep.err" || fail "sweep did not reuse the report's runs"
    grep -q 'not_told_apart' "$work/sweep.md" || fail "sweep's best k carries no uncertainty"
    # The verdict rows (estimates with their intervals, up to the verdict; the report may set the
    # columns after it in a second table), spacing aside, are sweep's.
    grep -E '^\| +1\.4 \|.*baseline-corrected.*\] (FAIL|PASS|INCONCLUSIVE) \|' "$work/sweep.md" | tr -s ' ' | sed -E 's/^(([^|]*\|){8}).*/\1/' >"$work/rows"
    [ "$(wc -l <"$work/rows")" -eq 2 ] || fail "sweep verdict rows (k = 1 and 3): $(cat "$work/rows")"
    tr -s ' ' <"$md" | grep -qFf "$work/rows" || fail "verdict rows in the report differ from demscale sweep"
    [ "$(tr -s ' ' <"$md" | grep -cFf "$work/rows")" -ge 2 ] || fail "a verdict row is missing from the report" ;;
  export_liggghts_deck)
    # The deck carries the scene's own values; steps by hand: lift 65 mm / 0.3 m/s / 2e-5 s = 10833,
    # spread 0.2 s / 2e-5 s = 10000. The data file holds the settled fill: same count, same spheres.
    { printf '[contact]\nrolling_damping = 0.3\n'; cat "$src/data/scenes/small_wet.toml"; } >"$work/damped.toml"
    expect 0 "bridges as LIGGGHTS' cohesion easo/capillary/viscous" -- "$demscale" export liggghts --scene "$work/damped.toml" --out "$work/deck"
    for line in 'fix m1 all property/global youngsModulus peratomtype 5e\+06' 'poissonsRatio peratomtype 0.3$' \
        'coefficientRestitution peratomtypepair 1 0.5$' 'coefficientFriction peratomtypepair 1 0.5$' \
        'coefficientRollingFriction peratomtypepair 1 0.1$' 'rollingStiffness scalar 2.25$' \
        'coefficientRollingViscousDamping peratomtypepair 1 0.3$' \
        '^pair_style gran model hertz tangential history cohesion easo/capillary/viscous rolling_friction epsd3$' \
        '^fix walls all wall/gran model hertz tangential history rolling_friction epsd3 mesh' \
        'surfaceLiquidContentInitial scalar 0.099$' 'surfaceTension scalar 0.074$' 'contactAngle peratomtype 0$' \
        'fluidViscosity scalar 0$' 'minSeparationDistanceRatio scalar 0.02$' '^# rupture: Lian' \
        '^timestep 2e-05$' '^neighbor 0.0006 bin$' 'gravity 9.81 vector 0.0 0.0 -1.0$' \
        '^fix lift all move/mesh mesh cone linear 0.0 0.0 0.3$' '^run 10833$' '^run 10000$'; do
      grep -Eq -- "$line" "$work/deck/in.slump" || { cat "$work/deck/in.slump" >&2; fail "deck lacks /$line/"; }
    done
    # The liquid each sphere carries: the bridge's V over the share a bridge takes, 1 - sqrt(3/4);
    # with Eq. 5 (V = w m / rho_l x that share) it is w rho_s / rho_l = 0.045 x 2200 / 1000 = 0.099
    # of the sphere's volume, by hand. A coarse-grained export carries gamma S_f^k: 0.074 x 1.4.
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$work/damped.toml" --sf 1.4 --exponent 1 --out "$work/coarse"
    grep -Eq 'surfaceTension scalar 0.1036$' "$work/coarse/in.slump" || fail "coarse deck's surface tension"
    grep -Eq 'surfaceLiquidContentInitial scalar 0.099$' "$work/coarse/in.slump" || fail "coarse deck's liquid"
    n=$(($(wc -l <"$work/deck/settled.csv") - 2))
    [ "$n" -gt 300 ] || fail "settled fill of $n spheres"
    grep -q "^$n atoms$" "$work/deck/particles.data" || fail "data file does not hold the $n settled spheres"
    grep -q "written by demscale export liggghts: small-wet-test, $n spheres" "$work/deck/in.slump" || fail "deck header count"
    # Atom lines: id type diameter density x y z; diameter 2 R = 4.4 mm, density 2200 kg/m^3 (the scene's).
    [ "$(awk 'NF == 7 && $3 == 0.0044000000000000003 && $4 == 2200' "$work/deck/particles.data" | wc -l)" -eq "$n" ] \
      || fail "atoms with another diameter or density"
    [ "$(grep -c 'endfacet' "$work/deck/cone.stl")" -gt 50 ] || fail "cone mesh has too few facets"
    # A box fitted to the scene: narrower than the old +-0.25 m, holding every sphere, above the lifted cone.
    box=$(awk '/xlo xhi/ {print $2}' "$work/deck/particles.data")
    awk -v b="$box" 'BEGIN {exit !(b > 0.05 && b < 0.2)}' || fail "box half-width $box m"
    awk -v b="$box" '/^Velocities/ {done = 1} !done && NF == 7 && ($5 > b || $5 < -b || $6 > b || $6 < -b) {bad++} END {exit bad > 0}' "$work/deck/particles.data" \
      || fail "spheres outside the box"
    grep -q '^-0.001 0.1342.* zlo zhi$' "$work/deck/particles.data" || fail "box height: 1.1 x (57 + 65) mm"
    # Without rolling resistance the deck asks for no rolling law and sets no rolling coefficient.
    { printf '[contact]\nrolling_resistance = false\n'; cat "$src/data/scenes/small_wet.toml"; } >"$work/free.toml"
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$work/free.toml" --out "$work/free"
    ! grep -q 'rolling_friction\|Rolling' "$work/free/in.slump" || fail "rolling law in a free-rolling deck"
    # A dry adhesive scene: LIGGGHTS' SJKR with the scene's k_c, its normal force kept out of the
    # Coulomb limit as in demscale (tangential_reduce on), and no wet-scene note.
    { printf '[contact]\ncohesion_energy_density_j_per_m3 = 2e4\n[liquid]\nwet = false\n'; grep -v '^\[liquid\]\|^wet' "$src/data/scenes/small_wet.toml"; } >"$work/sticky.toml"
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$work/sticky.toml" --out "$work/sticky"
    for line in '^pair_style gran model hertz tangential history cohesion sjkr rolling_friction epsd3 tangential_reduce on$' \
        'property/global cohesionEnergyDensity peratomtypepair 1 20000$'; do
      grep -Eq -- "$line" "$work/sticky/in.slump" || { cat "$work/sticky/in.slump" >&2; fail "adhesive deck lacks /$line/"; }
    done
    ! grep -q 'Mikami\|DRY' "$work/sticky/in.slump" || fail "wet-scene note in a dry deck"
    # --stop-at-rest: demscale's rest criterion in the deck, by hand: at most floor(0.01 n) of the n
    # spheres at 0.001 m/s or faster, checked every 0.01 s / 4 / 2e-5 s = 125 steps, five passes.
    expect 0 'wrote' -- "$demscale" export liggghts --scene "$work/damped.toml" --out "$work/rest" --stop-at-rest
    allowed=$((n / 100))
    for line in "^# spread until at rest: at most $allowed of the $n spheres at 0.001 m/s or faster" '^run 125$' \
        "^if \"\\\$\{nf\} <= $allowed\" then" '^if "\$\{still\} >= 5" then "jump SELF rested"$' '^print "demscale: at rest at step \$\{atstep\}"$' \
        '^dump final all custom 1 final.dump id type x y z radius vx vy vz$' '^run 0$'; do
      grep -Eq -- "$line" "$work/rest/in.slump" || { cat "$work/rest/in.slump" >&2; fail "rest deck lacks /$line/"; }
    done
    grep -q '^run 10000$' "$work/rest/in.slump" && fail "the rest deck still runs the whole spread at once"
    grep -q '^fix walls [a-z]* wall/gran model hertz tangential history cohesion sjkr' "$work/sticky/in.slump" || fail "walls without SJKR" ;;
  slump_sigint_then_resume)
    # The small scene with a short settle (the test runs it twice). The interrupt comes once the
    # log says the lift has begun, with the lift and 0.5 s of spreading still ahead (over 1 s of
    # run on a fast machine): a fixed sleep was outrun once the engine got faster.
    sed -e 's/^settle_time_s = .*/settle_time_s = 0.08/' -e 's/^spread_time_s = .*/spread_time_s = 0.5/' \
      "$src/data/scenes/small_wet.toml" >"$work/short.toml"
    args=(slump --scene "$work/short.toml" --format json --no-png)
    "$demscale" "${args[@]}" --out "$work/whole" >"$work/whole.json" 2>/dev/null || fail "uninterrupted run failed"
    "$demscale" "${args[@]}" --out "$work/cut" >"$work/cut.json" 2>"$work/cut.err" &
    pid=$!
    for _ in $(seq 600); do grep -q 'lift from' "$work/cut.err" && break; sleep 0.05; done
    grep -q 'lift from' "$work/cut.err" || { kill $pid; fail "the run never reached the lift"; }
    kill -INT $pid
    wait $pid; rc=$?
    [ "$rc" -eq 130 ] || { cat "$work/cut.err" >&2; fail "interrupted run exited $rc, expected 130"; }
    grep -q -- '--resume .*slump.ckpt' "$work/cut.err" || { cat "$work/cut.err" >&2; fail "no resume hint"; }
    [ -s "$work/cut/slump.ckpt" ] || fail "no checkpoint written"
    [ ! -e "$work/cut/slump_profile.csv" ] || fail "an interrupted run wrote results"
    expect 0 '"final_height_mm"' -- "$demscale" "${args[@]}" --out "$work/cut" --resume "$work/cut/slump.ckpt"
    # Same physics bit for bit: every measurement but the timing lines.
    grep -E '^ +"' "$work/whole.json" | grep -vE '"(wall_s|particle_steps_per_s|threads)"' >"$work/a"
    grep -E '^ +"' "$work/out" | grep -vE '"(wall_s|particle_steps_per_s|threads)"' >"$work/b"
    [ "$(wc -l <"$work/a")" -ge 15 ] || fail "too few measurements compared"
    diff "$work/a" "$work/b" >&2 || fail "resumed run differs from the uninterrupted one"
    [ ! -e "$work/cut/slump.ckpt" ] || fail "checkpoint left behind after a finished resume" ;;
  *) fail "unknown case" ;;
esac
echo "ok [$case_name]"
