#!/bin/bash
# A missing or unreadable input: non-zero exit, one stderr line naming the file.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

check_one_line_error() { # $1: label, rest: arguments
  local label=$1; shift
  "$@" >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -ne 0 ] || fail "$label: exit code 0"
  [ "$rc" -lt 128 ] || fail "$label: killed by a signal (exit $rc)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$label: expected one stderr line, got: $(cat err.txt)"
  grep -q "^optimize_seams: error: " err.txt || fail "$label: bad message: $(cat err.txt)"
}

check_one_line_error "missing file" "$BIN" does_not_exist.obj
grep -q "does_not_exist.obj" err.txt || fail "the message does not name the file: $(cat err.txt)"
[ ! -e does_not_exist_uv.obj ] || fail "an output file was written"

check_one_line_error "directory" "$BIN" "$SCRATCH"
: >empty.obj
check_one_line_error "empty file" "$BIN" empty.obj
grep -qi "empty" err.txt || fail "empty file: message does not say empty: $(cat err.txt)"
printf 'not a mesh\n\001\002\n' >garbage.off
check_one_line_error "garbage" "$BIN" garbage.off
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >bad_index.obj
check_one_line_error "face index out of range" "$BIN" bad_index.obj
printf 'solid x\nendsolid x\n' >mesh.stl
check_one_line_error "unsupported format" "$BIN" mesh.stl

# The report is still written, with the failure in it.
"$BIN" does_not_exist.obj --report r.json 2>/dev/null
python3 - r.json <<'PY' || fail "report of a failed run is not as expected"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"].startswith("ERROR"), r["status"]
assert "does_not_exist.obj" in r["message"], r["message"]
PY
echo "ok"
