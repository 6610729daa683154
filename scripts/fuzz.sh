#!/usr/bin/env bash
# The libFuzzer targets of fuzz/ (clang-14, AddressSanitizer + UndefinedBehaviorSanitizer), built
# in build-fuzz/.
#   scripts/fuzz.sh                  builds them and runs the short ctest: every target over its
#                                    seed corpus plus a fixed number of runs, and the
#                                    regression inputs
#   scripts/fuzz.sh campaign N [T [TARGET...]]
#                                    runs each target (or the ones named), one after another, for
#                                    N executions (at most T seconds each, if T > 0) from
#                                    build-fuzz/campaign, and prints executions, exec/s, coverage
#                                    and findings per target
set -euo pipefail
cd "$(dirname "$0")/.."

targets=(formula numbers scene explore_query png_read compute)
declare -A max_len=([formula]=256 [numbers]=96 [scene]=2048 [explore_query]=1024 [png_read]=4096 [compute]=512)
# compute runs meshes of the slow algebras under the sanitizers (fuzz/CMakeLists.txt)
declare -A timeout=([compute]=60)

cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_COMPILER=clang++-14 \
  >/dev/null
cmake --build build-fuzz -j "$(nproc)"

if [ "${1:-}" != campaign ]; then
  ctest --test-dir build-fuzz --output-on-failure -j "$(nproc)"
  exit 0
fi

runs=${2:?usage: scripts/fuzz.sh campaign RUNS [SECONDS [TARGET...]]}
seconds=${3:-0}
if [ $# -gt 3 ]; then targets=("${@:4}"); fi
# Allocation stacks of depth 0 make the allocation-heavy targets about three times faster; a
# finding is replayed with the full reports (scripts/fuzz.sh's ctest, or the target alone).
export ASAN_OPTIONS=malloc_context_size=0:quarantine_size_mb=16:detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# -reload=0: one process owns the corpus, and rereading the folder after each new input cost
# the formula target 8% of its time.
printf '%-14s %12s %7s %7s %8s %7s %9s %8s\n' target executions exec/s cov ft corpus findings \
  seconds
for target in "${targets[@]}"; do
  corpus=build-fuzz/campaign/$target
  findings=build-fuzz/campaign/findings-$target
  mkdir -p "$corpus" "$findings"
  log=build-fuzz/campaign/$target.log
  start=$(date +%s)
  build-fuzz/${target}_fuzzer -runs="$runs" -reload=0 -max_total_time="$seconds" \
    -max_len="${max_len[$target]}" -timeout="${timeout[$target]:-10}" -rss_limit_mb=2048 \
    -dict="fuzz/dict/$target.dict" -print_final_stats=1 -artifact_prefix="$findings/" \
    "$corpus" "fuzz/corpus/$target" >"$log" 2>&1 || true
  elapsed=$(( $(date +%s) - start ))
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|RELOAD)' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  printf '%-14s %12s %7s %7s %8s %7s %9s %8s\n' "$target" "${executions:-?}" "${rate:-?}" \
    "${cov:-?}" "${ft:-?}" "$(ls "$corpus" | wc -l)" "$(ls "$findings" | wc -l)" "$elapsed"
done
