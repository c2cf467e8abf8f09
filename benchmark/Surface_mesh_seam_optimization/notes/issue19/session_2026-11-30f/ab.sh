#!/bin/bash
# ab.sh OUT binA binB meshes...
out=$1; a=$2; b=$3; shift 3
mkdir -p $out/a $out/b
for m in "$@"; do
  $a --no-header --out-dir $out/a /work/shared/data/benchmark/$m.obj 2>/dev/null | sed 's/^/A,/' >> $out/res.csv
  $b --no-header --out-dir $out/b /work/shared/data/benchmark/$m.obj 2>/dev/null | sed 's/^/B,/' >> $out/res.csv
done
