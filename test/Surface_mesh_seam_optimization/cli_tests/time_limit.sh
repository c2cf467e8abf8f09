#!/bin/bash
# --time-limit S: the run stops at the first progress call past S seconds,
# writes the best result so far (status WARNING_CANCELLED, exit 0) and says
# so on stderr. S must be > 0 (exit 2), and --keep-seams cannot be stopped.
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
grep -q "time limit of 0.001 s reached" err.txt || fail "no stderr note: $(cat err.txt)"
python3 - r.json <<'PY' || fail "report not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "WARNING_CANCELLED", "status is %r, not WARNING_CANCELLED" % r["status"])
check(r["output"] == "t.obj", "output %r" % r["output"])
check(r["e_sd"] is not None and r["e_sd"] >= 4.0, "e_sd %r" % r["e_sd"])
check(any("time limit" in n for n in r["notes"]), "no time-limit note")
PY

for bad in 0 -1 abc; do
  "$BIN" "$DATA/cat_f1500.obj" --time-limit "$bad" -o x.obj >out.txt 2>err.txt
  rc=$?
  [ "$rc" -eq 2 ] || fail "--time-limit $bad: exit code $rc, expected 2"
  grep -q "^optimize_seams: error: .*--time-limit" err.txt || fail "--time-limit $bad: $(cat err.txt)"
done
"$BIN" "$DATA/cat_f1500.obj" --keep-seams --time-limit 1 -o x.obj >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 2 ] || fail "--keep-seams --time-limit: exit code $rc, expected 2"
[ ! -e x.obj ] || fail "an output was written on a usage error"
echo "ok"
