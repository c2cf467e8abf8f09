#!/bin/bash
# --seam-weights FILE[:W]: a region over the plain run's seams (cost 100)
# moves them out, within the bound; the file's vertex indices are the input
# file's, also when the input has an unused vertex before them; per-vertex and
# per-edge files; malformed files are refused with the line at fault.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }
MESH="$DATA/cat_f1500.obj"

"$BIN" "$MESH" -o plain.obj --report plain.json --quiet || fail "plain run"
# the plain run's seam vertices, as 0-based indices of the input file
python3 - "$MESH" plain.obj > region.txt <<'PY' || fail "cannot list the plain seams"
import sys
def obj(path):
    V, T, F = [], [], []
    for l in open(path):
        p = l.split()
        if p and p[0] == 'v': V.append(tuple(float(x) for x in p[1:4]))
        elif p and p[0] == 'vt': T.append(tuple(float(x) for x in p[1:3]))
        elif p and p[0] == 'f': F.append([tuple(int(y) - 1 for y in x.split('/')[:2]) for x in p[1:]])
    return V, T, F
Vin, _, _ = obj(sys.argv[1])
V, T, F = obj(sys.argv[2])
index = {p: i for i, p in enumerate(Vin)}
corners = {}
for f in F:
    for k in range(3):
        (a, ta), (b, tb) = f[k], f[(k + 1) % 3]
        a, b, ta, tb = index[V[a]], index[V[b]], T[ta], T[tb]
        if a > b: a, b, ta, tb = b, a, tb, ta
        corners.setdefault((a, b), []).append((ta, tb))
seam = {v for e, c in corners.items() if len(c) == 2 and c[0] != c[1] for v in e}
print("# the plain run's seam vertices")
for v in sorted(seam): print(v)
PY
"$BIN" "$MESH" -o repelled.obj --report repelled.json --quiet --seam-weights region.txt ||
  fail "repelled run: $(cat repelled.json)"
# the same region on a copy of the input with an unused vertex first: indices + 1
{ echo "v 9 9 9"; awk '/^f /{printf "f"; for(i=2;i<=NF;i++) printf " %d", $i+1; print ""; next} {print}' "$MESH"; } > shifted.obj
awk '/^[0-9]/{print $1+1; next} {print}' region.txt > region_shifted.txt
"$BIN" shifted.obj -o shifted_out.obj --report shifted.json --quiet --seam-weights region_shifted.txt:100 ||
  fail "shifted run: $(cat shifted.json)"
python3 - plain.json repelled.json shifted.json region.txt plain.obj repelled.obj "$MESH" <<'PY' || fail "reports not as expected"
import json, math, sys
plain, rep, shifted = (json.load(open(p)) for p in sys.argv[1:4])
region = {int(l) for l in open(sys.argv[4]) if l[0].isdigit()}
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s" % what)
for r in (plain, rep, shifted):
    check(r["status"] == "OK" and r["bound_met"] and r["bijective"], "status/bound/bijective %r" % r)
check(plain["seam_weights"] is None, "plain seam_weights %r" % plain["seam_weights"])
check(plain["weighted_seam_length_normalized"] == plain["seam_length_normalized"], "plain weighted != plain")
check(rep["seam_weights"] == "region.txt", "seam_weights %r" % rep["seam_weights"])
check(shifted["seam_length_normalized"] == rep["seam_length_normalized"] and
      shifted["weighted_seam_length_normalized"] == rep["weighted_seam_length_normalized"],
      "an unused vertex changed the result: %r vs %r" % (shifted, rep))
def inside(path):
    Vin = [tuple(float(x) for x in l.split()[1:4]) for l in open(sys.argv[7]) if l.startswith("v ")]
    index = {p: i for i, p in enumerate(Vin)}
    V, T, F = [], [], []
    for l in open(path):
        p = l.split()
        if p and p[0] == 'v': V.append(index[tuple(float(x) for x in p[1:4])])
        elif p and p[0] == 'vt': T.append(tuple(float(x) for x in p[1:3]))
        elif p and p[0] == 'f': F.append([tuple(int(y) - 1 for y in x.split('/')[:2]) for x in p[1:]])
    corners = {}
    for f in F:
        for k in range(3):
            (a, ta), (b, tb) = f[k], f[(k + 1) % 3]
            a, b, ta, tb = V[a], V[b], T[ta], T[tb]
            if a > b: a, b, ta, tb = b, a, tb, ta
            corners.setdefault((a, b), []).append((ta, tb))
    return sum(math.dist(Vin[a], Vin[b]) for (a, b), c in corners.items()
               if len(c) == 2 and c[0] != c[1] and a in region and b in region)
before, after = inside(sys.argv[5]), inside(sys.argv[6])
check(before > 0, "the plain seams are not in their own region")
check(after <= 0.5 * before, "seams in the region: %g before, %g with cost 100" % (before, after))
PY

# per-vertex and per-edge forms: a cost of 1 everywhere is the plain run
awk '/^[0-9]/{print $1, 1}' region.txt > ones_v.txt
first_face=$(grep -m1 '^f ' "$MESH" | awk '{split($2,a,"/"); split($3,b,"/"); print a[1]-1, b[1]-1}')
echo "$first_face 1.0   # an edge of the first face" > ones_e.txt
for f in ones_v.txt ones_e.txt; do
  "$BIN" "$MESH" -o o.obj --report o.json --quiet --seam-weights $f || fail "$f: $(cat o.json)"
  cmp -s o.obj plain.obj || fail "$f: costs of 1 changed the result"
done

run_error() { # $1: expected exit code, $2: word the message must contain, rest: arguments
  local code=$1 word=$2; shift 2
  "$BIN" "$MESH" -o u.obj "$@" >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -eq "$code" ] || fail "'$*': exit code $rc, expected $code (stderr: $(cat err.txt))"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*': expected one stderr line, got: $(cat err.txt)"
  grep -q -- "$word" err.txt || fail "'$*': message does not mention '$word': $(cat err.txt)"
  [ ! -e u.obj ] || fail "'$*': an output file was written"
}
printf '1\n2 0.5\n' > mixed.txt
printf '1\n99999\n' > range.txt
printf '0 1 2\n0 500 2\n' > nonedge.txt
printf '3 -2\n' > negative.txt
printf '# nothing\n\n' > empty.txt
printf '1\nx\n' > word.txt
run_error 1 "line 2: mixes forms" --seam-weights mixed.txt
run_error 1 "line 2: no vertex 99999" --seam-weights range.txt
run_error 1 "share no edge" --seam-weights nonedge.txt
run_error 1 "line 1: a cost must be a number >= 0" --seam-weights negative.txt
run_error 1 "lists nothing" --seam-weights empty.txt
run_error 1 "'x' is not a number" --seam-weights word.txt
run_error 1 "applies to a region" --seam-weights ones_v.txt:5
run_error 1 "cannot open seam weights" --seam-weights no_such_file.txt
run_error 2 "W >= 0" --seam-weights region.txt:-1
run_error 2 "keep-seams" --seam-weights region.txt --keep-seams
run_error 2 "repair" --seam-weights region.txt --repair
echo "ok"
