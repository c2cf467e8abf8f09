#!/bin/bash
# Nothing lost on output: every output path is checked before the run (a
# usage error, exit 2, in well under a second, nothing written); outputs are
# written to a temporary file renamed over the target, so a failed write
# leaves the previous file intact and no temporary file behind.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -rf ./* ./.[!.]*
fail() { echo "FAIL: $*" >&2; exit 1; }
MESH="$DATA/cat_f1500.obj"

usage_error() { # $1: text the message must contain; then the arguments
  local want=$1; shift
  local before=$(ls -A | grep -v -x -e out.txt -e err.txt)
  local t0=$(date +%s%N)
  "$BIN" "$@" >out.txt 2>err.txt
  local rc=$? ms=$(( ($(date +%s%N) - t0) / 1000000 ))
  [ "$rc" -eq 2 ] || fail "'$*': exit code $rc, expected 2 (stderr: $(cat err.txt))"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*': expected one stderr line, got: $(cat err.txt)"
  grep -qF -- "$want" err.txt || fail "'$*': message does not say '$want': $(cat err.txt)"
  ((ms < 3000)) || fail "'$*': took $ms ms, the paths were not checked before the run"
  [ "$(ls -A | grep -v -x -e out.txt -e err.txt)" = "$before" ] || fail "'$*': wrote something: $(ls -A)"
}

usage_error "cannot write 'no/such/dir/r.json' (option '--report'): directory 'no/such/dir' does not exist" \
  "$MESH" -o a.obj --report no/such/dir/r.json
touch keep.txt
usage_error "cannot write 'keep.txt/x.png' (option '--png'): directory 'keep.txt' does not exist" \
  "$MESH" -o a.obj --png keep.txt/x.png
mkdir keepdir
usage_error "cannot write 'keepdir' (option '--svg'): it is a directory" "$MESH" -o a.obj --svg keepdir
usage_error "option '-o' writes an OBJ (the format with per-corner UVs): 'a.ply' does not end in .obj" \
  "$MESH" -o a.ply
usage_error "options '-o' and '--report' name the same file './a.obj'" "$MESH" -o a.obj --report ./a.obj
usage_error "options '--report' and '--svg' name the same file 'r'" "$MESH" -o a.obj --report r --svg r
usage_error "option '--png' would overwrite the input '$MESH'" "$MESH" -o a.obj --png "$MESH"
cp "$MESH" in.obj
usage_error "option '-o' would overwrite the input 'in.obj'" in.obj -o "$SCRATCH/in.obj"
rm -f in.obj

# A failed write (file size limit; SIGXFSZ ignored so that write() fails)
# keeps the previous output and leaves no temporary file.
echo "previous" >keep_out.obj
( trap '' XFSZ; ulimit -f 2; exec "$BIN" "$MESH" --keep-seams -o keep_out.obj --quiet ) >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 1 ] || fail "failed write: exit code $rc, expected 1 (stderr: $(cat err.txt))"
grep -qF "cannot write 'keep_out.obj'" err.txt || fail "failed write: $(cat err.txt)"
[ "$(cat keep_out.obj)" = "previous" ] || fail "failed write: the previous output was changed"
[ -z "$(ls -A | grep -F '.tmp-')" ] || fail "failed write: temporary file left: $(ls -A)"

# A successful run replaces the previous files whole, with the usual permissions.
umask 022
echo "previous" >keep_out.obj
"$BIN" "$MESH" --keep-seams -o keep_out.obj --report keep_r.json --svg keep.svg --quiet >out.txt 2>err.txt \
  || fail "run: $(cat err.txt)"
[ "$(grep -c '^f ' keep_out.obj)" -eq 1499 ] || fail "run: the OBJ does not have the 1499 faces"
python3 -c 'import json; r = json.load(open("keep_r.json")); assert r["status"] == "OK"' || fail "run: report"
grep -q '</svg>' keep.svg || fail "run: the SVG is not complete"
[ "$(stat -c %a keep_out.obj)" = 644 ] && [ "$(stat -c %a keep_r.json)" = 644 ] || fail "run: permissions"
[ -z "$(ls -A | grep -F '.tmp-')" ] || fail "run: temporary file left: $(ls -A)"

# Through a link, the link's target is replaced (the link stays); a device
# (/dev/stdout) is written in place.
echo "previous" >target.json
ln -s target.json link.json
"$BIN" "$MESH" --keep-seams -o keep_out.obj --report link.json --quiet >out.txt 2>err.txt || fail "link: $(cat err.txt)"
[ -L link.json ] && grep -q '"status": "OK"' target.json || fail "link: the link or its target is wrong"
"$BIN" "$MESH" --keep-seams -o keep_out.obj --report /dev/stdout --quiet >out.txt 2>err.txt || fail "stdout: $(cat err.txt)"
python3 -c 'import json; assert json.load(open("out.txt"))["status"] == "OK"' || fail "--report /dev/stdout: $(cat out.txt)"
echo "ok"
