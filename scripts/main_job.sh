#!/usr/bin/env bash
# The README's first command: install what is missing, build optimize_seams in
# Release, run it on the mesh shipped in data/ (OBJ with UVs, SVG of the UV
# layout, PNG of the textured model, JSON report), print the report, and judge
# the output with ../shared/tools/uvmetrics.py when that evaluator is beside
# the repository. Idempotent; fast when already built.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target optimize_seams -j2

mesh=data/bimba_i_f10000.obj
mkdir -p out
build/cli/optimize_seams "$mesh" -o out/bimba.obj --report out/bimba.json \
  --svg out/bimba.svg --png out/bimba.png

echo
echo "== report: out/bimba.json"
cat out/bimba.json
echo

uvmetrics=../shared/tools/uvmetrics.py
if [[ -f $uvmetrics ]]; then
  echo "== ../shared/tools/uvmetrics.py out/bimba.obj"
  python3 "$uvmetrics" out/bimba.obj --reference "$mesh" --bound 4.1
fi
