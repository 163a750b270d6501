#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): issue 20's scaling curves, every run `lumina render`
# without validation, 200 frames of which the first 100 are left out, per-pass JSON:
#   pixels:    cornell_box and atrium, lumen medium, 640x360 to 3840x2160;
#   triangles: the generated city with 40 to 8000 buildings (about 0.1 M to 20 M triangles drawn),
#              lumen medium and direct at 1920x1080 (the GI passes should stay flat);
#   rays:      cornell_box, lumen medium at 1920x1080, 16 to 256 rays per screen probe.
# scripts/plot_scaling.py draws them (the GPU machine has no matplotlib). Writes $OUT/scaling.tgz.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
dir=$out/scaling
mkdir -p "$dir"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
deadline=$(( $(date +%s) + ${LUMINA_SCALING_BUDGET_S:-500} ))
# run NAME SCENE ARGS...: one render into $dir/NAME.json, unless past the time budget.
run() {
  local name=$1 scene=$2
  shift 2
  echo "== $name"
  if [ "$(date +%s)" -ge "$deadline" ]; then echo "skipped: past the time budget"; return; fi
  timeout 240 $lumina render "$scene" --frames 200 --warmup 100 --timings-json "$dir/$name.json" \
    --out "/tmp/$name.png" "$@" 2>&1 | grep -E "^(scene|GPU memory|error)"
  echo "exit ${PIPESTATUS[0]}"
}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  for scene in cornell_box atrium; do
    for size in 640x360 1280x720 1920x1080 2560x1440 3840x2160; do
      run "pixels_${scene}_${size}" "$scene" --technique lumen --preset medium --size "$size"
    done
  done
  for buildings in 40 160 400 1024 2000 4000 8000; do
    printf '{"generator": "city", "instances": %d, "metresPerUnit": 1.0}\n' "$buildings" >"/tmp/city_$buildings.json"
    for technique in lumen direct; do
      run "triangles_${technique}_$buildings" "/tmp/city_$buildings.json" --technique "$technique" --preset medium \
        --size 1920x1080
    done
  done
  for rays in 16 32 64 128 256; do
    run "rays_cornell_box_$rays" cornell_box --technique lumen --preset medium --size 1920x1080 --rays-per-probe "$rays"
  done
} 2>&1 | tee "$dir/scaling.log"
(cd "$out" && tar czf scaling.tgz scaling && rm -rf scaling)
