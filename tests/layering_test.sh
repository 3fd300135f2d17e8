#!/usr/bin/env bash
# Layers of lib/, lowest first: a file may include its own folder and the folders below it, never
# one above (the README's map of lib/). Prints every include that runs up and fails if there is one.
# Usage: layering_test.sh SOURCE_DIR
set -u
lib=$1/lib
layers=(core bridge similarity dem io stats slump report)
rank() { local i; for i in "${!layers[@]}"; do [ "${layers[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
bad=0 checked=0
for dir in "${layers[@]}"; do
  own=$(rank "$dir")
  while IFS= read -r line; do
    file=${line%%:*} target=${line#*#include \"} target=${target%%/*}
    theirs=$(rank "$target")
    checked=$((checked + 1))
    if [ "$theirs" -lt 0 ]; then echo "unknown layer: $line"; bad=1
    elif [ "$theirs" -gt "$own" ]; then echo "up the layers ($dir includes $target): $line"; bad=1; fi
  done < <(grep -rHn '^#include "[a-z_]*/' "$lib/$dir" | sed "s|^$lib/||")
done
# Every folder of lib/ has a layer.
for d in "$lib"/*/; do
  name=$(basename "$d")
  [ "$(rank "$name")" -ge 0 ] || { echo "lib/$name has no layer in ${BASH_SOURCE[0]}"; bad=1; }
done
echo "$checked includes checked"
exit $bad
