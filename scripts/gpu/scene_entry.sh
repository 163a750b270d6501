# Sourced by the accuracy scripts that run on the lent GPU machine (accuracy_table.sh,
# accuracy_variants.sh, stored_references.sh), with $lumina set.

# scene_entry ENTRY: ENTRY names a built-in scene, or SCENE@F for that scene posed at frame F of
# its animation. Sets scene, frame, entry_name (SCENE, or SCENE_frameF as tests/frame/stored_reference.h
# names the pose) and pose: the flag that holds an animated scene still at that frame (its first
# pose by default: played, atrium_day's sun moved on and its means read 10 % low), empty for a
# still scene. `lumina reference` and `lumina render` take the same flag, so a reference and the
# images measured against it show the same pose.
scene_entry() {
  scene=${1%@*}
  frame=0
  entry_name=$scene
  if [ "$1" != "$scene" ]; then
    frame=${1#*@}
    entry_name=${scene}_frame$frame
  fi
  pose=""
  if $lumina info "$scene" 2>/dev/null | grep '^  animation' | grep -qv ' none$'; then
    pose="--animation-frame $frame"
  fi
}

# cached_reference REF SIZE SPP: $scene's path-traced reference at $pose (pixel centres) in REF.
# One an earlier call on this (still warm) machine made under the same name, size and samples is
# reused: the references are most of a call's time. Prints the reference's last line when it
# renders one.
cached_reference() {
  local ref=$1 size=$2 spp=$3
  if [ ! -s "$ref.$size.$spp" ]; then
    # shellcheck disable=SC2086 # pose is words
    timeout 600 $lumina reference "$scene" --size "$size" --spp "$spp" --pixel-centres $pose --out "$ref" 2>&1 |
      tail -1
    cp "$ref" "$ref.$size.$spp"
  fi
  cp "$ref.$size.$spp" "$ref"
}
