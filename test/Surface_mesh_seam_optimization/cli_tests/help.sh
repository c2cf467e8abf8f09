#!/bin/bash
# --help: exit 0, usage on stdout, every option listed, nothing on stderr.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

for flag in --help -h; do
  "$BIN" $flag >out.txt 2>err.txt
  rc=$?
  [ "$rc" -eq 0 ] || fail "$flag: exit code $rc, expected 0"
  [ ! -s err.txt ] || fail "$flag: unexpected stderr: $(cat err.txt)"
  grep -q "^Usage: optimize_seams INPUT" out.txt || fail "$flag: no usage line"
  for opt in -o --output --distortion-bound --seam-weight --no-bijectivity --keep-seams --report \
             --quiet --max-iterations --recut-rounds --starts --normalize --use-input-uv --time-limit --energy --threads \
             --repair --svg --png --help; do
    grep -q -- "$opt\b" out.txt || fail "$flag: option $opt is not listed"
  done
  grep -q "default" out.txt || fail "$flag: defaults are not given"
  grep -q "default: 4.1" out.txt || fail "$flag: the default bound 4.1 is not given"
  grep -q "default: symmetric_dirichlet" out.txt || fail "$flag: the default energy is not given"
  ! grep -qi "not implemented yet" out.txt || fail "$flag: still says something is not implemented"
done
echo "ok"
