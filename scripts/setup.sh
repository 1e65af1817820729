#!/usr/bin/env bash
# The first README command: install what is missing, build (Release), render the default
# scene with the reference path tracer (lesson 3's solution, 64 samples per pixel) to
# build/cornell-box.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
./build/pathspace render scenes/cornell-box.scene --algo pt --spp 64 --out build/cornell-box.png
echo "pathspace: open build/cornell-box.png"
