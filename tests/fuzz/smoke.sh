#!/usr/bin/env bash
# The fuzz smoke of the default test set (tests/fuzz/CMakeLists.txt, label fuzz), and the
# build of the fuzz targets for tools/fuzz.sh.
#
#   smoke.sh probe
#       exit 0 where clang++ links a libFuzzer target, else 77 with the reason.
#   smoke.sh build SOURCE_DIR FUZZ_TREE
#       configures and builds SOURCE_DIR with -DSPHJET_FUZZ=ON and clang++ in FUZZ_TREE.
#   smoke.sh run PARSER FUZZ_BINARY SECONDS REGRESSION_DIR WORK_DIR
#       runs every input of REGRESSION_DIR once, then fuzzes for SECONDS (0: not at all) from
#       corpus/PARSER and REGRESSION_DIR (and tests/data/bad_cases for legacy) into a fresh
#       WORK_DIR/corpus. Any crash, sanitizer report, timeout (> 10 s for one input) or
#       out-of-memory (> 2048 MB) fails, naming the input.
#   smoke.sh goes-red FUZZ_PLANTED SOURCE_DIR WORK_DIR
#       the smoke's own test: `run legacy` on fuzz_planted (fuzz_legacy with a planted
#       heap overflow on inputs starting "SPHJET_FUZZ_PLANTED_CRASH") must pass with the
#       real regression inputs and fail with planted/crash.txt added to a copy of them.
#
# Exit status 77 (ctest: skipped) where clang++ cannot link a libFuzzer target; the message
# says why. Debian: apt-get install clang libclang-rt-dev (tools/install_deps.sh).
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
# libFuzzer's limits for one input in the smoke: wider than the campaign's 2 s (tools/fuzz.sh),
# since the smoke shares the cores with the other tests.
LIMITS=(-timeout=10 -rss_limit_mb=2048)

skip() {
    echo "SKIPPED: $*"
    exit 77
}

# Skips unless clang++ links a -fsanitize=fuzzer,address,undefined program.
need_toolchain() {
    command -v clang++ >/dev/null 2>&1 ||
        skip "clang++ not found; the fuzz smoke needs clang and libFuzzer (Debian: apt-get install clang libclang-rt-dev)"
    local probe
    probe=$(mktemp -d)
    printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' \
        >"$probe/probe.cpp"
    if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" \
        >"$probe/log" 2>&1; then
        local why
        why=$(head -3 "$probe/log" | tr '\n' ' ')
        rm -rf "$probe"
        skip "clang++ cannot link a libFuzzer target ($why); Debian: apt-get install libclang-rt-dev"
    fi
    rm -rf "$probe"
}

# The report of a failed libFuzzer run: what went wrong, then the end of the log.
show_failure() {
    grep -E 'sphjet-fuzz FINDING|ERROR: |SUMMARY: |runtime error:' "$1" | head -10
    echo "--- the end of $1:"
    tail -25 "$1"
}

cmd_build() {
    local src=$1 tree=$2
    need_toolchain
    local launcher=()
    command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    mkdir -p "$tree"
    cmake -S "$src" -B "$tree" -DSPHJET_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
        >"$tree/configure.log" 2>&1 ||
        { cat "$tree/configure.log"; echo "FAILED: configuring the fuzz build"; exit 1; }
    cmake --build "$tree" -j "$(nproc)" ||
        { echo "FAILED: building the fuzz targets (the build log above)"; exit 1; }
    echo "fuzz targets built in $tree/tests/fuzz"
}

