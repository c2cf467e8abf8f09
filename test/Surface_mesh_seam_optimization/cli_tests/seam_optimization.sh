#!/bin/bash
# The default mode (seam optimization under the bound 4.1) on a small shipped
# disk: exit 0, the report meets the bound with seams, the OBJ has per-corner
# UVs split along the seams, progress lines on stderr (not a terminal here),
# --quiet silences everything. Cross-checked by ../shared/tools/uvmetrics.py
# when the evaluator is beside the repository.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
UVMETRICS="$(cd "$(dirname "$0")" && pwd)/../../../../shared/tools/uvmetrics.py"
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" -o cat.obj --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "exit code $rc (stderr: $(cat err.txt))"
[ -s cat.obj ] || fail "cat.obj was not written"
[ ! -s out.txt ] || fail "unexpected stdout: $(cat out.txt)"
python3 - r.json cat.obj <<'PY' || fail "report or OBJ not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "OK", "status is %r, not OK" % r["status"])
check(r["mode"] == "distortion-bound", "mode %r" % r["mode"])
check(r["distortion_bound"] == 4.1, "distortion_bound %r" % r["distortion_bound"])
check(r["seam_weight"] is None, "seam_weight is not null")
check(r["bound_met"] is True, "bound not met")
check(4.0 <= r["e_sd"] <= 4.1, "e_sd %r not in [4, 4.1]" % r["e_sd"])
check(r["e_sd"] < r["initial_e_sd"], "E_SD did not decrease")
check(r["topology_operations"] > 0, "no topology operation")
check(r["seam_length_normalized"] > 0 and r["seam_length"] > 0, "no seams")
check(r["charts"] == 1, "%r charts, expected 1" % r["charts"])
check(r["iterations"] > 0, "no iteration")
check(r["lambda"] is not None and 0 <= r["lambda"] < 1, "lambda %r" % r["lambda"])
check(r["bijective"] is True, "the default run is not bijective")
check(r["overlapping_triangle_pairs"] == 0, "%r overlapping pairs" % r["overlapping_triangle_pairs"])
check(r["notes"] == [], "notes on a clean run: %r" % r["notes"])
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
# the seams split vertices into several UV corners
check(vt > v, "%d vt for %d vertices: no seam in the OBJ" % (vt, v))
PY

# Progress: plain lines (stderr is a file), then the note and the summary.
grep -Eq "^it [0-9]+  ops [0-9]+  E_SD [0-9.e+-]+  E_se [0-9.e+-]+  lambda [0-9.e+-]+  t [0-9.]+ s$" err.txt \
  || fail "no progress line on stderr: $(cat err.txt)"
! grep -q $'\r' err.txt || fail "carriage return in stderr although it is not a terminal"
! grep -q "^optimize_seams: note: " err.txt || fail "a note on a clean run: $(cat err.txt)"
tail -n 1 err.txt | grep -q "^optimize_seams: cat_f1500.obj: .*(bound 4.1, met).*wrote cat.obj$" \
  || fail "last stderr line is not the summary: $(tail -n 1 err.txt)"

# The same run again gives the same file (deterministic).
"$BIN" "$DATA/cat_f1500.obj" --quiet -o again.obj >out.txt 2>err.txt || fail "second run failed"
cmp -s cat.obj again.obj || fail "the run is not deterministic"

# --no-bijectivity: no scaffold; the report still checks the result.
"$BIN" "$DATA/cat_f1500.obj" --no-bijectivity -o nb.obj --report nb.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--no-bijectivity: exit code $rc (stderr: $(cat err.txt))"
python3 - nb.json <<'PY' || fail "--no-bijectivity report not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "OK" and r["bound_met"] is True, r
assert r["scaffold_rebuilds"] == 0, r["scaffold_rebuilds"]
assert r["bijective"] == (r["overlapping_triangle_pairs"] == 0), r
PY

"$BIN" "$DATA/cat_f1500.obj" --quiet -o q.obj >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--quiet run: exit code $rc"
[ ! -s err.txt ] || fail "--quiet printed: $(cat err.txt)"

if [ -f "$UVMETRICS" ]; then
  python3 "$UVMETRICS" cat.obj --json >m.json || fail "uvmetrics failed on cat.obj"
  python3 - r.json m.json <<'PY' || fail "uvmetrics disagrees with the report"
import json, sys
r, m = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert m["valid"] and m["flipped"] == 0 and m["degenerate"] == 0, m["problems"]
assert m["charts"] == r["charts"] == 1, (m["charts"], r["charts"])
assert m["e_sd"] <= 4.1 and abs(m["e_sd"] - r["e_sd"]) <= 1e-6 * r["e_sd"], (m["e_sd"], r["e_sd"])
assert abs(m["seam_length_normalized"] - r["seam_length_normalized"]) <= 1e-6, \
    (m["seam_length_normalized"], r["seam_length_normalized"])
PY
fi
echo "ok"
