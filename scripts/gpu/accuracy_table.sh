#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): README's accuracy table. For every built-in scene,
# a path-traced reference (LUMINA_REFERENCE_SPP samples at pixel centres, default 65536), the
# direct-only image and lumen at every preset after convergence (what `lumina render` does without
# --frames), all at LUMINA_SIZE (default 256x256); then `lumina compare` of each against the
# reference. LUMINA_TECHNIQUES (default lumen) names the GI techniques measured the same way.
# A furnace (furnace_RHO: emission 1, albedo RHO, closed) is compared with its exact answer,
# 1 / (1 - RHO) everywhere (`lumina compare --exact`), and no reference is rendered for it: a path-traced
# reference's own noise was most of the relMSE there (furnace_0.99 at 1,024 spp) and hid the order
# of the presets.
# An animated scene is measured at its first pose, held still (--animation-frame 0), or at frame F
# where LUMINA_SCENES names it SCENE@F (`door@240`: the door open); its reference shows the same
# pose (`lumina reference --animation-frame`). Prints one markdown row per scene and technique: relMSE of direct-only, and for each preset the
# technique's relMSE, its ratio to direct-only's and its mean radiance over the reference's. Writes
# accuracy.txt (every compare in full) and accuracy.md (the table) under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
source scripts/gpu/scene_entry.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
scenes=${LUMINA_SCENES:-"cornell_box cornell_box_point open_top_box two_rooms sunlit_rooms furnace_0.5 furnace_0.8 furnace_0.95 furnace_0.99"}
presets=${LUMINA_PRESETS:-"low medium high"}
techniques=${LUMINA_TECHNIQUES:-lumen}
size=${LUMINA_SIZE:-256x256}
spp=${LUMINA_REFERENCE_SPP:-65536}

# relMSE and mean radiance (R, G, B averaged) of TEST against REF, as "relmse mean_test mean_ref".
# REF "exact:V" is the constant image of radiance V.
figures() {
  local ref=("$1")
  case "$1" in exact:*) ref=(--exact "${1#exact:}") ;; esac
  $lumina compare "${ref[@]}" "$2" 2>&1 | awk '
    /^  relMSE/ { r = $2 }
    /^  mean / { gsub(/[(),]/, " "); ref = ($3 + $4 + $5) / 3; test = ($7 + $8 + $9) / 3 }
    END { printf "%s %.6g %.6g\n", r, test, ref }'
}

{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown), $size, reference $spp spp"
  $lumina --list-devices 2>&1 | head -3
} | tee "$out/accuracy.txt"
header="| scene | technique | direct relMSE"
rule="|---|---|---:"
for preset in $presets; do
  header="$header | $preset relMSE | $preset / direct | $preset mean / reference"
  rule="$rule|---:|---:|---:"
done
echo "$header |" >"$out/accuracy.md"
echo "$rule|" >>"$out/accuracy.md"
for entry in $scenes; do
  scene_entry "$entry"
  ref=/tmp/ref_$entry_name.exr
  label=""
  [ "$entry" = "$scene" ] || label=" (frame $frame)"
  case "$scene" in
    furnace_*)
      ref=exact:$(awk -v rho="${scene#furnace_}" 'BEGIN { printf "%.9g", 1 / (1 - rho) }')
      echo "$scene: against the exact answer, ${ref#exact:} everywhere" >>"$out/accuracy.txt" ;;
    *) cached_reference "$ref" "$size" "$spp" >>"$out/accuracy.txt" ;;
  esac
  timeout 120 $lumina render "$scene" --technique direct --size "$size" --frames 1 $pose --exr "/tmp/direct_$entry_name.exr" \
    --out "/tmp/direct_$entry_name.png" >/dev/null 2>&1
  read -r directRel _ _ < <(figures "$ref" "/tmp/direct_$entry_name.exr")
  for technique in $techniques; do
    row="| \`$scene\`$label | $technique | $directRel"
    for preset in $presets; do
      exr=/tmp/${technique}_${entry_name}_$preset.exr
      timeout 600 $lumina render "$scene" --technique "$technique" --preset "$preset" --size "$size" $pose --exr "$exr" \
        --out "/tmp/${technique}_${entry_name}_$preset.png" 2>&1 | grep -E '^(frames|surface)' >>"$out/accuracy.txt"
      read -r rel mean refMean < <(figures "$ref" "$exr")
      echo "$entry $technique $preset: relMSE $rel (direct $directRel), mean $mean (reference $refMean)" |
        tee -a "$out/accuracy.txt"
      row="$row | $rel | $(awk -v a="$rel" -v b="$directRel" 'BEGIN { printf "%.3f", a / b }') | $(awk -v a="$mean" -v b="$refMean" 'BEGIN { printf "%.3f", a / b }')"
    done
    echo "$row |" >>"$out/accuracy.md"
  done
done
cat "$out/accuracy.md"
(cd /tmp && tar czf "$out/accuracy_images.tgz" ./*_*_*.png direct_*.png 2>/dev/null)
