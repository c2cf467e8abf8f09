#!/bin/bash
# --normalize: the written UVs lie in [0,1]^2 with a longer extent of exactly
# 1 (one scale for all charts); the report keeps the E_SD of the optimizer's
# (unnormalized) map and says "normalized": true, "packed": false (one
# chart: scaled, not packed; several are packed, see pack.sh). With the shared evaluator
# beside the repository, E_SD at the optimal uniform scale of the written map
# equals the report's e_sd, and no triangle is flipped.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" --normalize -o n.obj --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "exit code $rc (stderr: $(cat err.txt))"
[ -s n.obj ] || fail "n.obj was not written"
python3 - n.obj r.json <<'PY' || fail "normalized output not as expected"
import json, sys
r = json.load(open(sys.argv[2]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s" % what)
check(r["status"] == "OK", "status is %r, not OK" % r["status"])
check(r.get("normalized") is True, "report: normalized is %r" % r.get("normalized"))
check(r["charts"] == 1 and r.get("packed") is False and r.get("fill_rate") is None,
      "report: charts %r, packed %r, fill_rate %r" % (r["charts"], r.get("packed"), r.get("fill_rate")))
check(r["e_sd"] is not None and 4.0 <= r["e_sd"] <= 4.1 + 1e-9, "e_sd %r" % r["e_sd"])
us, vs = [], []
for line in open(sys.argv[1]):
    t = line.split()
    if t and t[0] == "vt":
        us.append(float(t[1])); vs.append(float(t[2]))
check(us, "no vt in the output")
eps = 1e-12
check(all(-eps <= x <= 1 + eps for x in us + vs), "vt outside [0,1]: u %r..%r, v %r..%r"
      % (min(us), max(us), min(vs), max(vs)))
ext = max(max(us) - min(us), max(vs) - min(vs))
check(abs(ext - 1) <= 1e-9, "max extent %r, not 1" % ext)
PY
UVM="$DATA/../../shared/tools/uvmetrics.py"
if [ -f "$UVM" ]; then
  python3 "$UVM" --json --no-overlap n.obj >m.json 2>m.err || fail "uvmetrics failed: $(cat m.err)"
  python3 - m.json r.json <<'PY' || fail "uvmetrics disagrees with the report"
import json, sys
m = json.loads(open(sys.argv[1]).read().strip().splitlines()[0])
r = json.load(open(sys.argv[2]))
opt = m["e_sd_optimal_scale"]
if abs(opt - r["e_sd"]) > 1e-6 * abs(r["e_sd"]):
    sys.exit("FAIL: e_sd_optimal_scale %r vs report e_sd %r" % (opt, r["e_sd"]))
if m["flipped"] != 0:
    sys.exit("FAIL: %r flipped triangles" % m["flipped"])
PY
else
  echo "note: $UVM not found; evaluator check skipped"
fi
echo "ok"
