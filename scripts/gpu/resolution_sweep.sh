#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): how a scene's accuracy depends on the image size.
# For each scene (SCENES, default atrium) and size (SIZES, default "128 256 512"), a path-traced
# reference with its direct-light channels (--aovs, SPP samples at pixel centres, default 16384),
# the direct-only image and lumen at each of PRESETS (default "low high") after convergence; prints
# each image's mean radiance (R, G, B) against the reference's. Writes sweep.txt and the EXRs
# (sweep_exr.tgz) under $OUT. docs/bench/h200/atrium_image_size_8282716.txt is its output.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
means() {
  $lumina compare "$1" "$2" 2>&1 | awk '/^  mean / { gsub(/[(),]/, " ");
    printf "ref %.5f test %.5f ratio %.4f", ($3 + $4 + $5) / 3, ($7 + $8 + $9) / 3, ($7 + $8 + $9) / ($3 + $4 + $5) }'
}
for scene in ${SCENES:-atrium}; do
  for n in ${SIZES:-128 256 512}; do
    ref=/tmp/ref_${scene}_$n.exr
    $lumina reference "$scene" --size "${n}x$n" --spp "${SPP:-16384}" --pixel-centres --aovs --out "$ref" >/dev/null 2>&1
    $lumina render "$scene" --technique direct --size "${n}x$n" --frames 1 --exr "/tmp/d_${scene}_$n.exr" \
      --out /tmp/direct.png >/dev/null 2>&1
    echo "$scene $n direct: $(means "$ref" "/tmp/d_${scene}_$n.exr")"
    for preset in ${PRESETS:-low high}; do
      $lumina render "$scene" --preset "$preset" --size "${n}x$n" --exr "/tmp/l_${scene}_${n}_$preset.exr" \
        --out /tmp/lumen.png >/dev/null 2>&1
      echo "$scene $n lumen $preset: $(means "$ref" "/tmp/l_${scene}_${n}_$preset.exr")"
    done
  done
done 2>&1 | tee "$out/sweep.txt"
(cd /tmp && tar czf "$out/sweep_exr.tgz" ref_*.exr d_*.exr l_*.exr)
