#!/usr/bin/env bash
# The README's two commands.
#   bash tools/quat.sh bench   build quat_bench for this machine (preset release-native, -march=native)
#                              and print the benchmark comparison table, naming the instruction set:
#                              each cell the median of 7 repetitions run in random interleaved order,
#                              with their spread, so one disturbed run on a shared machine cannot
#                              flip a verdict (quat_bench --table's defaults; a few minutes); last,
#                              the README's headline rows measured here beside the README's own
#                              (bench/headline.py)
#   bash tools/quat.sh test    configure, build and test every CI matrix preset (what .ci/run does):
#                              four x86-64 configurations, then the unit tests cross-built for
#                              AArch64 and run under qemu-aarch64 (preset ci-aarch64)
# Both first make sure the Debian packages quat needs are installed: as root they are installed
# with apt-get; otherwise the script stops and prints the apt-get line to run.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

packages=(g++ cmake clang libglm-dev catch2 libbenchmark-dev libeigen3-dev doxygen
          libclang-rt-14-dev valgrind clang-format clang-tidy python3 pkg-config libfmt-dev
          clang-19 libc++-19-dev libc++abi-19-dev libclang-rt-19-dev qemu-user libceres-dev
          libgtest-dev libgmock-dev libopencv-dev g++-aarch64-linux-gnu)
matrix=(ci-gcc-cxx17-asan ci-clang-cxx20-asan ci-gcc-cxx20-release ci-clang-cxx17-release
        ci-aarch64)
jobs="${QUAT_JOBS:-2}"

usage() {
    echo "usage: bash tools/quat.sh bench|test" >&2
    exit 2
}

ensure_packages() {
    local missing=() p
    for p in "${packages[@]}"; do
        if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$p")
        fi
    done
    [[ ${#missing[@]} -eq 0 ]] && return 0
    local line="apt-get update && apt-get install -y ${missing[*]}"
    if [[ $(id -u) -ne 0 ]]; then
        echo "quat.sh: missing Debian packages: ${missing[*]}" >&2
        echo "quat.sh: install them as root, then run this command again:" >&2
        echo "    sudo sh -c '$line'" >&2
        exit 1
    fi
    echo "quat.sh: installing missing Debian packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends "${missing[@]}"
}

# The benchmark is run where it is built, so it is built for this machine's instruction set; the
# presets release (plain x86-64) and release-x86-64-v3 (AVX2 + FMA) build the other levels.
run_bench() {
    local preset=release-native
    cmake --preset "$preset"
    if ! cmake --build --preset "$preset" --target quat_bench; then
        echo "quat.sh: could not build the quat_bench target (is bench/ present?)" >&2
        exit 1
    fi
    local exe
    exe="$(find "build/$preset" -type f -name quat_bench -perm -u+x | head -n 1)"
    [[ -n "$exe" ]] || { echo "quat.sh: quat_bench executable not found" >&2; exit 1; }
    # --table repeats and interleaves by itself (--benchmark_repetitions=5,
    # --benchmark_enable_random_interleaving=true), printing medians and their spread; the JSON it
    # also writes gives the README's headline rows measured here, printed last beside the README's.
    local json="build/$preset/bench-table.json"
    "$exe" --table --benchmark_out="$json" --benchmark_out_format=json
    python3 bench/headline.py "$json" --beside README.md
}

# Seconds as 12m34s.
duration() { printf '%dm%02ds' $(($1 / 60)) $(($1 % 60)); }

run_tests() {
    local preset log status=0 summaries=() passed=0 total=0
    local logdir="build/logs"
    local start_all t0 t1 t2 t3 times
    mkdir -p "$logdir"
    start_all=$(date +%s)
    for preset in "${matrix[@]}"; do
        log="$logdir/$preset.log"
        echo "==== $preset: configure, build, test"
        local built=0
        t0=$(date +%s)
        if cmake --preset "$preset" >"$log" 2>&1; then
            t1=$(date +%s)
            if cmake --build --preset "$preset" -j "$jobs" >>"$log" 2>&1; then
                built=1
            fi
        fi
        t2=$(date +%s)
        if ((!built)); then
            tail -n 60 "$log"
            echo "quat.sh: $preset failed to configure or build (full log: $log)" >&2
            summaries+=("$preset: configure or build failed (counted as 1 failed test) [wall $(duration $((t2 - t0)))]")
            total=$((total + 1))
            status=1
            continue
        fi
        ctest --preset "$preset" 2>&1 | tee -a "$log" || status=1
        t3=$(date +%s)
        times="wall $(duration $((t3 - t0))): configure $(duration $((t1 - t0))), build $(duration $((t2 - t1))), test $(duration $((t3 - t2)))"
        echo "==== $preset: $times"
        local line
        line="$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1)"
        summaries+=("$preset: ${line:-no CTest summary} [$times]")
        if [[ $line =~ ([0-9]+)\ tests?\ failed\ out\ of\ ([0-9]+) ]]; then
            total=$((total + BASH_REMATCH[2]))
            passed=$((passed + BASH_REMATCH[2] - BASH_REMATCH[1]))
        fi
    done
    echo "==== summary over ${#matrix[@]} configurations (wall $(duration $(($(date +%s) - start_all))))"
    printf '%s\n' "${summaries[@]}"
    # Close with CTest's summary line, summed over the matrix.
    local pct=0
    ((total > 0)) && pct=$((passed * 100 / total))
    echo "$pct% tests passed, $((total - passed)) tests failed out of $total"
    return "$status"
}

[[ $# -eq 1 ]] || usage
case "$1" in
    bench) ensure_packages; run_bench ;;
    test) ensure_packages; run_tests ;;
    *) usage ;;
esac
