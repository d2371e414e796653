#!/usr/bin/env bash
# Regenerates every image README.md and docs/ show, from the build tree, with the commands the
# docs name (docs/ocean_sample.md, docs/measurements.md). Run from the repository root after
# building (README's set-up). About 2 minutes on 2 cores; --with-report adds the generated
# measurement tables in docs/report/ (ocean_sample report, ~25 min; run it on a quiet machine,
# nothing else timing: its milliseconds are CPU time).
set -euo pipefail
cd "$(dirname "$0")/.."
sample=./build/sample_app/ocean_sample
[ -x "$sample" ] || { echo "make_images: build first ($sample is missing)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "make_images: docs/hero.png (the default command at 1280x720)"
"$sample" render --out docs/hero.png > /dev/null

echo "make_images: docs/side_by_side.png (seabed preset, 320x180, traced reference)"
size="--preset seabed --width 320 --height 180"
"$sample" render $size --out "$work/plugin.exr" > /dev/null
"$sample" render $size --no-caustics --no-object-caustics --out "$work/base.exr" > /dev/null
"$sample" render $size --caustics-model ray-deviation --tau 0 --no-object-caustics \
  --out "$work/flat.exr" > /dev/null
"$sample" reference $size --out "$work/reference.exr"
"$sample" compare --plugin "$work/plugin.exr" --reference "$work/reference.exr" \
  --base "$work/base.exr" --flat "$work/flat.exr" --out docs/side_by_side.png

echo "make_images: docs/torch.png"
"$sample" render --preset torch --width 640 --height 360 --volume-caustics --out docs/torch.png \
  > /dev/null

echo "make_images: docs/pool.png and docs/pool_side_by_side.png (the pool, local water)"
"$sample" render --preset pool --width 960 --height 540 --out docs/pool.png > /dev/null
size="--preset pool --width 640 --height 360 --no-god-rays"
"$sample" render $size --out "$work/pool_plugin.exr" > /dev/null
"$sample" render $size --no-caustics --no-object-caustics --out "$work/pool_base.exr" > /dev/null
"$sample" render $size --caustics-model ray-deviation --tau 0 --no-object-caustics \
  --flat-local-water --out "$work/pool_flat.exr" > /dev/null
"$sample" reference $size --out "$work/pool_reference.exr"
"$sample" compare --plugin "$work/pool_plugin.exr" --reference "$work/pool_reference.exr" \
  --base "$work/pool_base.exr" --flat "$work/pool_flat.exr" --out docs/pool_side_by_side.png

echo "make_images: docs/harbour.png (the harbour, reflected caustics above the water)"
"$sample" render --preset harbour --width 640 --height 360 --out docs/harbour.png > /dev/null

echo "make_images: docs/loop.gif (40 frames)"
"$sample" render --width 320 --height 180 --frames 40 --fps 20 --out docs/loop.gif | tail -n 1

if [ "${1:-}" = "--with-report" ]; then
  echo "make_images: docs/report/ (ocean_sample report: error against run time, stability)"
  "$sample" report --out "$work/report"
  "$sample" report --only local-water --out "$work/report"
  mkdir -p docs/report
  for f in error_vs_time.md error_vs_time.csv error_vs_time.png temporal_stability.md \
    temporal_stability.csv local_water.md local_water.csv local_water.png; do
    cp "$work/report/$f" "docs/report/$f"
  done
fi
echo "make_images: done"
