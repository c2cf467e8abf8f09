#!/bin/bash
# --seam-weight: a fixed lambda (no dual step, no bound) on a small shipped
# disk; the report carries it as given.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/bishop_part_f1000.obj" --seam-weight 0.025 -o b.obj --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "exit code $rc (stderr: $(cat err.txt))"
[ -s b.obj ] || fail "b.obj was not written"
python3 - r.json <<'PY' || fail "report not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "OK", "status is %r, not OK" % r["status"])
check(r["mode"] == "seam-weight", "mode %r" % r["mode"])
check(r["seam_weight"] == 0.025, "seam_weight %r" % r["seam_weight"])
check(r["lambda"] is not None and abs(r["lambda"] - 0.025) < 1e-12, "lambda %r, expected 0.025" % r["lambda"])
check(r["distortion_bound"] is None and r["bound_met"] is None, "a bound in seam-weight mode")
check(4.0 <= r["e_sd"] < r["initial_e_sd"], "e_sd %r" % r["e_sd"])
check(r["topology_operations"] > 0 and r["seam_length_normalized"] > 0, "no seams")
check(r["charts"] == 1, "%r charts" % r["charts"])
PY
# every progress line shows the fixed lambda
grep -E "^it " err.txt | grep -vq "  lambda 0.025  " && fail "lambda moved: $(grep -E '^it ' err.txt)"
grep -Eq "^it " err.txt || fail "no progress line: $(cat err.txt)"
echo "ok"
