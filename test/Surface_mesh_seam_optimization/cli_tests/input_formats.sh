#!/bin/bash
# The same mesh read from OBJ, OFF, PLY and STL (ASCII and binary; an STL
# repeats every shared point, the reader merges them) is the same mesh: the
# same vertex and face counts, the same distortion-only map.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }
python3 - "$DATA/cat_f1500.obj" <<'PY' || fail "conversion"
import struct, sys
V, F = [], []
for line in open(sys.argv[1]):
    t = line.split()
    if t and t[0] == 'v': V.append(tuple(float(x) for x in t[1:4]))
    if t and t[0] == 'f': F.append(tuple(int(x.split('/')[0]) - 1 for x in t[1:]))
with open('cat.off', 'w') as f:
    f.write('OFF\n%d %d 0\n' % (len(V), len(F)))
    for p in V: f.write('%.17g %.17g %.17g\n' % p)
    for t in F: f.write('3 %d %d %d\n' % t)
with open('cat.ply', 'w') as f:
    f.write('ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n'
            'element face %d\nproperty list uchar int vertex_indices\nend_header\n' % (len(V), len(F)))
    for p in V: f.write('%.17g %.17g %.17g\n' % p)
    for t in F: f.write('3 %d %d %d\n' % t)
with open('cat_ascii.stl', 'w') as f:
    f.write('solid cat\n')
    for t in F:
        f.write(' facet normal 0 0 0\n  outer loop\n')
        for v in t: f.write('   vertex %.17g %.17g %.17g\n' % V[v])
        f.write('  endloop\n endfacet\n')
    f.write('endsolid cat\n')
# binary STL stores floats: its mesh is the float-rounded one (same connectivity)
with open('cat_binary.stl', 'wb') as f:
    f.write(b'binary STL of cat_f1500'.ljust(80, b' ') + struct.pack('<I', len(F)))
    for t in F:
        f.write(struct.pack('<3f', 0, 0, 0) + b''.join(struct.pack('<3f', *V[v]) for v in t) + b'\0\0')
PY
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }
run() { # $1 input, $2 name
  timeout 120 "$BIN" "$1" --keep-seams --quiet -o "$2.obj" --report "$2.json" >out.txt 2>err.txt ||
    fail "$1: exit code $? ($(cat err.txt))"
}
run "$DATA/cat_f1500.obj" obj
for f in cat.off cat.ply cat_ascii.stl cat_binary.stl; do
  run "$f" "${f%.*}"
  for k in faces vertices seam_length_normalized; do
    [ "$(field obj.json $k)" = "$(field "${f%.*}.json" $k)" ] || fail "$f: $k $(field "${f%.*}.json" $k), OBJ: $(field obj.json $k)"
  done
done
# text formats: the same doubles, the same map to the last digit; binary STL: floats, the same map to 1e-6
for f in cat cat_ascii; do
  [ "$(field obj.json e_sd)" = "$(field $f.json e_sd)" ] || fail "$f: e_sd $(field $f.json e_sd), OBJ: $(field obj.json e_sd)"
done
python3 -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(abs(a - b) > 1e-6 * a)" \
  "$(field obj.json e_sd)" "$(field cat_binary.json e_sd)" || fail "binary STL: e_sd $(field cat_binary.json e_sd), OBJ: $(field obj.json e_sd)"
echo "ok"