cmd_run() {
    local parser=$1 bin=$2 seconds=$3 regressions=$4 work=$5
    if [[ ! -x $bin ]]; then
        need_toolchain
        echo "FAILED: $bin was not built (see the test fuzz_build)"
        exit 1
    fi
    rm -rf "$work"
    mkdir -p "$work/corpus"

    local inputs=()
    [[ -d $regressions ]] && mapfile -t inputs < <(find "$regressions" -maxdepth 1 -type f ! -name '.*' | sort)
    if ((${#inputs[@]} > 0)); then
        if ! "$bin" "${LIMITS[@]}" "${inputs[@]}" >"$work/replay.log" 2>&1; then
            show_failure "$work/replay.log"
            local culprit
            culprit=$(grep -E '^Running: ' "$work/replay.log" | tail -1 | sed 's/^Running: //')
            echo "FAILED: $parser: the regression input ${culprit:-?} crashes (log: $work/replay.log)"
            exit 1
        fi
    fi
    echo "$parser: ${#inputs[@]} regression inputs replayed, no finding"
    ((seconds > 0)) || return 0

    local seeds=("$HERE/corpus/$parser")
    [[ -d $regressions ]] && seeds+=("$regressions")
    [[ $parser == legacy && -d $ROOT/tests/data/bad_cases ]] && seeds+=("$ROOT/tests/data/bad_cases")
    if ! "$bin" "${LIMITS[@]}" -max_total_time="$seconds" -print_final_stats=1 \
        -artifact_prefix="$work/" "$work/corpus" "${seeds[@]}" >"$work/fuzz.log" 2>&1; then
        show_failure "$work/fuzz.log"
        local artifact
        artifact=$(grep -oE 'Test unit written to [^ ]+' "$work/fuzz.log" | tail -1 | sed 's/.* //')
        echo "FAILED: $parser: a finding in $seconds s of fuzzing, input ${artifact:-?} (log: $work/fuzz.log)"
        echo "  replay: $bin $artifact; once fixed, add it to tests/fuzz/regressions/$parser/"
        exit 1
    fi
    local execs
    execs=$(grep -E '^stat::number_of_executed_units' "$work/fuzz.log" | awk '{print $2}' | tail -1)
    echo "$parser: ${execs:-?} inputs in $seconds s of fuzzing, no finding"
    rm -rf "$work/corpus"
}

cmd_goes_red() {
    local bin=$1 src=$2 work=$3
    local planted=$src/tests/fuzz/planted/crash.txt
    if [[ ! -x $bin ]]; then
        need_toolchain
        echo "FAILED: $bin was not built (see the test fuzz_build)"
        exit 1
    fi
    rm -rf "$work"
    mkdir -p "$work/regressions"

    echo "--- the smoke on fuzz_planted with the regression inputs of legacy: must pass"
    bash "$0" run legacy "$bin" 0 "$src/tests/fuzz/regressions/legacy" "$work/clean" ||
        { echo "FAILED: the smoke failed without the planted input"; exit 1; }

    echo "--- the same with planted/crash.txt added to them: must fail, naming it"
    cp "$src"/tests/fuzz/regressions/legacy/* "$planted" "$work/regressions/"
    local rc=0
    bash "$0" run legacy "$bin" 5 "$work/regressions" "$work/planted" >"$work/planted.log" 2>&1 || rc=$?
    cat "$work/planted.log"
    [[ $rc == 1 ]] || { echo "FAILED: the smoke exited $rc with a crashing regression input, not 1"; exit 1; }
    grep -q "FAILED: legacy: the regression input $work/regressions/crash.txt crashes" "$work/planted.log" ||
        { echo "FAILED: the smoke's failure does not name the planted input"; exit 1; }
    grep -q "SUMMARY: AddressSanitizer: heap-buffer-overflow" "$work/planted.log" ||
        { echo "FAILED: no AddressSanitizer report of the planted overflow"; exit 1; }
    echo "the smoke went red on the planted input, as it must"
}

case ${1:-} in
    probe) need_toolchain; echo "clang++ links libFuzzer targets" ;;
    build) shift; cmd_build "$@" ;;
    run) shift; cmd_run "$@" ;;
    goes-red) shift; cmd_goes_red "$@" ;;
    *) echo "usage: smoke.sh probe | build SOURCE_DIR FUZZ_TREE | run PARSER BINARY SECONDS REGRESSION_DIR WORK_DIR | goes-red FUZZ_PLANTED SOURCE_DIR WORK_DIR" >&2; exit 2 ;;
esac
