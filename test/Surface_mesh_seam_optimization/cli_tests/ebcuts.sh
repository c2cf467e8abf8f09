#!/bin/bash
# --cut-strategy ebcuts: the EBCuts baseline meets the bound on a small mesh,
# the report names the strategy and counts the cuts; bad values and
# combinations are usage errors.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" -o e.obj --report e.json --quiet --cut-strategy ebcuts || fail "ebcuts run"
"$BIN" "$DATA/cat_f1500.obj" -o o.obj --report o.json --quiet --cut-strategy optcuts || fail "optcuts run"
python3 - e.json o.json <<'PY' || fail "reports not as expected"
import json, sys
e, o = (json.load(open(f)) for f in sys.argv[1:3])
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(e)))
check(e["status"] == "OK" and e["bound_met"] and e["e_sd"] <= 4.1, "status/bound")
check(e["cut_strategy"] == "ebcuts" and o["cut_strategy"] == "optcuts", "cut_strategy")
check(e["topology_operations"] >= 1, "no cut counted")
check(e["seam_length_normalized"] > o["seam_length_normalized"], "EBCuts seams not longer than OptCuts'")
PY
for args in "--cut-strategy foo" "--cut-strategy ebcuts --keep-seams" "--cut-strategy ebcuts --seam-weight 0.1"; do
  "$BIN" "$DATA/cat_f1500.obj" -o u.obj $args >out.txt 2>err.txt
  [ $? -eq 2 ] || fail "'$args': not a usage error"
  grep -q "cut-strategy" err.txt || fail "'$args': message $(cat err.txt)"
  [ ! -e u.obj ] || fail "'$args': an output was written"
done
echo "ok"
