#!/usr/bin/env bash
# tools/plot --overlay draws the cases of a sweep into one non-empty PNG (skipped, exit 77,
# when matplotlib is missing).
set -u
sweep=$1; plot=$2
/usr/bin/python3 -c "import matplotlib" 2>/dev/null || { echo "skipped: python3-matplotlib is not installed"; exit 77; }
rm -f "$sweep/overlay.png"
"$plot" --overlay "$sweep" "$sweep"/alpha=* || exit 1
if [ -s "$sweep/overlay.png" ] && [ "$(head -c 4 "$sweep/overlay.png" | tail -c 3)" = "PNG" ]; then
  echo "1 passed, 0 failed"
else
  echo "0 passed, 1 failed"; exit 1
fi
