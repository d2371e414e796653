#!/usr/bin/env bash
# The frames a behaviour-preserving change (a move, a rename, a split) must leave bit for bit as
# they were: every preset, each caustics model, the god rays at each resolution, object caustics
# on and off, local lights, the tile model's settings and a moving sequence, as EXR.
#
#   tests/identical_renders.sh render BUILD/sample_app/ocean_sample DIR   # before, then after
#   tests/identical_renders.sh compare DIR_BEFORE DIR_AFTER              # exit 1 on any change
#
# compare reads both through OpenImageIO (oiiotool, Debian's openimageio-tools) and prints each
# frame's largest absolute difference; a change passes only where every frame's is 0.
set -euo pipefail

usage() {
  echo "usage: $0 render OCEAN_SAMPLE DIR | compare DIR_A DIR_B" >&2
  exit 2
}

render_all() {
  local sample=$1 dir=$2
  mkdir -p "$dir"
  local size=(--width 320 --height 180)
  local n=0
  run() {
    local name=$1
    shift
    n=$((n + 1))
    echo "[$n] $name" >&2
    # IDENTICAL_RENDERS_FLAGS: flags every render of this side adds (e.g. a new feature's off
    # switch, when the side before the change did not have the feature).
    # shellcheck disable=SC2086
    "$sample" render "${size[@]}" --out "$dir/$name.exr" "$@" ${IDENTICAL_RENDERS_FLAGS:-} >/dev/null
  }
  for preset in shallow seabed sunward above waterline torch pool wake harbour; do
    run "preset_$preset" --preset "$preset"
  done
  for model in ray-deviation wavefront-area-ratio; do
    run "seabed_$model" --preset seabed --caustics-model "$model"
    run "above_$model" --preset above --caustics-model "$model"
  done
  for resolution in full half; do
    run "seabed_god_rays_$resolution" --preset seabed --god-rays-resolution "$resolution"
  done
  run seabed_no_object_caustics --preset seabed --no-object-caustics
  run seabed_no_god_rays --preset seabed --no-god-rays
  run seabed_lookup_full --preset seabed --caustics-lookup full
  run seabed_tile_256_8_layers --preset seabed --tile-resolution 256 --tile-depth-layers 8
  run seabed_triplanar --preset seabed --caustics-model ray-deviation --triplanar-walls
  run seabed_lights --preset seabed --light point:0,-3,0:2 --light spot:2,-2,1:0,-1,0:3:50
  run torch_no_object_caustics --preset torch --no-object-caustics
  run seabed_moving --preset seabed --frames 3 --camera-velocity 2,0,1
  echo "$n renders in $dir" >&2
}

compare_all() {
  local a=$1 b=$2 failed=0 count=0
  if ! command -v oiiotool > /dev/null; then
    echo "compare needs oiiotool (Debian: apt-get install openimageio-tools)" >&2
    exit 2
  fi
  for fa in "$a"/*.exr; do
    local name
    name=$(basename "$fa")
    count=$((count + 1))
    if [[ ! -f "$b/$name" ]]; then
      echo "$name: missing in $b"
      failed=1
      continue
    fi
    # --diff --fail 0: any pixel that differs at all fails; its report names the largest error.
    if ! out=$(oiiotool "$fa" "$b/$name" --diff --fail 0 --failpercent 0 2>&1); then
      echo "$name: differs"
      echo "$out" | grep -i "max error\|mean error" | sed 's/^/  /'
      failed=1
    else
      echo "$name: identical"
    fi
  done
  [[ $count -gt 0 ]] || { echo "no EXR in $a"; exit 2; }
  if [[ $(ls "$b"/*.exr | wc -l) -ne $count ]]; then
    echo "$b holds a different set of frames"
    failed=1
  fi
  return $failed
}

[[ $# -eq 3 ]] || usage
case $1 in
  render) render_all "$2" "$3" ;;
  compare) compare_all "$2" "$3" ;;
  *) usage ;;
esac
