#!/usr/bin/env bash
# Two builds of the bench timed alternately (ABBA) on the lent GPU machine, e.g. two label
# encodings (docs/benchmark.md, "On a GPU": RGBA32F labels against R32F ids). Here, first: the
# carry of bench/gpu/prepare.sh in .gpu/, then one bundle per tree, named by A and B:
#   esbuild bench/run.ts --bundle --platform=node --format=esm --outfile=/tmp/bench_A.mjs \
#     --external:gl --external:@playwright/test --external:vite --external:../playwright.config \
#     --banner:js="import { createRequire as __cr } from 'module'; const require = __cr(import.meta.url);"
#   xz -6 -c /tmp/bench_A.mjs > .gpu/bench_A.mjs.xz   (the same for B, from the other tree)
# There (device run, carry .gpu): A=main B=labels bash bench/gpu/ab.sh
set -u
R=$(pwd); OUT=${OUT:-/tmp/out}; mkdir -p "$OUT"; A=${A:-main}; B=${B:-labels}
BENCH_S=20 bash bench/gpu/device.sh --sizes 256 --sites 200 --rounds 1 --iterations 2 > "$OUT/setup.txt" 2>&1  # unpack, Xvfb, probe
for t in "$A" "$B"; do python3 -c "import lzma,sys; sys.stdout.buffer.write(lzma.open(sys.argv[1]).read())" "$R/.gpu/bench_$t.mjs.xz" > "/opt/gpu/gpulibs/bench/bench_$t.mjs"; done
NV=$(dirname "$(find / -xdev -name 'libGLX_nvidia.so.0' 2>/dev/null | head -1)")
export LD_LIBRARY_PATH=/opt/gpu/gpulibs/lib:$NV __GLX_VENDOR_LIBRARY_NAME=nvidia DISPLAY=:99
cd /opt/gpu/gpulibs/bench
for b in "$A" "$B" "$B" "$A"; do
  echo "== $b $(date +%T)"
  timeout "${RUN_S:-110}" /opt/gpu/node "bench_$b.mjs" --only node --no-max-size --sizes 4096,8192 --sites 100000,1000000 --budget-s 60 2>&1 | grep -E "^node \||rror"
done 2>&1 | tee "$OUT/ab.txt"
