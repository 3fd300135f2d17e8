# Sourced by the tests that run LIGGGHTS: `need_liggghts` returns 0 when `liggghts` and `mpirun` are
# there, installing them from Debian's archive first where they are missing and we are root;
# otherwise it returns 1 and sets why_no_liggghts.
need_liggghts() {
  command -v liggghts >/dev/null && command -v mpirun >/dev/null && return 0
  if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null; then
    why_no_liggghts="LIGGGHTS or mpirun missing, and not root to install them (apt-get install liggghts openmpi-bin)"
    return 1
  fi
  if ! DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -q liggghts openmpi-bin >/tmp/demscale-liggghts-apt.log 2>&1; then
    why_no_liggghts="apt-get install liggghts openmpi-bin failed: $(tail -2 /tmp/demscale-liggghts-apt.log | tr '\n' ' ')"
    return 1
  fi
}
