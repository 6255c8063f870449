#!/usr/bin/env bash
# Fuzzes the three input parsers with libFuzzer (tests/fuzz/README.md).
#
#   tools/fuzz.sh [SECONDS_PER_PARSER [PARSER...]]     (default 600; legacy indat modern)
#
# Installs clang and its runtime when missing (Debian: clang, libclang-rt-dev; root or sudo
# needed), builds the fuzz targets in build-fuzz/ (the top-level CMakeLists.txt with
# -DSPHJET_FUZZ=ON and clang: cpp_driver's sphjet_config library, the same sources as sphjet's,
# instrumented with -fsanitize=fuzzer-no-link,address,undefined; no Fortran, no HDF5), then
# runs each PARSER's target for SECONDS_PER_PARSER with -timeout=2 -rss_limit_mb=2048, one
# after the other, and prints per parser the inputs executed and the findings. (libFuzzer's
# timeout is wall-clock time: on a machine loaded far beyond its cores, FUZZ_TIMEOUT=10 keeps
# a starved process from being reported as a hang; replay a timeout to tell.)
#
# Inputs: the seeds (tests/fuzz/corpus/<parser>, tests/fuzz/regressions/<parser>, and
# tests/data/bad_cases for the legacy reader); what libFuzzer adds goes to
# build-fuzz/work/<parser> (kept between runs). A finding stops that parser's run; it is
# written to build-fuzz/artifacts/<parser>-crash-* (or -timeout-, -oom-), and the log to
# build-fuzz/logs/<parser>.log. To replay one: build-fuzz/tests/fuzz/fuzz_<parser> FILE.
# Environment: SPHJET_FUZZ_GENERATE_CAP (particles, default 20000) bounds the generator run
# on accepted cases; FUZZ_TIMEOUT (seconds, default 2) is the limit for one input;
# FUZZ_FLAGS adds libFuzzer flags (e.g. -seed=1, -runs=1000000).
set -euo pipefail

SECONDS_PER_PARSER=${1:-600}
shift || true
PARSERS=("$@")
((${#PARSERS[@]} > 0)) || PARSERS=(legacy indat modern)
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$ROOT/build-fuzz

if ! bash "$ROOT/tests/fuzz/smoke.sh" probe >/dev/null 2>&1; then
    echo "fuzz.sh: installing clang and libclang-rt-dev"
    SUDO=""
    [[ $(id -u) == 0 ]] || SUDO=sudo
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq clang libclang-rt-dev libtomlplusplus-dev libfmt-dev cmake >/dev/null
fi

echo "fuzz.sh: building the fuzz targets in $BUILD"
mkdir -p "$BUILD/artifacts" "$BUILD/logs"
bash "$ROOT/tests/fuzz/smoke.sh" build "$ROOT" "$BUILD" >"$BUILD/logs/build.log" 2>&1 ||
    { tail -30 "$BUILD/logs/build.log"; echo "fuzz.sh: the build failed (log: $BUILD/logs/build.log)"; exit 1; }

summary=()
status=0
for parser in "${PARSERS[@]}"; do
    seeds=("$ROOT/tests/fuzz/corpus/$parser" "$ROOT/tests/fuzz/regressions/$parser")
    [[ $parser == legacy && -d $ROOT/tests/data/bad_cases ]] && seeds+=("$ROOT/tests/data/bad_cases")
    mkdir -p "$BUILD/work/$parser"
    log=$BUILD/logs/$parser.log
    echo "fuzz.sh: fuzz_$parser for $SECONDS_PER_PARSER s (log: $log)"
    # shellcheck disable=SC2086  # FUZZ_FLAGS: several flags
    "$BUILD/tests/fuzz/fuzz_$parser" -max_total_time="$SECONDS_PER_PARSER" -timeout="${FUZZ_TIMEOUT:-2}" -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$BUILD/artifacts/$parser-" ${FUZZ_FLAGS:-} \
        "$BUILD/work/$parser" "${seeds[@]}" >"$log" 2>&1 || true
    execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' | tail -1 || true)
    [[ -n $execs ]] || execs=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#' || true)
    rate=$(grep -E '^stat::average_exec_per_sec' "$log" | awk '{print $2}' | tail -1 || true)
    corpus=$(find "$BUILD/work/$parser" -type f | wc -l)
    findings=$(grep -cE 'sphjet-fuzz FINDING|ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|LeakSanitizer|libFuzzer)|runtime error:|Test unit written' "$log" || true)
    line="$parser: ${execs:-?} inputs executed (${rate:-?}/s), corpus $corpus, findings $findings"
    # A timeout is wall-clock time: replayed alone, an input that a loaded machine starved
    # runs in milliseconds. Such a one is reported, not counted.
    timeout_unit=$(grep -oE 'Test unit written to [^ ]*-timeout-[0-9a-f]+' "$log" | tail -1 | sed 's/.* //' || true)
    if [[ $findings != 0 && -n $timeout_unit ]] &&
        ! grep -qE 'sphjet-fuzz FINDING|ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|LeakSanitizer)|runtime error:' "$log"; then
        replay=$("$BUILD/tests/fuzz/fuzz_$parser" -timeout="${FUZZ_TIMEOUT:-2}" "$timeout_unit" 2>&1 |
                 grep -oE 'Executed .* in [0-9]+ ms' | sed 's/.* in //') || true
        if [[ -n $replay ]]; then
            line="$parser: ${execs:-?} inputs executed (${rate:-?}/s), corpus $corpus, findings 0"
            line+=$'\n'"    stopped by a timeout whose input replays in $replay (the machine's load, not a hang): $timeout_unit"
            findings=0
        fi
    fi
    if [[ $findings != 0 ]]; then
        status=1
        line+=$'\n'"$(grep -E 'sphjet-fuzz FINDING|SUMMARY|runtime error:|Test unit written' "$log" | head -5 | sed 's/^/    /')"
    fi
    summary+=("$line")
done

echo
echo "fuzz.sh: summary ($SECONDS_PER_PARSER s per parser)"
printf '%s\n' "${summary[@]}"
exit $status
