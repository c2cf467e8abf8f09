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

# Issue 17: ARAP (no barrier) once squeezed a cat triangle to area ratio
# 5e-16 (E_SD 6e27) and said OK; now a valid map (checked by uvmetrics). Pure
# MIPS (conformal without its area term) is scale invariant: its map is
# written at the scale that minimizes E_SD, uvmetrics' optimal scale.
UVM="$DATA/../../shared/tools/uvmetrics.py"
for e in arap mips; do
  extra=()
  [ $e = mips ] && extra=(--area-weight 0)
  "$BIN" "$DATA/cat_f1500.obj" --keep-seams --energy $e "${extra[@]}" -o cat_$e.obj --report cat_$e.json >out.txt 2>err.txt
  rc=$?
  [ "$rc" -eq 0 ] || fail "--energy $e: exit code $rc (stderr: $(cat err.txt))"
  [ -f "$UVM" ] || continue
  python3 "$UVM" --json cat_$e.obj >m_$e.json 2>m.err || fail "uvmetrics failed: $(cat m.err)"
  python3 - m_$e.json cat_$e.json $e <<'PY' || fail "--energy $e: report or map not as expected"
import json, sys
m, r, e = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), sys.argv[3]
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "OK", "status %r" % r["status"])
check(m["flipped"] == 0 and m["degenerate"] == 0, "%d flipped, %d degenerate" % (m["flipped"], m["degenerate"]))
check(m["e_sd"] is not None and abs(m["e_sd"] - r["e_sd"]) <= 1e-6 * r["e_sd"], "e_sd vs uvmetrics %r" % m["e_sd"])
check(abs(m["e_sd_optimal_scale"] - r["e_sd_optimal_scale"]) <= 1e-6 * r["e_sd_optimal_scale"],
      "e_sd_optimal_scale vs uvmetrics %r" % m["e_sd_optimal_scale"])
if e == "mips":
    check(r["energy"] == "conformal", "energy %r" % r["energy"])
    check(abs(r["e_sd"] - r["e_sd_optimal_scale"]) <= 1e-9 * r["e_sd"], "not written at the optimal scale")
    check(abs(m["conformal_distortion"] - r["energy_value"] / 2) <= 1e-6, "energy_value vs uvmetrics' conformal")
PY
done
grep -q "energy conformal 2\." err.txt || fail "no conformal energy on the summary line: $(cat err.txt)"
echo "ok"
