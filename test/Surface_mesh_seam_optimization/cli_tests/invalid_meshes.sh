#!/bin/bash
# Invalid meshes are refused with one clear line, never a crash:
# a non-manifold mesh (CGAL cannot represent it) and zero-area triangles
# (infinite distortion energy). No repair is attempted.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
TEST_DATA="$(cd "$(dirname "$0")/../data" && pwd)"
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

run_invalid() { # $1: mesh, $2: word the message must contain, $3: report status
  "$BIN" "$TEST_DATA/$1" --keep-seams --report r.json >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -eq 1 ] || fail "$1: exit code $rc, expected 1 (stderr: $(cat err.txt))"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$1: expected one stderr line, got: $(cat err.txt)"
  grep -q "^optimize_seams: error: " err.txt || fail "$1: bad message: $(cat err.txt)"
  grep -q "$2" err.txt || fail "$1: message does not mention '$2': $(cat err.txt)"
  [ ! -e "${1%.obj}_uv.obj" ] || fail "$1: an output OBJ was written"
  python3 -c 'import json,sys; r=json.load(open("r.json")); sys.exit(r["status"] != sys.argv[1])' "$3" \
    || fail "$1: report status is not $3: $(cat r.json)"
}

run_invalid non_manifold_toy.obj "manifold" ERROR_NON_MANIFOLD_MESH
run_invalid zero_area_triangles_48.obj "zero-area" ERROR_DEGENERATE_TRIANGLE
echo "ok"
