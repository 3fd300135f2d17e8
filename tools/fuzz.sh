#!/usr/bin/env bash
# Fuzzes the scene parser and the bridge functions with libFuzzer under ASan + UBSan, SECONDS per
# target (default 60). Installs Debian's clang and libomp-dev if missing and builds in build-fuzz/.
# New interesting inputs stay in a temporary folder; an input that crashes is written to
# tests/fuzz/crashes/ (commit it to tests/fuzz/corpus/<target>/ once fixed: CTest replays it).
# Usage: tools/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}
missing=()
command -v clang++ >/dev/null || missing+=(clang)
[ -e /usr/lib/llvm-14/lib/libomp.so ] || missing+=(libomp-dev)
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""; [ "$(id -u)" -eq 0 ] || sudo_cmd=sudo
  $sudo_cmd apt-get install -y -qq "${missing[@]}" >/dev/null
fi
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDEMSCALE_FUZZ=ON \
  -DDEMSCALE_SANITIZE=address,undefined >/dev/null
cmake --build build-fuzz -j2 --target fuzz_scene fuzz_bridge >/dev/null
mkdir -p tests/fuzz/crashes
status=0
for target in scene bridge; do
  found=$(mktemp -d)
  echo "== fuzz_$target: $secs s"
  if ! build-fuzz/fuzz_$target -max_total_time="$secs" -timeout=10 -print_final_stats=1 \
       -artifact_prefix="tests/fuzz/crashes/$target-" "$found" "tests/fuzz/corpus/$target" >"$found.log" 2>&1; then
    status=1
    grep -E 'ERROR|SUMMARY|Test unit written|what\(\)' "$found.log" | head -20
  fi
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)|^#[0-9]+ *DONE' "$found.log" | tr '\n' ' '; echo
  rm -rf "$found" "$found.log"
done
exit $status
