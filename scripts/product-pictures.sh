#!/usr/bin/env bash
# Regenerates the pictures of the map products in doc/images/ from one run of
# planar-mapper on the bundled sample: the report's renders and charts
# (report-*.png), viewer.html in headless Chromium (viewer.png, with the raw
# points toggled on: viewer-points.png) and the --gui window under Xvfb
# (gui-live.png, gui-final.png via scripts/gui-screenshot.sh).
# Usage: scripts/product-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$build/bin/planar-mapper" --out "$work/out" -q
cp "$work/out/report/map_perspective.png" doc/images/report-perspective.png
cp "$work/out/report/map_top.png" doc/images/report-top.png
cp "$work/out/report/em_per_scan.png" doc/images/report-em-per-scan.png
"$build/bin/planar-mapper" --mode offline --out "$work/offline" -q
cp "$work/offline/report/em_iterations.png" doc/images/report-em-iterations.png
node tools/viewer/screenshot.js "$work/out/viewer.html" doc/images/viewer.png
node tools/viewer/screenshot.js "$work/out/viewer.html" doc/images/viewer-points.png --points
scripts/gui-screenshot.sh "$build"
