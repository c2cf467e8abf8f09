#!/bin/bash
# --pack on two models in one OBJ (cat and bishop part: two components, so
# two charts at least): the written UVs lie in [margin/N, 1 - margin/N]^2,
# the charts' bounding boxes are at least margin texels apart, the report
# says "packed": true with the texture size, margin and fill rate; the E_SD
# at the optimal uniform scale is the report's (charts moved rigidly, one
# scale), no overlap (shared evaluator, when present). The same on
# multiComp.obj (six components, 6 charts). --normalize packs
# too with several charts. Usage errors exit 2, a margin too large for the
# charts exits 1 with no OBJ written. Fill rates measured: 0.566 (512
# texels, margin 4), 0.580 (1024); the threshold 0.45 leaves room for the
# optimizer to find other seams (other chart shapes).
set -u
BIN=$1 DATA=$2 SCRATCH=$3
MULTI="$(cd "$(dirname "$0")/../data/general" && pwd)/multiComp.obj"
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

# the two meshes in one OBJ (vertex indices of the second shifted)
python3 - "$DATA/cat_f1500.obj" "$DATA/bishop_part_f1000.obj" >two.obj <<'PY' || fail "cannot make two.obj"
import sys
offset = 0
for name in sys.argv[1:]:
    n = 0
    for line in open(name):
        t = line.split()
        if t and t[0] == "v":
            print(line.strip()); n += 1
        elif t and t[0] == "f":
            print("f " + " ".join(str(int(x.split("/")[0]) + offset) for x in t[1:]))
    offset += n
PY

# OBJ checks: vt in [m/N, 1 - m/N], charts (faces joined by shared vt) at
# least m texels apart by their bounding boxes.
check_obj() {
python3 - "$1" "$2" "$3" "$4" <<'PY'
import json, sys
obj, rep, N, m = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
r = json.load(open(rep))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s" % what)
check(r["status"] == "OK", "status is %r" % r["status"])
check(r.get("packed") is True, "report: packed is %r" % r.get("packed"))
check(r.get("texture_size") == N and r.get("margin") == m,
      "report: texture_size %r, margin %r" % (r.get("texture_size"), r.get("margin")))
check(isinstance(r.get("fill_rate"), float) and 0.45 < r["fill_rate"] <= 1, "fill_rate %r" % r.get("fill_rate"))
check(r["charts"] >= 2, "charts %r" % r["charts"])
vt, faces = [], []
for line in open(obj):
    t = line.split()
    if t and t[0] == "vt":
        vt.append((float(t[1]), float(t[2])))
    elif t and t[0] == "f":
        faces.append([int(x.split("/")[1]) - 1 for x in t[1:]])
check(vt, "no vt in the output")
lo, hi = m / N - 1e-12, 1 - m / N + 1e-12
check(all(lo <= u <= hi and lo <= v <= hi for u, v in vt), "vt outside [m/N, 1 - m/N]")
parent = list(range(len(vt)))
def find(x):
    while parent[x] != x:
        parent[x] = parent[parent[x]]; x = parent[x]
    return x
for f in faces:
    for c in f[1:]:
        parent[find(c)] = find(f[0])
box = {}
for i, (u, v) in enumerate(vt):
    b = box.setdefault(find(i), [u, v, u, v])
    b[0] = min(b[0], u); b[1] = min(b[1], v); b[2] = max(b[2], u); b[3] = max(b[3], v)
check(len(box) == r["charts"], "%d charts in the OBJ, %r in the report" % (len(box), r["charts"]))
bs = list(box.values())
for i in range(len(bs)):
    for j in range(i):
        a, b = bs[i], bs[j]
        gap = max(a[0] - b[2], b[0] - a[2], a[1] - b[3], b[1] - a[3])
        check(gap * N >= m - 1e-6, "charts %d and %d only %g texels apart" % (i, j, gap * N))
area = 0
for f in faces:
    (a, b, c) = (vt[f[0]], vt[f[1]], vt[f[2]])
    area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
check(abs(area - r["fill_rate"]) <= 1e-9, "UV area %r, fill_rate %r" % (area, r["fill_rate"]))
PY
}

