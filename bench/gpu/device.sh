#!/usr/bin/env bash
# Times the GPU engine (headless-gl under Xvfb, NVIDIA GLX) on the lent device machine; with
# --check first (or GPU_RUN=check), runs the correctness check (bench/gpuCheck.ts) instead, with
# the other arguments, e.g. `bash bench/gpu/device.sh --check --large`: $OUT/gpuCheck.txt and .json.
# Made by bench/gpu/prepare.sh; carried in .gpu/: node.xz (Node 20), llvm.xz (libLLVM-15 for Xvfb's swrast GLX provider),
# gpulibs.tar.xz (Xvfb, xkbcomp, swrast_dri.so, X/GLVND client libs, stub z3/xml2, the bench and check bundles).
set -u
R=$(pwd); OUT=${OUT:-/tmp/out}; mkdir -p "$OUT"; D=/opt/gpu; mkdir -p $D; cd $D
unxz() { if command -v xz >/dev/null; then xz -dc "$1"; else python3 -c "import lzma,sys,shutil; shutil.copyfileobj(lzma.open(sys.argv[1]), sys.stdout.buffer)" "$1"; fi; }
echo "== machine"; nvidia-smi -L; grep PRETTY /etc/os-release; nproc; command -v node && node --version
if [ ! -x $D/node ]; then unxz "$R/.gpu/node.xz" > $D/node; chmod +x $D/node; fi
if [ ! -d $D/gpulibs ]; then unxz "$R/.gpu/gpulibs.tar.xz" | tar -xf - -C $D; unxz "$R/.gpu/llvm.xz" > $D/gpulibs/lib/libLLVM-15.so.1; fi
L=$D/gpulibs/lib
mkdir -p /usr/lib/x86_64-linux-gnu/dri
[ -e /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so ] || cp $D/gpulibs/dri/swrast_dri.so /usr/lib/x86_64-linux-gnu/dri/
[ -e /usr/bin/xkbcomp ] || cp $D/gpulibs/bin/xkbcomp /usr/bin/
[ -d /usr/share/X11/xkb ] || { mkdir -p /usr/share/X11; cp -r $D/gpulibs/xkb /usr/share/X11/xkb; }
NVGLX=$(find / -xdev -name 'libGLX_nvidia.so.0' 2>/dev/null | head -1); [ -z "$NVGLX" ] && NVGLX=$(find / -name 'libGLX_nvidia.so.0' 2>/dev/null | head -1)
echo "== NVIDIA GLX: ${NVGLX:-none}"
NV=""; [ -n "$NVGLX" ] && NV=$(dirname "$NVGLX")
export LD_LIBRARY_PATH=$L${NV:+:$NV}
[ -n "$NV" ] && export __GLX_VENDOR_LIBRARY_NAME=nvidia
XD=${XD:-99}
$D/gpulibs/bin/Xvfb :$XD -screen 0 1280x1024x24 -nolisten tcp +extension GLX > $OUT/xvfb.log 2>&1 &
sleep 3; export DISPLAY=:$XD
cd $D/gpulibs/bench
cat > probe.mjs <<'P'
import createGL from 'gl';
const gl = createGL(1, 1, { createWebGL2Context: true });
if (!gl) { console.log('null context'); process.exit(1); }
const dbg = gl.getExtension('WEBGL_debug_renderer_info');
console.log('renderer', gl.getParameter(gl.RENDERER), dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : '-', 'maxTex', gl.getParameter(gl.MAX_TEXTURE_SIZE), 'floatblend', !!gl.getExtension('EXT_float_blend'), 'cbf', !!gl.getExtension('EXT_color_buffer_float'));
const maps = (await import('node:fs')).readFileSync('/proc/self/maps','utf8').split('\n').filter(l=>/dri|nvidia|GLX/.test(l)).map(l=>l.split(/\s+/).pop());
console.log([...new Set(maps)].join(' '));
P
echo "== probe"; timeout 60 $D/node probe.mjs 2>&1 | tail -4
RUN=${GPU_RUN:-bench}; [ "${1:-}" = "--check" ] && { RUN=check; shift; }
if [ "$RUN" = check ]; then
  # The full table and the JSON come back as files; the reply shows the summary and any failures.
  echo "== check $*"
  timeout ${CHECK_S:-300} $D/node gpucheck.mjs --json $OUT/gpuCheck.json --mesh "$R/public/meshes/egg-chamber.ply" "$@" > $OUT/gpuCheck.txt 2>&1
  echo "== check exit $?"; head -9 $OUT/gpuCheck.txt; grep -E "figures within|^FAILED|Error" $OUT/gpuCheck.txt
else
  echo "== bench $*"
  timeout ${BENCH_S:-400} $D/node bench.mjs --only node --no-max-size "$@" 2>&1 | tee $OUT/bench.txt | tail -40
  cp bench/out/bench.json $OUT/ 2>/dev/null
fi
tail -5 $OUT/xvfb.log
