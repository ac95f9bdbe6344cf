#!/usr/bin/env bash
# "Run the main job" (README command 1):
#   install missing Debian packages, build Release, run every registered scenario with its
#   defaults, and write out/: NAME.csv, NAME.json, PNG plots, and out/REPORT.md (paper claim |
#   the paper's own value | ours | paper verdict | our criterion | criterion holds?).
# Usage: tools/run-main.sh [OUT_DIR]   (default: out)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-"$root/out"}
build="$root/build"
jobs=$(nproc 2>/dev/null || echo 2)

bash "$root/tools/setup-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" --target adcs-sim -j "$jobs"
sim="$build/src/adcs-sim"

mkdir -p "$out"
status=0
while IFS= read -r name; do
  [ -n "$name" ] || continue
  echo "== $name"
  start=$(date +%s)
  if ! "$sim" run "$name" --out "$out" | tail -n 1; then
    echo "run-main: scenario $name failed" >&2
    status=1
  fi
  echo "   ($(( $(date +%s) - start )) s)"
done < <("$sim" list)

# Your own vehicle (issue 18): the example vehicle files, and a dispersed campaign of the 12U
# cubesat (docs/CAMPAIGNS.md) for the report's Campaigns section.
for f in "$root"/examples/vehicles/*.toml; do
  echo "== $f"
  if ! "$sim" run "$f" --out "$out" | tail -n 1; then
    echo "run-main: vehicle file $f failed" >&2
    status=1
  fi
done
rm -f "$out"/cubesat-12u-montecarlo*
echo "== campaign: cubesat-12u.toml, 200 dispersed runs"
if ! "$sim" montecarlo "$root/examples/vehicles/cubesat-12u.toml" --runs 200 --seed0 1 --jobs "$jobs" \
    --disperse 'spacecraft.J_kgm2=inertia(0.1, 1)' --disperse 'wheels.axes_B=axes(0.5)' \
    --disperse 'sensors.gyro.arw_rad_sqrt_s=rel_uniform(0.5)' \
    --disperse 'sensors.star_tracker.dropout_probability=uniform(0, 0.2)' \
    --series att_err_deg --out "$out" | tail -n 1 | cut -c1-300; then
  echo "run-main: the cubesat campaign failed" >&2
  status=1
fi

/usr/bin/python3 "$root/tools/plot.py" "$out"
/usr/bin/python3 "$root/tools/report.py" "$out"
echo "run-main: wrote $out/REPORT.md"
exit $status
