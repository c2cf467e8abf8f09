#!/bin/bash
# A torus cannot be flattened without seam optimization: the library's error
# code comes out as one line, exit 1, and the report carries its name.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

python3 - >torus.obj <<'PY'
import math
n, m = 12, 6  # around the hole, around the tube
for i in range(n):
    for j in range(m):
        a, b = 2 * math.pi * i / n, 2 * math.pi * j / m
        r = 1 + 0.4 * math.cos(b)
        print("v %.17g %.17g %.17g" % (r * math.cos(a), r * math.sin(a), 0.4 * math.sin(b)))
idx = lambda i, j: (i % n) * m + (j % m) + 1
for i in range(n):
    for j in range(m):
        print("f %d %d %d" % (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)))
        print("f %d %d %d" % (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)))
PY

"$BIN" torus.obj --keep-seams --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 1 ] || fail "exit code $rc, expected 1 (stderr: $(cat err.txt))"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "expected one stderr line, got: $(cat err.txt)"
grep -q "^optimize_seams: error: A chart is not a topological disk" err.txt \
  || fail "message is not the library's ERROR_NOT_A_DISK message: $(cat err.txt)"
[ ! -e torus_uv.obj ] || fail "an output OBJ was written"
python3 -c 'import json,sys; r=json.load(open("r.json")); sys.exit(r["status"] != "ERROR_NOT_A_DISK")' \
  || fail "report status is not ERROR_NOT_A_DISK: $(cat r.json)"
echo "ok"
