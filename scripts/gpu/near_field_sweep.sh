#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): lumen's accuracy and cost against the screen probes'
# near-field distance. For SCENE (default atrium) at PRESET (default medium): a 256x256 reference
# (16,384 spp at pixel centres), then for each of DISTANCES (metres; "default" for the preset's)
# lumen's mean over the reference's and relMSE at 256x256, and the near-field trace's median GPU
# time at 1920x1080 (300 frames, medians after 100). Writes near_field.txt under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=$PWD/.devbin/lumina
scene=${SCENE:-atrium}
preset=${PRESET:-medium}
$lumina reference "$scene" --size 256x256 --spp 16384 --pixel-centres --out /tmp/nf_ref.exr >/dev/null 2>&1
for d in ${DISTANCES:-0 default 5 20 40}; do
  flag=""
  [ "$d" = default ] || flag="--near-field-distance $d"
  $lumina render "$scene" --preset "$preset" --size 256x256 $flag --exr /tmp/nf_$d.exr --out /tmp/nf.png >/dev/null 2>&1
  figures=$($lumina compare /tmp/nf_ref.exr /tmp/nf_$d.exr 2>&1 | awk '/^  relMSE/ { r = $2 }
    /^  mean / { gsub(/[(),]/, " "); printf "relMSE %s mean/reference %.4f", r, ($7 + $8 + $9) / ($3 + $4 + $5) }')
  cost=$($lumina render "$scene" --preset "$preset" --size 1920x1080 $flag --frames 300 --warmup 100 --timings \
    --out /tmp/nf.png 2>&1 | grep -E "near field|far field|shade rays" |
    awk '/skipped/ { sub(/^ *screen probes: /, ""); sub(/: skipped.*/, " skipped; "); printf "%s", $0; next }
      { m = $(NF - 3); sub(/^ *screen probes: /, ""); sub(/ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9]+$/, ""); printf "%s %s ms; ", $0, m }')
  echo "$scene $preset near field $d: $figures; 1080p: $cost"
done | tee "$out/near_field.txt"
