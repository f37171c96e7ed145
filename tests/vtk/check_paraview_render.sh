#!/bin/sh
# A mode shape of `bladebench run --vtk` rendered off-screen by ParaView (Debian's paraview and
# python3-paraview, pvbatch under xvfb-run): the PNG has the size asked and is not blank
# (render_mode.py). Arguments: BLADEBENCH CASE WORK. Label paraview (not in the default run:
# `apt-get install paraview python3-paraview xvfb`, then `ctest --preset paraview`).
set -eu
bin=$1 case=$2 work=$3
rm -rf "$work"
"$bin" run "$case" --vtk --no-plots --no-cache --out "$work/report" > "$work.log" 2>&1 || { cat "$work.log"; exit 1; }
xvfb-run -a pvbatch "$(dirname "$0")/render_mode.py" "$work/report/vtk/modes.vtu" mode_4 "$work/mode_4.png" 640 480
