#!/usr/bin/env bash
# Fuzzes the three input parsers with libFuzzer (tests/fuzz/README.md).
#
#   tools/fuzz.sh [SECONDS_PER_PARSER]      (default 600)
#
# Installs clang 14 and its runtime when missing (Debian: clang, libclang-rt-14-dev; root or
# sudo needed), builds tests/fuzz as its own project in build-fuzz/ with clang
# (-fsanitize=fuzzer,address,undefined; only the parser sources, no Fortran, no HDF5),
# then runs fuzz_legacy, fuzz_indat and fuzz_modern one after the other, each for
# SECONDS_PER_PARSER with -timeout=2 -rss_limit_mb=2048 -jobs=1, and prints per parser
# the inputs executed and the findings.
#
# Inputs: the seeds (tests/fuzz/corpus/<parser>, tests/fuzz/regressions/<parser>, and
# tests/data/bad_cases for the legacy reader); what libFuzzer adds goes to
# build-fuzz/work/<parser> (kept between runs). A finding is written to
# build-fuzz/artifacts/<parser>-crash-* (or -timeout-, -oom-), and its log to
# build-fuzz/logs/<parser>.log. To replay one: build-fuzz/fuzz_<parser> FILE.
# Environment: SPHJET_FUZZ_GENERATE_CAP (particles, default 20000) bounds the generator run
# on accepted cases; FUZZ_FLAGS adds libFuzzer flags (e.g. -seed=1).
set -euo pipefail

SECONDS_PER_PARSER=${1:-600}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$ROOT/build-fuzz

need_install=0
command -v clang++ >/dev/null 2>&1 || need_install=1
if [[ $need_install == 0 ]]; then
    rt_dir=$(clang++ -print-resource-dir)/lib/linux
    ls "$rt_dir"/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1 || need_install=1
fi
if [[ $need_install == 1 ]]; then
    echo "fuzz.sh: installing clang and libclang-rt-14-dev"
    SUDO=""
    [[ $(id -u) == 0 ]] || SUDO=sudo
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq clang libclang-rt-14-dev libtomlplusplus-dev cmake >/dev/null
fi

echo "fuzz.sh: building the fuzz targets in $BUILD"
cmake -S "$ROOT/tests/fuzz" -B "$BUILD" -DCMAKE_CXX_COMPILER=clang++ -DSPHJET_FUZZ=ON >/dev/null
cmake --build "$BUILD" -j"$(nproc)" >/dev/null

mkdir -p "$BUILD/artifacts" "$BUILD/logs"
summary=()
status=0
for parser in legacy indat modern; do
    seeds=("$ROOT/tests/fuzz/corpus/$parser" "$ROOT/tests/fuzz/regressions/$parser")
    [[ $parser == legacy ]] && seeds+=("$ROOT/tests/data/bad_cases")
    mkdir -p "$BUILD/work/$parser"
    log=$BUILD/logs/$parser.log
    echo "fuzz.sh: fuzz_$parser for $SECONDS_PER_PARSER s (log: $log)"
    # -jobs=1: one process at a time (it writes fuzz-0.log in the current directory).
    (
        cd "$BUILD/logs"
        rm -f fuzz-0.log
        "$BUILD/fuzz_$parser" -max_total_time="$SECONDS_PER_PARSER" -timeout=2 -rss_limit_mb=2048 \
            -jobs=1 -print_final_stats=1 -artifact_prefix="$BUILD/artifacts/$parser-" ${FUZZ_FLAGS:-} \
            "$BUILD/work/$parser" "${seeds[@]}" >/dev/null 2>&1 || true
        mv -f fuzz-0.log "$log"
    )
    execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' | tail -1)
    [[ -n $execs ]] || execs=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')
    rate=$(grep -E '^stat::average_exec_per_sec' "$log" | awk '{print $2}' | tail -1)
    corpus=$(find "$BUILD/work/$parser" -type f | wc -l)
    findings=$(grep -cE 'sphjet-fuzz FINDING|ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error:|Test unit written' "$log" || true)
    line="$parser: ${execs:-?} inputs executed (${rate:-?}/s), corpus $corpus, findings $findings"
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
