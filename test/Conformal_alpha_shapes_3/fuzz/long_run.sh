#!/usr/bin/env bash
# The long fuzz run, outside CI (README.md beside this file): runs one
# libFuzzer target for a while on a corpus kept in the build tree (so that
# runs add up), then merge-minimizes what it found against the committed
# seeds and leaves the inputs that add coverage in new_seeds_<target>/ for
# review; with --copy it copies them into seeds/<target>/ as well.
#
#   test/Conformal_alpha_shapes_3/fuzz/long_run.sh [--copy] [target] [seconds]
#
# target: fuzz_pipeline (default) or fuzz_read_point_cloud; seconds: the
# length of the run (default 3600). Environment: CAS3_FUZZ_BUILD (the
# sanitizer build directory, default build-sanitize), CAS3_FUZZ_FORK (run
# that many fuzzing processes with -fork, default 1: a single process, for
# shared machines). Exits with 1 when the run left a crash, leak or timeout
# reproducer (in crashes_<target>/ of the build's fuzz directory).
set -euo pipefail
copy=0
if [ "${1:-}" = "--copy" ]; then
  copy=1
  shift
fi
target="${1:-fuzz_pipeline}"
seconds="${2:-3600}"
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
build="${CAS3_FUZZ_BUILD:-build-sanitize}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
dir="$build/test/Conformal_alpha_shapes_3/fuzz"
seeds="$here/seeds/$target"
fuzzer="$dir/$target"
[ -x "$fuzzer" ] || { echo "$fuzzer is not built (README.md: the sanitizer build with clang++)"; exit 2; }
[ -d "$seeds" ] || { echo "no seed directory $seeds"; exit 2; }

corpus="$dir/corpus_$target"
crashes="$dir/crashes_$target"
merged="$dir/new_seeds_$target"
mkdir -p "$corpus" "$crashes"
log="$dir/long_run_$target.log"
echo "$target: $seconds s from $corpus and $seeds; log in $log"

# the run: the corpus grows in place; a crash stops the run and is kept
fork=()
[ "${CAS3_FUZZ_FORK:-1}" -gt 1 ] && fork=(-fork="$CAS3_FUZZ_FORK" -ignore_crashes=1)
status=0
"$fuzzer" -max_total_time="$seconds" -max_len=4096 -print_final_stats=1 -artifact_prefix="$crashes/" \
  "${fork[@]}" "$corpus" "$seeds" > "$log" 2>&1 || status=$?
grep -E '^(Done|stat::number_of_executed_units|stat::new_units_added|stat::average_exec_per_sec)' "$log" || true

# the corpus minimized against the seeds: a merge into a copy of the seeds
# adds only the inputs that reach code the seeds do not (edges only, not
# hit counts, so that the seed folder stays small)
rm -rf "$merged" "$merged.all"
mkdir -p "$merged.all"
cp "$seeds"/* "$merged.all"/
"$fuzzer" -merge=1 -use_counters=0 -max_len=4096 "$merged.all" "$corpus" > "$dir/long_run_${target}_merge.log" 2>&1
mkdir -p "$merged"
for f in "$merged.all"/*; do
  [ -e "$seeds/$(basename "$f")" ] || cp "$f" "$merged"/
done
rm -rf "$merged.all"
count=$(find "$merged" -type f | wc -l)
echo "$target: $count input(s) add coverage to the seeds, in $merged"
if [ "$copy" = 1 ] && [ "$count" -gt 0 ]; then
  cp "$merged"/* "$seeds"/
  echo "$target: copied into $seeds (review, then git add)"
fi

found=$(find "$crashes" -type f | wc -l)
if [ "$found" -gt 0 ] || [ "$status" -ne 0 ]; then
  echo "$target: the run stopped with status $status; reproducers in $crashes:"
  ls "$crashes"
  exit 1
fi
