#!/usr/bin/env bash
# Runs the libFuzzer harnesses of a fuzz build (`make fuzz`, `make fuzz-regressions`;
# docs/FUZZING.md).
#
#   tests/fuzz/run_fuzz.sh BUILD_DIR SECONDS [HARNESS...]
#
# Writes the seed corpora (BUILD_DIR/bin/fuzz_seeds -> BUILD_DIR/seeds/), then runs each
# harness (all thirteen by default) for SECONDS with the limits that make a finding of a
# memory blow-up (-rss_limit_mb, -malloc_limit_mb) or a hang (-timeout). New inputs go to
# BUILD_DIR/corpus/<harness>/ (kept between runs), crashers to BUILD_DIR/crashes/<harness>/,
# the output to BUILD_DIR/logs/<harness>.log. SECONDS = 0 only replays the regression and
# seed corpora once. Prints executions per harness; exits 1 if any harness found something.
#
# Environment: FUZZ_JOBS (harnesses run at once, default 2), FUZZ_RSS_MB (1024),
# FUZZ_TIMEOUT_S (10, per input), FUZZ_PREFIX (the harnesses' names before <harness>:
# fuzz_ in a fuzz build, libfuzzer_ in a sanitized build with EW_SANITIZE_FUZZ).
set -euo pipefail

if [[ $# -lt 2 ]]; then
  echo "usage: $0 BUILD_DIR SECONDS [HARNESS...]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
seconds=$2
shift 2
harnesses=("$@")
[[ ${#harnesses[@]} -gt 0 ]] || harnesses=(c3d bvh asf_amc trc qtm_tsv joint_csv model_file mapping_file pipeline keypoints calibration
                                       calibrated_clip keyframes)
src=$(cd "$(dirname "$0")" && pwd)
jobs=${FUZZ_JOBS:-2}
rss=${FUZZ_RSS_MB:-1024}
timeout=${FUZZ_TIMEOUT_S:-10}
prefix=${FUZZ_PREFIX:-fuzz_}

"$build/bin/fuzz_seeds" "$build/seeds"
mkdir -p "$build/logs" "$build/dict"
# The pipeline reads every format: its dictionary is the union of the others.
cat "$src"/dict/*.dict > "$build/dict/pipeline.dict"

run_one() {
  local h=$1 dict
  local corpus="$build/corpus/$h" crashes="$build/crashes/$h" log="$build/logs/$h.log"
  mkdir -p "$corpus" "$crashes"
  dict="$src/dict/$h.dict"
  [[ $h == pipeline ]] && dict="$build/dict/pipeline.dict"
  local args=(-rss_limit_mb="$rss" -malloc_limit_mb="$rss" -timeout="$timeout"
              -print_final_stats=1 -artifact_prefix="$crashes/")
  [[ -f $dict ]] && args+=(-dict="$dict")
  if [[ $seconds -eq 0 ]]; then
    args+=(-runs=0)
  else
    args+=(-max_total_time="$seconds")
  fi
  # The work corpus first: libFuzzer adds new inputs to the first folder only.
  "$build/bin/$prefix$h" "${args[@]}" "$corpus" "$build/seeds/$h" "$src/regressions/$h" \
    > "$log" 2>&1
}

stamp="$build/logs/.started"
touch "$stamp"
declare -A pid_of status_of
running=0
for h in "${harnesses[@]}"; do
  if [[ ! -x "$build/bin/$prefix$h" ]]; then
    echo "fuzz: no harness $build/bin/$prefix$h" >&2
    exit 2
  fi
  if [[ $running -ge $jobs ]]; then
    wait -n || true
    running=$((running - 1))
  fi
  run_one "$h" &
  pid_of[$h]=$!
  running=$((running + 1))
done
for h in "${harnesses[@]}"; do
  if wait "${pid_of[$h]}"; then status_of[$h]=0; else status_of[$h]=$?; fi
done

stat() {  # stat NAME LOG: a libFuzzer final statistic, "-" when absent
  local v
  v=$(grep -o "^stat::$1: *[0-9]*" "$2" | awk '{print $2}' | tail -1)
  echo "${v:--}"
}

found=0
failed_logs=()
printf "fuzz: %-11s %8s %12s %8s %8s %8s  %s\n" harness seconds executions exec/s new rss_mb result
for h in "${harnesses[@]}"; do
  log="$build/logs/$h.log"
  execs=$(stat number_of_executed_units "$log")
  persec=$(stat average_exec_per_sec "$log")
  added=$(stat new_units_added "$log")
  peak=$(stat peak_rss_mb "$log")
  artifacts=$(find "$build/crashes/$h" -type f -newer "$stamp" | sort)
  if [[ ${status_of[$h]} -eq 0 && -z $artifacts ]]; then
    result=ok
  else
    found=1
    result="FINDING (exit ${status_of[$h]}): ${artifacts:-see $log}"
    failed_logs+=("$log")
  fi
  printf "fuzz: %-11s %8s %12s %8s %8s %8s  %s\n" "$h" "$seconds" "$execs" "$persec" "$added" \
    "$peak" "$(echo "$result" | tr '\n' ' ')"
done
if [[ $found -ne 0 ]]; then
  # The report of each finding (the sanitizer's or libFuzzer's, with the stack and the
  # input in Base64), so a CI log alone says what broke.
  for log in "${failed_logs[@]}"; do
    first=$(grep -n -m1 -E "==[0-9]+==ERROR|ERROR: libFuzzer|runtime error:|terminate called" "$log" \
            | cut -d: -f1 || true)
    echo "fuzz: ---- $log (from line ${first:-1}) ----" >&2
    tail -n "+${first:-1}" "$log" | head -n 80 >&2
  done
  echo "fuzz: findings above; each log's end has the stack (build: $build/logs/)." >&2
  echo "fuzz: minimise a crasher with: $build/bin/fuzz_<harness> -minimize_crash=1 -runs=10000 FILE" >&2
  exit 1
fi
