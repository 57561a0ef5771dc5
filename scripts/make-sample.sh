#!/usr/bin/env bash
# Regenerates the bundled sample share/sample/default-L.* : the first 30 s of
# the default world (seed 1), with camera images.
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build}/bin"
rm -rf share/sample/default-L*
mkdir -p share/sample
"$bin/indoor-sim" --seed 1 --duration 30 --quiet --out share/sample/default-L
du -sh share/sample/*
