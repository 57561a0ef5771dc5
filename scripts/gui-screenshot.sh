#!/usr/bin/env bash
# Screenshots of `planar-mapper --gui` (MRPT's 3D window) under Xvfb, on the
# bundled sample: doc/images/gui-live.png mid-run (growing map, current scan,
# robot) and doc/images/gui-final.png (the final textured map); and
# doc/images/gui-loops.png: the default building driven there and back
# (config/worlds/default-return.json) with loop closure on, at the end: the
# accepted loop closures as magenta lines.
# MRPT 2.5.8's own window capture (CDisplayWindow3D::getLastWindowImage)
# returns a black image under Mesa, so the X screen is grabbed with xwd.
# Needs: xvfb xauth x11-apps netpbm.   Usage: scripts/gui-screenshot.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(realpath "${1:-build}/bin")"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p doc/images

"$bin/indoor-sim" --world config/worlds/default-return.json --no-cameras --quiet --out "$work/ret"

cat > "$work/inner.sh" <<INNER
#!/usr/bin/env bash
set -euo pipefail
grab() { xwd -root -silent | xwdtopnm 2>/dev/null | pnmcut 0 0 1024 720 | pnmtopng > "\$1"; }
"$bin/planar-mapper" --out "$work/out" --gui --gui-hold 8 --playback-rate 2 -q &
pid=\$!
sleep 9
grab doc/images/gui-live.png
while [ ! -f "$work/out/summary.json" ]; do sleep 0.5; done
sleep 3
grab doc/images/gui-final.png
wait \$pid
"$bin/planar-mapper" --config "$PWD/config/default.ini" --rawlog "$work/ret.rawlog" --out "$work/loops" \
  --gui --gui-hold 8 -q &
pid=\$!
while [ ! -f "$work/loops/summary.json" ]; do sleep 0.5; done
sleep 3
grab doc/images/gui-loops.png
wait \$pid
INNER
chmod +x "$work/inner.sh"
xvfb-run -a -s "-screen 0 1280x1024x24 +extension GLX" "$work/inner.sh"
echo "wrote doc/images/gui-live.png doc/images/gui-final.png doc/images/gui-loops.png"
