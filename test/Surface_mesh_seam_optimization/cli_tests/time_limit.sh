#!/bin/bash
# --time-limit S (the library's time_limit named parameter): the run stops
# past S seconds, writes the best result so far (status WARNING_TIME_LIMIT,
# exit 0, a valid map) and says so on stderr; --keep-seams too. S must be > 0
# (exit 2).
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/bimba_i_f10000.obj" --time-limit 0.001 -o t.obj --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "exit code $rc, expected 0 (stderr: $(cat err.txt))"
[ -s t.obj ] || fail "t.obj was not written"
grep -q "^vt " t.obj || fail "t.obj has no texture coordinates"
grep -q "time limit of 0.001 s reached: best result so far" err.txt || fail "no stderr note: $(cat err.txt)"
grep -q "warning: Time limit reached: best result so far" err.txt || fail "no stderr warning: $(cat err.txt)"
! grep -q "Cancelled" err.txt || fail "the visitor's message: $(cat err.txt)"
python3 - r.json <<'PY' || fail "report not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "WARNING_TIME_LIMIT", "status is %r, not WARNING_TIME_LIMIT" % r["status"])
check(r["output"] == "t.obj", "output %r" % r["output"])
check(r["e_sd"] is not None and r["e_sd"] >= 4.0, "e_sd %r" % r["e_sd"])
check(any("time limit" in n for n in r["notes"]), "no time-limit note")
check(r["bound_met"] == (r["e_sd"] <= 4.1), "bound_met %r for e_sd %r" % (r["bound_met"], r["e_sd"]))
PY
UVM="$DATA/../../shared/tools/uvmetrics.py"
if [ -f "$UVM" ]; then
  python3 "$UVM" --json t.obj >m.json 2>m.err || fail "uvmetrics failed: $(cat m.err)"
  python3 - m.json r.json <<'PY' || fail "uvmetrics disagrees"
import json, sys
m, r = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
if m["flipped"] != 0 or m["degenerate"] != 0:
    sys.exit("FAIL: %d flipped, %d degenerate" % (m["flipped"], m["degenerate"]))
if abs(m["e_sd"] - r["e_sd"]) > 1e-6 * r["e_sd"]:
    sys.exit("FAIL: e_sd %r vs uvmetrics %r" % (r["e_sd"], m["e_sd"]))
PY
fi

# --keep-seams stops too (bimba needs ~19 iterations, 0.5 s)
"$BIN" "$DATA/bimba_i_f10000.obj" --keep-seams --time-limit 0.001 -o k.obj --report k.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--keep-seams --time-limit: exit code $rc (stderr: $(cat err.txt))"
[ -s k.obj ] || fail "k.obj was not written"
python3 -c 'import json,sys; r=json.load(open("k.json")); sys.exit(not (r["status"] == "WARNING_TIME_LIMIT"
    and r["mode"] == "keep-seams" and r["iterations"] < 19))' || fail "--keep-seams report: $(cat k.json)"

for bad in 0 -1 abc; do
  "$BIN" "$DATA/cat_f1500.obj" --time-limit "$bad" -o x.obj >out.txt 2>err.txt
  rc=$?
  [ "$rc" -eq 2 ] || fail "--time-limit $bad: exit code $rc, expected 2"
  grep -q "^optimize_seams: error: .*--time-limit" err.txt || fail "--time-limit $bad: $(cat err.txt)"
  [ ! -e x.obj ] || fail "an output was written on a usage error"
done
echo "ok"
