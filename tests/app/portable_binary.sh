#!/bin/sh
# A portable build (TACTILE_NATIVE=OFF) must run on any x86-64 processor: AVX and AVX-512
# registers may appear only in the kernel copies chosen at run time (kernels_x86_64_v3 for ymm,
# kernels_x86_64_v4 for ymm, zmm and mask registers). Disassembles the binary and lists every other
# function that uses them.
# Usage: portable_binary.sh BINARY...
set -eu
command -v objdump >/dev/null || { echo "objdump not found (binutils)"; exit 1; }
for bin in "$@"; do objdump -d --no-show-raw-insn -C "$bin"; done | awk '
  /^[0-9a-f]+ <.*>:$/ { fn = $0; next }
  /%zmm|%k[1-7]/ { if (fn !~ /kernels_x86_64_v4/) bad[fn] = 1; next }
  /%ymm/ { if (fn !~ /kernels_x86_64_v[34]/) bad[fn] = 1; next }
  END {
    n = 0
    for (f in bad) { print "wide registers outside the dispatched kernels: " f; n++ }
    if (n > 0) exit 1
    print "ok: AVX/AVX-512 registers only in the run-time dispatched kernels"
  }'
