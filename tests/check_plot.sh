#!/usr/bin/env bash
# tools/plot makes non-empty PNGs of every figure from a run's results (skipped, exit 77,
# when matplotlib is missing).
set -u
run=$1; plot=$2
/usr/bin/python3 -c "import matplotlib" 2>/dev/null || { echo "skipped: python3-matplotlib is not installed"; exit 77; }
rm -rf "$run/plots"
"$plot" "$run" || exit 1
n=0; bad=0
for f in profiles history_B deformed force; do
  n=$((n + 1))
  if [ -s "$run/plots/$f.png" ] && [ "$(head -c 4 "$run/plots/$f.png" | tail -c 3)" = "PNG" ]; then :; else echo "FAIL $f.png"; bad=$((bad + 1)); fi
done
echo "$((n - bad)) passed, $bad failed"
[ "$bad" -eq 0 ]
