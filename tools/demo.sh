#!/bin/sh
# tools/demo.sh [OUT_DIR]: runs every scene of the LÖVE lab (examples/demo) under every
# method in scripted mode, and the platformer's input scripts (examples/platformer),
# under a virtual X display, and checks each run's verdict (its exit status) and that its
# screenshot is a real picture (tools/png_check.py).
# Ends with "demo: N passed, N failed". Installs love, xvfb and python3 when missing.
set -u
cd "$(dirname "$0")/.." || exit 2
out=${1:-/tmp/budge-demo}
FRAMES=180
if [ -z "${BUDGE_IN_XVFB:-}" ]; then
  sh tools/deps.sh love xvfb-run python3 lua5.4 || exit 2
  mkdir -p "$out"
  BUDGE_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1024x768x24" sh tools/demo.sh "$out"
fi
passed=0
failed=0
# the method names, as budge's registry lists them
methods=$(lua5.4 -e 'package.path = "./src/?.lua;./src/?/init.lua;" .. package.path
  print(table.concat(require("budge").METHODS, " "))') || exit 2
# run NAME ARGS...: one scripted run; passes when it exits 0 and its PNG is a picture
# (GAME: the folder, examples/demo unless set)
run() {
  name=$1; shift
  png="$out/$name.png"
  rm -f "$png"
  if timeout 60 love "${GAME:-examples/demo}" "$@" --screenshot "$png" 2>"$out/stderr.log" \
      && python3 tools/png_check.py "$png" >"$out/check.log"; then
    passed=$((passed + 1))
  else
    grep -v XDG_RUNTIME_DIR "$out/stderr.log"; cat "$out/check.log" 2>/dev/null
    echo "FAILED: $name"
    failed=$((failed + 1))
  fi
}
for scene in platformer corners speed fatcross crowd; do
  for method in $methods; do
    run "$scene-$method" --scene "$scene" --method "$method" --frames "$FRAMES"
  done
done
# the interactive keys, pressed by the script: methods, scenes, restart, help
run keys --scene 1 --method seed --keys "20:m,40:m,60:3,80:tab,100:r,120:h,140:5" --frames 220
# the platformer's input scripts: their verdicts and their pictures
for script in playthrough deaths checkpoint; do
  GAME=examples/platformer run "platformer-$script" --script "$script"
done
echo "demo: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
