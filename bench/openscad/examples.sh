#!/bin/sh
# Render time of every example OpenSCAD ships, at 512x512: capsim (which runs
# OpenSCAD's CSG export first, timed apart in the second column) against
# OpenSCAD's own PNG, previewed (OpenCSG) and rendered (--render, CGAL), under
# xvfb-run. One run each, wall-clock seconds; a run past the time limit shows
# as ">LIMIT", one that fails as "fails". Prints a Markdown table.
#
#   sh bench/openscad/examples.sh ./build/capsim [EXAMPLES_DIR] [LIMIT_SECONDS]
set -u
capsim=${1:?usage: examples.sh CAPSIM [EXAMPLES_DIR] [LIMIT_SECONDS]}
examples=${2:-/usr/share/openscad/examples}
limit=${3:-600}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The wall-clock seconds of a command, ">LIMIT" past the limit, "fails" on failure.
seconds() {
  start=$(date +%s.%N)
  timeout "$limit" "$@" >/dev/null 2>&1
  rc=$?
  end=$(date +%s.%N)
  if [ "$rc" -eq 124 ]; then echo ">$limit"; elif [ "$rc" -ne 0 ]; then echo "fails"; else
    echo "$start $end" | awk '{ printf "%.2f", $2 - $1 }'; fi
}

echo "| Example | capsim | its CSG export | OpenSCAD preview | OpenSCAD --render |"
echo "|---|---:|---:|---:|---:|"
find "$examples" -name '*.scad' | sort | while read -r f; do
  name=${f#"$examples"/}
  ours=$(seconds "$capsim" render "$f" -o "$work/capsim.png" --size 512x512 --quiet)
  export_csg=$(seconds openscad -o "$work/model.csg" "$f")
  preview=$(seconds xvfb-run -a openscad -o "$work/preview.png" --imgsize=512,512 "$f")
  full=$(seconds xvfb-run -a openscad --render -o "$work/render.png" --imgsize=512,512 "$f")
  echo "| ${name%.scad} | $ours | $export_csg | $preview | $full |"
done
