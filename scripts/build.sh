#!/bin/bash
# Configure (Release) and build in ./build: the programs levelsinter and
# levelsinter-pack; with --all also the test drivers (scripts/run_tests.sh).
# ccache, if installed, caches the compilations across rebuilds.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=(--target levelsinter levelsinter-pack)
if [ "${1:-}" = "--all" ]; then
  targets=()
elif [ $# -gt 0 ]; then
  echo "usage: scripts/build.sh [--all]" >&2
  exit 2
fi
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)" "${targets[@]}" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
