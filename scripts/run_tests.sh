#!/usr/bin/env bash
# The README's second command: install what is missing, build everything in
# Release with the tests, run the whole CTest suite. Exit code = ctest's.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON
cmake --build build -j2

set +e
ctest --test-dir build --output-on-failure
rc=$?
set -e
exit "$rc"
