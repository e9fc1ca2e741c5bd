#!/bin/bash
# Install what is missing, build the programs and the test drivers, and run
# the CI test suite (everything not labelled validation-long or benchmark).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh --all
cd build
ctest --output-on-failure -LE "validation-long|benchmark" "$@"
