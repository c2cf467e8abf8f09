#!/bin/bash
# The seam options: invalid values and conflicts are usage errors (exit 2, one
# stderr line, no output); --keep-seams keeps the distortion-only mode.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

usage_error() { # $1: word the message must contain, rest: arguments
  local word=$1; shift
  "$BIN" "$DATA/cat_f1500.obj" -o u.obj --report u.json "$@" >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -eq 2 ] || fail "'$*': exit code $rc, expected 2 (stderr: $(cat err.txt))"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*': expected one stderr line, got: $(cat err.txt)"
  grep -q "^optimize_seams: error: " err.txt || fail "'$*': bad message: $(cat err.txt)"
  grep -q -- "$word" err.txt || fail "'$*': message does not mention '$word': $(cat err.txt)"
  [ ! -e u.obj ] && [ ! -e u.json ] || fail "'$*': an output file was written"
}

usage_error "> 4" --distortion-bound 3.5
usage_error "> 4" --distortion-bound 4
usage_error "> 4" --distortion-bound=abc
usage_error "> 4" --distortion-bound inf
usage_error "> 2 (the minimum of conformal)" --energy conformal --distortion-bound 1.5
usage_error "> 0 (the minimum of arap)" --distortion-bound 0 --energy arap
usage_error "area term of '--energy conformal' only" --area-weight 0.1
usage_error "area term of '--energy conformal' only" --area-weight 0.1 --energy arap
usage_error "needs a number >= 0" --area-weight -1 --energy conformal
usage_error "\[0, 1)" --seam-weight 1.5
usage_error "applies to the distortion bound" --proxy-faces 400 --seam-weight 0.1
usage_error "non-negative integer" --proxy-faces -3
usage_error "\[0, 1)" --seam-weight -0.1
usage_error "\[0, 1)" --seam-weight 1
usage_error "exclusive" --distortion-bound 4.2 --seam-weight 0.1
usage_error "keep-seams" --keep-seams --distortion-bound 4.2
usage_error "keep-seams" --seam-weight 0.1 --keep-seams
usage_error "no-bijectivity" --no-bijectivity=1
usage_error "recut-rounds" --recut-rounds -1
usage_error "recut-rounds" --recut-rounds abc
usage_error "keep-seams" --keep-seams --recut-rounds 2
usage_error "seam-weight" --seam-weight 0.1 --recut-rounds 2
usage_error "1, 2, 3 or 4" --starts 0
usage_error "1, 2, 3 or 4" --starts 5
usage_error "1, 2, 3 or 4" --starts abc
usage_error "keep-seams" --keep-seams --starts 2
usage_error "seam-weight" --seam-weight 0.1 --starts 1
# an option where a value should be is no value (a file name starting with
# "--" is given as --svg=--name)
usage_error "needs a value, not the option '--quiet'" --svg --quiet
usage_error "needs a value, not the option '--keep-seams'" --seam-weight --keep-seams

# --keep-seams: the distortion-only mode, no topology operation, no lambda, no bound.
"$BIN" "$DATA/cat_f1500.obj" --keep-seams -o k.obj --report k.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--keep-seams: exit code $rc (stderr: $(cat err.txt))"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "--keep-seams: expected only the summary, got: $(cat err.txt)"
python3 - k.json k.obj <<'PY' || fail "--keep-seams report or OBJ not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
def check(cond, what):
    if not cond:
        sys.exit("FAIL: %s (report: %s)" % (what, json.dumps(r)))
check(r["status"] == "OK", "status %r" % r["status"])
check(r["mode"] == "keep-seams", "mode %r" % r["mode"])
check(r["topology_operations"] == 0, "topology_operations %r" % r["topology_operations"])
check(r["seam_length_normalized"] == 0 and r["charts"] == 1, "seams in keep-seams mode on a disk")
check(r["lambda"] is None and r["bound_met"] is None and r["distortion_bound"] is None
      and r["seam_weight"] is None, "lambda/bound figures in keep-seams mode")
check(4.0 <= r["e_sd"] < r["initial_e_sd"], "e_sd %r" % r["e_sd"])
v = sum(1 for l in open(sys.argv[2]) if l.startswith("v "))
vt = sum(1 for l in open(sys.argv[2]) if l.startswith("vt "))
check(v == vt == r["vertices"], "%d v, %d vt: the disk was cut" % (v, vt))
PY

# A different bound reaches the report (and the seams get shorter with a looser one).
"$BIN" "$DATA/cat_f1500.obj" --distortion-bound 4.5 --quiet -o b45.obj --report b45.json || fail "--distortion-bound 4.5 failed"
"$BIN" "$DATA/cat_f1500.obj" --quiet -o b41.obj --report b41.json || fail "default bound failed"
python3 - b45.json b41.json <<'PY' || fail "--distortion-bound 4.5 not as expected"
import json, sys
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert a["distortion_bound"] == 4.5 and a["bound_met"] is True and a["e_sd"] <= 4.5, a
assert a["seam_length_normalized"] < b["seam_length_normalized"], (a["seam_length_normalized"], b["seam_length_normalized"])
PY

# --recut-rounds 0: the first result alone, whose seams the default rounds shorten on the cat
# (one start each: the rounds of a start, not the choice between starts).
"$BIN" "$DATA/cat_f1500.obj" --recut-rounds 0 --starts 1 --quiet -o r0.obj --report r0.json || fail "--recut-rounds 0 failed"
"$BIN" "$DATA/cat_f1500.obj" --starts 1 --quiet -o s1.obj --report s1.json || fail "--starts 1 failed"
python3 - r0.json s1.json <<'PY' || fail "--recut-rounds 0 not as expected"
import json, sys
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert a["bound_met"] is True and a["e_sd"] <= 4.1, a
assert a["iterations"] < b["iterations"], (a["iterations"], b["iterations"])
assert a["seam_length_normalized"] > b["seam_length_normalized"], (a["seam_length_normalized"], b["seam_length_normalized"])
PY

# --starts: on the cat the hold-price start's seams (start 1, the fourth taken) are the shorter
# (1.746 against 1.757), and four starts keep them; --starts 1 is the first start alone.
"$BIN" "$DATA/cat_f1500.obj" --starts 4 --quiet -o s4.obj --report s4.json || fail "--starts 4 failed"
python3 - s1.json s4.json <<'PY' || fail "--starts not as expected"
import json, sys
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert a["start"] == 0 and b["start"] == 1, (a["start"], b["start"])
assert a["bound_met"] is True and b["bound_met"] is True, (a, b)
assert b["seam_length_normalized"] < a["seam_length_normalized"], (a["seam_length_normalized"], b["seam_length_normalized"])
PY
# --proxy-faces: the cat (1499 faces) through a proxy of about 400 faces; the
# result meets the bound without overlap, its report gives the proxy's size;
# a mesh at most twice the proxy size runs directly.
"$BIN" "$DATA/cat_f1500.obj" --proxy-faces 400 --quiet -o p.obj --report p.json || fail "--proxy-faces failed"
"$BIN" "$DATA/cat_f1500.obj" --proxy-faces 750 --starts 1 --quiet -o p750.obj --report p750.json || fail "--proxy-faces 750 failed"
python3 - p.json p750.json <<'PY' || fail "--proxy-faces not as expected"
import json, sys
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert 0 < a["proxy_faces"] <= 440, a["proxy_faces"]
assert a["bound_met"] is True and a["e_sd"] <= 4.1 and a["bijective"] is True, a
assert b["proxy_faces"] == 0, b["proxy_faces"]
PY
echo "ok"
