#!/usr/bin/env bash
# Installs demscale's build and run dependencies from Debian's archive; with --tests, also what the
# test suite uses beyond them: Slurm's daemons and client with munge, for the test that runs a
# study through a real single-node Slurm (the test starts and stops the daemons itself).
# Idempotent and silent when everything is present; works as root or through sudo.
set -euo pipefail

packages=(
  cmake g++ make            # build
  libgsl-dev libeigen3-dev  # numerics (GSL: ODE + root finding; Eigen: basis solve)
  catch2                    # tests (v2 on Debian 12)
  gnuplot-nox               # plots (pngcairo terminal)
  fonts-dejavu-core         # a font for pngcairo on a bare machine
  libtomlplusplus-dev       # input files (TOML)
  nlohmann-json3-dev        # --format json
  libcli11-dev              # command-line subcommands
)
if [ "${1:-}" = --tests ]; then
  packages+=(slurmctld slurmd slurm-client munge)  # the Slurm backend's test (tests/cluster/slurm_test.sh)
elif [ $# -gt 0 ]; then
  echo "usage: $0 [--tests]" >&2; exit 2
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then as_root=(); else as_root=(sudo); fi
echo "install-deps: installing ${missing[*]}" >&2
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
