#!/usr/bin/env bash
# Runs the libFuzzer harnesses of the readers (fuzz/, built by the `fuzz` preset).
#   scripts/fuzz.sh SECONDS JOBS [FORMAT ...]
# Each harness runs SECONDS seconds, JOBS harnesses at a time, on its corpus build/fuzz/corpus/
# <format>/, which starts with the seed files named in fuzz/harnesses.cmake (at most 12 files per
# glob: fixtures whole, the first 4 KB of real data from TESSERA_DATA_DIR, default
# ../shared/data) and the format's regression inputs (tests/fuzz/regressions/<format>/). Logs go to build/fuzz/logs/, inputs
# that crash to build/fuzz/artifacts/<format>/. Prints one line per harness (executions per
# second, corpus size, libFuzzer's cov and ft) and exits 1 when any harness found a problem.
set -uo pipefail

seconds=${1:?usage: scripts/fuzz.sh SECONDS JOBS [FORMAT ...]}
jobs=${2:?usage: scripts/fuzz.sh SECONDS JOBS [FORMAT ...]}
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build/fuzz
data=${TESSERA_DATA_DIR:-$root/../shared/data}
manifest=$build/harnesses.txt
[ -f "$manifest" ] || { echo "fuzz: $manifest missing: build the fuzz preset first" >&2; exit 2; }

# seed_corpus FORMAT GLOB...: fills build/fuzz/corpus/FORMAT once.
seed_corpus() {
  local format=$1 corpus=$build/corpus/$1
  shift
  mkdir -p "$corpus"
  if [ -n "$(ls -A "$corpus")" ]; then return; fi
  local spec dir pattern n f
  for spec in "$@"; do
    case $spec in
      data:*) dir=$data; pattern=${spec#data:} ;;
      *) dir=$root; pattern=$spec ;;
    esac
    n=0
    for f in "$dir"/$pattern; do
      [ -f "$f" ] || continue
      # Real files can be megabytes: their first 4 KB. Fixtures are small and whole (a ROS 1
      # bag's header record alone is 4 KB).
      case $spec in
        data:*) head -c 4096 "$f" > "$corpus/seed-$(basename "$f")" ;;
        *) cp "$f" "$corpus/seed-$(basename "$f")" ;;
      esac
      n=$((n + 1))
      [ $n -ge 12 ] && break
    done
  done
  if [ -d "$root/tests/fuzz/regressions/$format" ]; then
    for f in "$root/tests/fuzz/regressions/$format"/*; do
      [ -f "$f" ] && cp "$f" "$corpus/regression-$(basename "$f")"
    done
  fi
  # libFuzzer needs at least one input to start from; an empty one will do.
  [ -n "$(ls -A "$corpus")" ] || : > "$corpus/empty"
}

run_one() {
  local format=$1 binary=$2 dict=$3
  local log=$build/logs/$format.log artifacts=$build/artifacts/$format/
  mkdir -p "$artifacts"
  local args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=1024
              -print_final_stats=1
              -artifact_prefix="$artifacts")
  [ "$dict" != "-" ] && args+=(-dict="$dict")
  # ASan: a report is a crash; leaks are reported at exit and count too.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "$binary" "${args[@]}" "$build/corpus/$format" > "$log" 2>&1
  return $?
}

mkdir -p "$build/logs"
selected=("$@")
lines=()
while read -r format binary dict seeds; do
  [ -n "$format" ] || continue
  if [ ${#selected[@]} -gt 0 ] && [[ ! " ${selected[*]} " == *" $format "* ]]; then continue; fi
  # shellcheck disable=SC2086  # the seed globs are expanded in seed_corpus
  seed_corpus "$format" $seeds
  lines+=("$format $binary $dict")
done < "$manifest"

pids=()
formats=()
for line in "${lines[@]}"; do
  read -r format binary dict <<< "$line"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  run_one "$format" "$binary" "$dict" &
  pids+=($!)
  formats+=("$format")
done

failed=0
printf '%-20s %-7s %10s %8s %7s %7s %6s\n' harness result execs/s corpus cov ft secs
for i in "${!pids[@]}"; do
  format=${formats[$i]}
  wait "${pids[$i]}"
  rc=$?
  log=$build/logs/$format.log
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+[[:space:]]' "$log" | tail -1)
  field() { sed -n "s/.*$1: *\([0-9]*\).*/\1/p" <<< "${done_line:-$last}"; }
  execs=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  secs=$(sed -n 's/.*Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log")
  corpus=$(sed -n 's/.*corp: \([0-9]*\)\/.*/\1/p' <<< "${done_line:-$last}")
  result=ok
  if [ $rc -ne 0 ]; then result=FOUND; failed=1; fi
  printf '%-20s %-7s %10s %8s %7s %7s %6s\n' "$format" "$result" "${execs:-?}" "${corpus:-?}" \
    "$(field cov)" "$(field ft)" "${secs:-?}"
  [ $rc -ne 0 ] && echo "  $log; inputs in $build/artifacts/$format/" && grep -a -m3 -E 'ERROR|fuzz |runtime error' "$log" | sed 's/^/  /'
done
exit $failed
