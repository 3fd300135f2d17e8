# Shared by the bench scripts (sourced): how busy the cores are, a median, a JSON field.
# Cores busy with any work over 2 s (from /proc/stat: non-idle jiffies over all, times the cores).
busy() {
  local first second
  first=$(head -1 /proc/stat); sleep 2; second=$(head -1 /proc/stat)
  printf '%s\n%s\n' "$first" "$second" | awk -v n="$(nproc)" '
    {t = 0; for (i = 2; i <= NF; i++) t += $i; total[NR] = t; idle[NR] = $5 + $6}
    END {printf "%.2f", n * (1 - (idle[2] - idle[1]) / (total[2] - total[1]))}'
}
# The median of whitespace-separated numbers ("none" for none).
median() { echo "$1" | tr ' ' '\n' | grep . | sort -g | awk '{v[NR] = $1} END {if (NR == 0) print "none"; else printf "%.2f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
# A number field of demscale's --format json output: json FILE NAME.
json() { sed -n "s/^ *\"$2\": \\([^,]*\\),\\?$/\\1/p" "$1" | head -1; }
# ns a cache line takes to cross between two cores now (demscale bench --core-link; "-" without
# two threads): on a virtual machine it changes from minute to minute, and threads' speed with it.
link() { "${DEMSCALE:-build/demscale}" bench --core-link --format csv 2>/dev/null | grep -v '^#' | awk -F, 'NR == 2 {printf "%.2f", $2; found = 1} END {if (!found) printf "-"}'; }
