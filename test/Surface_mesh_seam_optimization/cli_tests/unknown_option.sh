#!/bin/bash
# An unknown option is a usage error: exit 2, exactly one line on stderr, no output file.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/bimba_i_f10000.obj" --no-such-option >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 2 ] || fail "exit code $rc, expected 2 (stderr: $(cat err.txt))"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "expected exactly one stderr line, got: $(cat err.txt)"
grep -q -- "--no-such-option" err.txt || fail "the message does not name the option: $(cat err.txt)"
grep -q "^optimize_seams: error: " err.txt || fail "message not prefixed 'optimize_seams: error: ': $(cat err.txt)"
[ ! -s out.txt ] || fail "unexpected stdout: $(cat out.txt)"
[ ! -e bimba_i_f10000_uv.obj ] || fail "an output file was written despite the usage error"

# Other usage errors behave the same.
for args in "" "--max-iterations abc $DATA/bimba_i_f10000.obj" "$DATA/bimba_i_f10000.obj --report" \
            "--quiet=yes $DATA/bimba_i_f10000.obj" "a.obj b.obj"; do
  # shellcheck disable=SC2086
  "$BIN" $args >out.txt 2>err.txt
  rc=$?
  [ "$rc" -eq 2 ] || fail "'$args': exit code $rc, expected 2"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$args': expected one stderr line, got: $(cat err.txt)"
done
echo "ok"
