#!/usr/bin/env bash
# The plugin's GPU timings at 1920x1080 on a machine that has a GL driver and nothing else
# (e.g. a lent NVIDIA machine reachable only by running a command in a copy of this tree), each
# beside the cost model's ESTIMATE for that GPU class (docs/gpu_cost.md): the measurement that
# checks the model.
#
#   sample_app/bench/standalone/gpu_bench.sh prepare   # here: build postfx_bench, gather what
#                                                      # it needs into .gpu-bench/ (git-ignored),
#                                                      # with the shaders' arithmetic as llvmpipe
#                                                      # compiles them (a GPU driver prints none)
#   sample_app/bench/standalone/gpu_bench.sh run OUT   # there, with .gpu-bench carried: unpack
#                                                      # the GL loader, run, write OUT/bench.json
#
# postfx_bench links libstdc++ statically; libepoxy comes along, and the GL/EGL loader
# (glvnd) comes as Debian packages unpacked there, which find the vendor's driver.
set -euo pipefail
cd "$(dirname "$0")/../../.."
dir=.gpu-bench
case "${1:-}" in
  prepare)
    grep -qx "/$dir/" .git/info/exclude 2> /dev/null || echo "/$dir/" >> .git/info/exclude
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
    cmake --build build -j 2 --target postfx_bench
    rm -rf "$dir" && mkdir -p "$dir/lib" "$dir/deb" /tmp/gpu-bench-apt/partial
    cp build/sample_app/postfx_bench "$dir/"
    # Every configuration's programs, compiled by Mesa here: their arithmetic for the estimate.
    build/sample_app/postfx_bench --width 320 --height 180 --frames 1 \
      --write-alu "$dir/alu.json" > /dev/null
    cp -L "$(ldconfig -p | awk '/libepoxy.so.0 / {print $NF; exit}')" "$dir/lib/libepoxy.so.0"
    apt="-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/gpu-bench-apt"
    apt-get $apt update -qq
    (cd "$dir/deb" && apt-get $apt download libegl1 libglvnd0 libopengl0 libgl1 libglx0 > /dev/null)
    du -sh "$dir"
    echo "gpu_bench: ready; carry '$dir' and run: bash sample_app/bench/standalone/gpu_bench.sh run \$OUT"
    ;;
  run)
    out=${2:?"usage: gpu_bench.sh run OUT"}
    for f in "$dir"/deb/*.deb; do dpkg -x "$f" /; done
    ldconfig
    if [ -d /usr/local/nvidia/share/glvnd/egl_vendor.d ]; then
      export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
    fi
    export LD_LIBRARY_PATH="$PWD/$dir/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > "$out/gpu.txt" 2>&1 || true
    "$dir/postfx_bench" --width 1920 --height 1080 --frames 64 --work --gpu all \
      --alu "$dir/alu.json" --json "$out/bench.json" 2>&1 | tee "$out/bench.txt"
    ;;
  *)
    sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
    ;;
esac
