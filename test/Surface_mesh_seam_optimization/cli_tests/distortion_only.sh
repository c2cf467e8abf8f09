#!/bin/bash
# Distortion-only run on a shipped disk mesh: exit 0, the OBJ is written with
# per-corner UVs, the JSON report says OK and the distortion went down.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/bimba_i_f10000.obj" --keep-seams -o out.obj --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "exit code $rc (stderr: $(cat err.txt))"
[ -s out.obj ] || fail "out.obj was not written"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "expected one summary line on stderr, got: $(cat err.txt)"
python3 - r.json out.obj <<'PY' || fail "report or OBJ not as expected"
import json, math, sys
r = json.load(open(sys.argv[1]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "OK", "status is %r, not OK" % r["status"])
for key in ("message", "e_sd", "initial_e_sd", "seam_length", "seam_length_normalized", "charts",
            "iterations", "topology_operations", "lambda", "bound_met", "seconds", "faces",
            "vertices", "input"):
    check(key in r, "no %r in the report" % key)
check(r["e_sd"] is not None and r["initial_e_sd"] is not None, "E_SD missing")
check(4.0 <= r["e_sd"] < r["initial_e_sd"], "e_sd %r not in [4, initial_e_sd %r)" % (r["e_sd"], r["initial_e_sd"]))
check(r["charts"] == 1, "a disk gives one chart")
check(r["iterations"] > 0, "no iteration")
check(r["input"].endswith("bimba_i_f10000.obj"), "input file name")
v = vt = f = 0
for line in open(sys.argv[2]):
    tag = line.split(" ", 1)[0]
    if tag == "v": v += 1
    elif tag == "vt": vt += 1
    elif tag == "f":
        f += 1
        corners = line.split()[1:]
        check(len(corners) == 3 and all(c.count("/") == 1 for c in corners), "bad face line %r" % line)
check(f == r["faces"] and v == r["vertices"], "OBJ has %d v, %d f" % (v, f))
# a disk with fixed (no) seams: one UV per vertex
check(vt == v, "%d vt for %d vertices" % (vt, v))
PY

python3 -c 'import json,sys; r=json.load(open("r.json")); sys.exit(not (r["mode"] == "keep-seams"
    and r["topology_operations"] == 0 and r["lambda"] is None and r["bound_met"] is None))' \
  || fail "keep-seams report: mode/topology_operations/lambda/bound_met: $(cat r.json)"

# The default output name (seam optimization is the default mode now; three
# Newton iterations only, the cap is a warning, not a failure), and --quiet.
"$BIN" "$DATA/bimba_i_f10000.obj" --max-iterations 3 --report d.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "default run: exit code $rc (stderr: $(cat err.txt))"
[ -s bimba_i_f10000_uv.obj ] || fail "default output bimba_i_f10000_uv.obj not written"
python3 -c 'import json,sys; r=json.load(open("d.json")); sys.exit(not (r["mode"] == "distortion-bound"
    and r["status"] == "WARNING_MAXIMUM_ITERATIONS" and r["iterations"] == 3))' \
  || fail "default run report: $(cat d.json)"
grep -q "warning: Maximum number of iterations" err.txt || fail "no warning about the cap: $(cat err.txt)"
"$BIN" "$DATA/bimba_i_f10000.obj" --quiet --max-iterations 3 -o q.obj >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--quiet run: exit code $rc"
[ ! -s err.txt ] || fail "--quiet printed: $(cat err.txt)"
echo "ok"
