#!/usr/bin/env bash
# Regenerates docs/images/*.svg from the examples: configures a small build (examples only) in
# build-images/, builds it, and runs the `images` target, which writes into docs/images/.
# Usage: bash examples/make_images.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmake -S "$root" -B "$root/build-images" -DCMAKE_BUILD_TYPE=Release \
      -DQUAT_BUILD_TESTS=OFF -DQUAT_BUILD_BENCH=OFF -DQUAT_BUILD_FUZZ=OFF -DQUAT_BUILD_DOCS=OFF \
      -DQUAT_BUILD_ACCURACY=OFF -DQUAT_BUILD_EXAMPLES=ON -DQUAT_INSTALL=OFF >/dev/null
cmake --build "$root/build-images" --target images -j 2
ls -1 "$root/docs/images"