UVM="$DATA/../../shared/tools/uvmetrics.py"
check_uvmetrics() {
  [ -f "$UVM" ] || { echo "note: $UVM not found; evaluator check skipped"; return 0; }
  python3 "$UVM" --json "$1" >m.json 2>m.err || fail "uvmetrics failed: $(cat m.err)"
  python3 - m.json "$2" <<'PY' || fail "uvmetrics disagrees with the report"
import json, sys
m = json.loads(open(sys.argv[1]).read().strip().splitlines()[0])
r = json.load(open(sys.argv[2]))
opt = m["e_sd_optimal_scale"]
if abs(opt - r["e_sd"]) > 1e-6 * abs(r["e_sd"]):
    sys.exit("FAIL: e_sd_optimal_scale %r vs report e_sd %r" % (opt, r["e_sd"]))
if m["flipped"] != 0 or m["overlap_pairs"] != 0:
    sys.exit("FAIL: %r flipped triangles, %r overlapping pairs" % (m["flipped"], m["overlap_pairs"]))
if m["charts"] != r["charts"]:
    sys.exit("FAIL: uvmetrics finds %r charts, the report %r" % (m["charts"], r["charts"]))
PY
}

"$BIN" two.obj --recut-rounds 0 --pack --texture-size 512 --margin 4 -o p.obj --report p.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--pack: exit code $rc (stderr: $(cat err.txt))"
check_obj p.obj p.json 512 4 || fail "--pack output not as expected"
python3 -c "import json,sys; r=json.load(open('p.json')); sys.exit(0 if r['normalized'] is False else 1)" ||
  fail "--pack alone: normalized should be false"
check_uvmetrics p.obj p.json

# six components of any genus (multiComp.obj, cut into disks by the initial
# map): 6 charts packed, bijective (measured fill rate 0.662, 2048 texels, margin 2)
"$BIN" "$MULTI" --seam-weight 0.3 --pack --texture-size 2048 --margin 2 -o m6.obj --report m6.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "multiComp --pack: exit code $rc (stderr: $(cat err.txt))"
check_obj m6.obj m6.json 2048 2 || fail "multiComp --pack output not as expected"
python3 -c "import json,sys; r=json.load(open('m6.json')); sys.exit(0 if r['charts'] == 6 and r['overlapping_triangle_pairs'] == 0 else 1)" ||
  fail "multiComp: charts or overlaps: $(cat m6.json)"
check_uvmetrics m6.obj m6.json

# --normalize with several charts packs, with the default texture and margin
"$BIN" two.obj --recut-rounds 0 --normalize -o n.obj --report n.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--normalize: exit code $rc (stderr: $(cat err.txt))"
check_obj n.obj n.json 1024 4 || fail "--normalize output not as expected"
python3 -c "import json,sys; r=json.load(open('n.json')); sys.exit(0 if r['normalized'] is True else 1)" ||
  fail "--normalize: normalized should be true"

# usage errors: exit 2, nothing written
for args in "--pack --texture-size 0" "--pack --texture-size 12.5" "--pack --margin -1" "--pack --margin x" \
            "--texture-size 512" "--margin 2" "--pack --texture-size 64 --margin 32"; do
  # shellcheck disable=SC2086
  "$BIN" two.obj $args -o u.obj >out.txt 2>err.txt
  rc=$?
  [ "$rc" -eq 2 ] || fail "'$args': exit code $rc, not 2"
  [ -s err.txt ] || fail "'$args': no message on stderr"
  [ ! -e u.obj ] || fail "'$args': u.obj written"
done

# a margin that leaves room for one chart only: exit 1, status in the report, no OBJ
"$BIN" two.obj --recut-rounds 0 --pack --texture-size 16 --margin 7 -o f.obj --report f.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 1 ] || fail "margin too large: exit code $rc, not 1"
[ ! -e f.obj ] || fail "margin too large: f.obj written"
python3 -c "import json,sys; r=json.load(open('f.json')); sys.exit(0 if r['status'] == 'ERROR_WRONG_PARAMETER' and r['packed'] is False else 1)" ||
  fail "margin too large: report $(cat f.json)"
echo "ok"
