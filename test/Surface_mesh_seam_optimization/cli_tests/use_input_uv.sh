#!/bin/bash
# --use-input-uv: the optimizer's own output, read back with its UVs and
# re-optimized with the seams kept, is already optimal (same E_SD to 1e-5: the
# first run also minimized the scaffold's tiny energy, at most 3 iterations). An OBJ without texture coordinates is
# a one-line error with exit code 1; a mirrored (all flipped) map cannot be
# untangled: the default initial map replaces it, and a note says so.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" -o out.obj --report r1.json --quiet >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "first run: exit code $rc (stderr: $(cat err.txt))"
"$BIN" --keep-seams --use-input-uv out.obj -o again.obj --report r2.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--use-input-uv run: exit code $rc (stderr: $(cat err.txt))"
[ -s again.obj ] || fail "again.obj was not written"
python3 - r1.json r2.json <<'PY' || fail "report not as expected"
import json, sys
r1 = json.load(open(sys.argv[1]))
r2 = json.load(open(sys.argv[2]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r2)))
check(r2["status"] == "OK", "status is %r, not OK" % r2["status"])
check(r2["mode"] == "keep-seams", "mode %r" % r2["mode"])
check(r2["iterations"] <= 3, "%r iterations from an optimal map" % r2["iterations"])
check(r2["e_sd"] <= r1["e_sd"] * (1 + 1e-12), "e_sd grew")
check(abs(r2["e_sd"] - r1["e_sd"]) <= 1e-5 * r1["e_sd"], "e_sd %r, first run %r" % (r2["e_sd"], r1["e_sd"]))
check(abs(r2["initial_e_sd"] - r1["e_sd"]) <= 1e-6 * r1["e_sd"],
      "initial_e_sd %r is not the input map's %r" % (r2["initial_e_sd"], r1["e_sd"]))
check(r2["charts"] == r1["charts"], "charts %r vs %r" % (r2["charts"], r1["charts"]))
check(abs(r2["seam_length"] - r1["seam_length"]) <= 1e-9 * max(1, r1["seam_length"]),
      "seam_length %r vs %r" % (r2["seam_length"], r1["seam_length"]))
PY

one_line_error() {   # $1: what
  rc=$?
  [ "$rc" -eq 1 ] || fail "$1: exit code $rc, expected 1 (stderr: $(cat err.txt))"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$1: not one stderr line: $(cat err.txt)"
  grep -q "^optimize_seams: error: " err.txt || fail "$1: no error line: $(cat err.txt)"
}
# no texture coordinates
"$BIN" "$DATA/cat_f1500.obj" --use-input-uv -o x.obj >out.txt 2>err.txt
one_line_error "no UVs"
grep -qi "texture coordinate" err.txt || fail "no UVs: message does not say why: $(cat err.txt)"
# a mirrored (flipped) map
awk '$1 == "vt" { $2 = -$2 } 1' out.obj >flipped.obj
"$BIN" flipped.obj --use-input-uv --keep-seams -o x.obj >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "flipped map: exit code $rc (stderr: $(cat err.txt))"
grep -q "note: .*fell back to the default initial map" err.txt || fail "flipped map: no note: $(cat err.txt)"
[ -s x.obj ] || fail "flipped map: no output"
echo "ok"
