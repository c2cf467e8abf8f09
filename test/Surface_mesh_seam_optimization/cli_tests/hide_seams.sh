#!/bin/bash
# --hide-seams: seam costs from visibility move the seams off the most
# visible quarter of the edges (visible_seam_share at most half the default
# run's, measured with --measure-visibility) for at most 1.3x the length,
# within the bound; not with --keep-seams.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" -o d.obj --report d.json --quiet --measure-visibility || fail "default run"
"$BIN" "$DATA/cat_f1500.obj" -o h.obj --report h.json --quiet --hide-seams || fail "hidden run"
"$BIN" "$DATA/cat_f1500.obj" -o p.obj --report p.json --quiet || fail "plain run"
python3 - d.json h.json p.json <<'PY' || fail "reports not as expected"
import json, sys
d, h, p = (json.load(open(f)) for f in sys.argv[1:4])
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (reports: %s / %s)" % (what, json.dumps(d), json.dumps(h)))
check(d["status"] == "OK" and h["status"] == "OK" and h["bound_met"] and h["bijective"], "status/bound")
check(d["hide_seams"] is False and h["hide_seams"] is True, "hide_seams flags")
check(p["visible_seam_share"] is None, "visible_seam_share measured without being asked: %r" % p["visible_seam_share"])
check(d["seam_length_normalized"] == p["seam_length_normalized"], "--measure-visibility changed the seams")
check(d["visible_seam_share"] > 0, "default seams not on visible edges: %r" % d["visible_seam_share"])
check(h["visible_seam_share"] <= 0.5 * d["visible_seam_share"],
      "visible share %r -> %r" % (d["visible_seam_share"], h["visible_seam_share"]))
check(h["seam_length_normalized"] <= 1.3 * d["seam_length_normalized"], "seams more than 1.3x longer")
check(h["weighted_seam_length_normalized"] >= h["seam_length_normalized"], "costs below 1")
PY
"$BIN" "$DATA/cat_f1500.obj" -o u.obj --hide-seams --keep-seams >out.txt 2>err.txt
[ $? -eq 2 ] || fail "--hide-seams --keep-seams: not a usage error"
grep -q "keep-seams" err.txt || fail "message: $(cat err.txt)"
[ ! -e u.obj ] || fail "an output was written"
echo "ok"
