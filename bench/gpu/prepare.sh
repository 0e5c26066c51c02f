#!/usr/bin/env bash
# Packs what `npm run bench`'s Node half needs on a bare GPU machine that has an NVIDIA driver
# (GLX libraries) but neither Node, Xvfb nor Mesa: writes .gpu/ (git-ignored), under 60 MiB so
# that the repository and it travel together (docs/benchmark.md, "On a GPU"). Run on Debian 12
# with xvfb, libgl1-mesa-dri and the project's node_modules installed; then on the GPU machine,
# in the repository root: `bash bench/gpu/device.sh --sizes 4096,8192 --sites 100000,1000000`
# (the bench) or `bash bench/gpu/device.sh --check` (the correctness check, bench/gpuCheck.ts).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${GPU_CARRY_DIR:-.gpu}; work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir -p "$out" "$work/gpulibs/lib" "$work/gpulibs/bin" "$work/gpulibs/dri" "$work/gpulibs/bench/node_modules/gl/build/Release" "$work/stubs"
lib=/usr/lib/x86_64-linux-gnu; gl=node_modules/gl

# The bench and the correctness check (bench/gpuCheck.ts), one file each; `gl` (native) stays a
# package beside them with its run-time dependencies.
for entry in run.ts:bench.mjs gpuCheck.ts:gpucheck.mjs; do
  node_modules/tsx/node_modules/esbuild/bin/esbuild "bench/${entry%%:*}" --bundle --platform=node --format=esm \
    --outfile="$work/gpulibs/bench/${entry##*:}" --external:gl --external:@playwright/test --external:vite \
    --external:../playwright.config --log-level=warning \
    --banner:js="import { createRequire as __cr } from 'module'; const require = __cr(import.meta.url);"
done
for m in bindings file-uri-to-path bit-twiddle glsl-tokenizer through2 readable-stream inherits string_decoder safe-buffer util-deprecate xtend; do
  cp -r "node_modules/$m" "$work/gpulibs/bench/node_modules/"
done
cp "$gl/package.json" "$gl/index.js" "$work/gpulibs/bench/node_modules/gl/"
mkdir -p "$work/gpulibs/bench/node_modules/gl/src" && cp -r "$gl/src/javascript" "$work/gpulibs/bench/node_modules/gl/src/"
cp "$gl"/build/Release/{webgl.node,libEGL.so,libGLESv2.so} "$work/gpulibs/bench/node_modules/gl/build/Release/"

# Xvfb with its GLX provider (Mesa's swrast: the server needs one to offer GLX at all; the
# client then renders through NVIDIA's libGLX_nvidia, chosen by __GLX_VENDOR_LIBRARY_NAME).
targets="/usr/bin/Xvfb /usr/bin/xkbcomp $lib/dri/swrast_dri.so $lib/libGLX.so.0 $lib/libGL.so.1 $lib/libGLdispatch.so.0 $lib/libEGL.so.1 $gl/build/Release/webgl.node $gl/build/Release/libGLESv2.so"
for t in $targets; do ldd "$t" | awk '/=>/{print $3}'; done | sort -u |
  grep -v -E '/(libc|libm|libdl|libpthread|librt|ld-linux-x86-64|libresolv|libstdc\+\+|libgcc_s|libLLVM-15|libz3|libxml2|libicu[a-z]*)\.so' |
  while read -r so; do cp -L "$so" "$work/gpulibs/lib/"; done
cp -L $lib/libGLX.so.0 $lib/libGL.so.1 $lib/libGLdispatch.so.0 $lib/libEGL.so.1 $lib/libOpenGL.so.0 "$work/gpulibs/lib/"
cp /usr/bin/Xvfb /usr/bin/xkbcomp "$work/gpulibs/bin/"
cp -L $lib/dri/swrast_dri.so "$work/gpulibs/dri/"
cp -r /usr/share/X11/xkb "$work/gpulibs/xkb"

# libLLVM links z3 (its static analyser) and libxml2 (Windows manifests), neither used by a
# rasterizer: empty stand-ins with the same symbols and versions keep 40 MB out of the carry.
nm -D --undefined-only $lib/libLLVM-15.so.1 | awk '/Z3_/{sub(/@.*/, "", $2); print "void " $2 "(void) {}"}' | sort -u > "$work/stubs/z3.c"
gcc -shared -fPIC -Wl,-soname,libz3.so.4 -o "$work/gpulibs/lib/libz3.so.4" "$work/stubs/z3.c"
objdump -T $lib/libLLVM-15.so.1 | awk '/\*UND\*/ && /LIBXML2/ {gsub(/[()]/, "", $(NF-1)); print $(NF-1), $NF}' | sort -u > "$work/stubs/xml.txt"
awk '{ print ($2 == "xmlFree" ? "void *xmlFree;" : "void " $2 "(void) {}") }' "$work/stubs/xml.txt" > "$work/stubs/xml2.c"
awk '{v[$1] = v[$1] " " $2 ";"} END {for (k in v) print k " {" v[k] " };"}' "$work/stubs/xml.txt" > "$work/stubs/xml2.map"
gcc -shared -fPIC -Wl,-soname,libxml2.so.2 -Wl,--version-script="$work/stubs/xml2.map" -o "$work/gpulibs/lib/libxml2.so.2" "$work/stubs/xml2.c"

# The carry and the repository must stay under the device's 64 MiB together: one xz block each
# (-T1: threads split a stream into blocks, ~1 MB more), x86 branch filters on the two binaries
# (~1.4 MB less; Python's lzma, device.sh's fallback, reads them), and Node without its symbol
# table (--strip-all keeps .dynsym, which gl's native module binds to; 10 MB less unpacked).
bin="--x86 --lzma2=preset=6 -T1"
tar -C "$work" -cf - gpulibs | xz -6 -T1 > "$out/gpulibs.tar.xz"
xz $bin -c $lib/libLLVM-15.so.1 > "$out/llvm.xz"
cp "$(command -v node)" "$work/node" && strip --strip-all "$work/node" && xz $bin -c "$work/node" > "$out/node.xz"
du -ch "$out"/*.xz | tail -1
