#!/usr/bin/env bash
# On a machine with many cores (the lent GPU machine's 16, docs/gpu.md): every fuzzer of
# .fuzz/ (scripts/gpu/package_fuzzers.sh) at once, each in libFuzzer's fork mode with
# LUMINA_FUZZ_WORKERS processes (default 3) for LUMINA_FUZZ_SECONDS (default 540), with the
# options of the CI runs (tests/fuzz/run_fuzzer.cmake). A corpus left in .fuzz/corpus/ by an
# earlier run is carried on. Writes $OUT/fuzz.tgz (the logs, the grown corpora, any crash
# input) and prints each fuzzer's final statistics.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
fuzz=$root/.fuzz
out=${OUT:-$PWD/fuzz-out}
seconds=${LUMINA_FUZZ_SECONDS:-540}
workers=${LUMINA_FUZZ_WORKERS:-3}
mkdir -p "$out" "$fuzz/corpus" "$fuzz/logs" "$fuzz/artifacts"
export LD_LIBRARY_PATH=$fuzz/lib
echo "fuzz_long: $(nproc) cores, $workers workers a fuzzer, $seconds s, commit $(cat "$root/.devbin/commit" 2>/dev/null || echo unknown)"
declare -A dicts=([gltf_loader]=gltf [scene_file]=scene_file [exr_openexr]=exr [exr_tinyexr]=exr [cli_args]=cli_args)
pids=()
for bin in "$fuzz"/bin/*_fuzzer; do
  name=$(basename "$bin" _fuzzer)
  mkdir -p "$fuzz/corpus/$name" "$fuzz/artifacts/$name"
  dict=()
  [ -n "${dicts[$name]:-}" ] && dict=(-dict="$fuzz/dict/${dicts[$name]}.dict")
  (cd "$fuzz/artifacts/$name" &&
    "$bin" -fork="$workers" -ignore_crashes=1 -max_total_time="$seconds" -max_len=65536 -timeout=20 \
      -rss_limit_mb=2048 -detect_leaks="${LUMINA_FUZZ_DETECT_LEAKS:-1}" -print_final_stats=1 "${dict[@]}" \
      -artifact_prefix="$fuzz/artifacts/$name/" "$fuzz/corpus/$name" "$fuzz/seeds/$name" \
      >"$fuzz/logs/$name.log" 2>&1; echo "exit $?" >>"$fuzz/logs/$name.log") &
  pids+=($!)
done
wait "${pids[@]}"
for log in "$fuzz"/logs/*.log; do
  name=$(basename "$log" .log)
  echo "== $name: $(ls "$fuzz/corpus/$name" | wc -l) corpus files, $(ls "$fuzz/artifacts/$name" | grep -c -E '^(crash|leak|oom|timeout)-') failing inputs"
  # Fork mode's progress lines: "#<executions>: cov: <edges> ft: <features> corp: <files> exec/s ...".
  grep -E '^#[0-9]+: cov:' "$log" | tail -1
  grep -E '^exit|ERROR: |SUMMARY' "$log" | tail -4
done
tar -C "$fuzz" -czf "$out/fuzz.tgz" logs corpus artifacts
