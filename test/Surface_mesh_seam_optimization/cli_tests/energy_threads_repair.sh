#!/bin/bash
# --threads: one thread gives the same file as the default (results do not
# depend on the schedule). --energy arap / mips: the report names the energy,
# E_SD is still what the bound applies to. --repair: a duplicated face and an
# unused point are refused without it (saying --repair fixes this) and removed
# with it (the report counts them), giving the clean mesh's result.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" -o all.obj --quiet || fail "default run failed"
"$BIN" "$DATA/cat_f1500.obj" -o one.obj --threads 1 --report one.json --quiet || fail "--threads 1 failed"
cmp -s all.obj one.obj || fail "--threads 1 changed the result"
python3 -c 'import json,sys; r=json.load(open("one.json")); sys.exit(r["threads"] != 1)' \
  || fail "report threads is not 1: $(cat one.json)"

for energy in arap conformal; do
  "$BIN" "$DATA/cat_f1500.obj" --energy $energy -o $energy.obj --report $energy.json --quiet \
    || fail "--energy $energy: exit code $?"
  python3 - $energy.json $energy <<'PY' || fail "--energy $energy: report not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] in ("OK", "WARNING_BOUND_NOT_MET"), r["status"]
assert r["energy"] == sys.argv[2], r["energy"]
assert r["e_sd"] >= 4 and r["iterations"] > 0, r
# the bound is on the energy, its default the energy's
assert abs(r["distortion_bound"] - {"arap": 0.025, "conformal": 2.02525}[sys.argv[2]]) < 1e-12, r
assert r["bound_met"] == (r["energy_value"] <= r["distortion_bound"]), r
PY
done
cmp -s arap.obj conformal.obj && fail "arap and conformal gave the same map"
"$BIN" "$DATA/cat_f1500.obj" --energy mips -o mips.obj --quiet || fail "--energy mips (the former name)"
cmp -s mips.obj conformal.obj || fail "--energy mips is not --energy conformal"

# a duplicated face (non-manifold edges) and an unused point
(cat "$DATA/cat_f1500.obj"; grep '^f' "$DATA/cat_f1500.obj" | head -n 1; echo "v 9 9 9") >dirty.obj
"$BIN" dirty.obj -o x.obj >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 1 ] || fail "dirty mesh without --repair: exit code $rc"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "(--repair fixes this)" err.txt || fail "no repair hint: $(cat err.txt)"
[ ! -e x.obj ] || fail "an output was written on error"
"$BIN" dirty.obj --repair -o repaired.obj --report rep.json >out.txt 2>err.txt || fail "--repair: exit code $?"
grep -q "^optimize_seams: repair: 1 duplicate face removed, 1 unused point removed" err.txt \
  || fail "--repair did not say what it changed: $(cat err.txt)"
python3 - rep.json <<'PY' || fail "--repair report not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
rep = r["repair"]
assert rep["duplicate_faces_removed"] == 1 and rep["isolated_points_removed"] == 1, rep
assert r["faces"] == 1499 and r["vertices"] == 767 and r["status"] == "OK", r
PY
# the repaired mesh is the clean one: same vertices and faces, same result
cmp -s <(grep -v '^#' all.obj) <(grep -v '^#' repaired.obj) || fail "the repaired mesh gave another result"
echo "ok"
