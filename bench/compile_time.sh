#!/usr/bin/env bash
# Compile time of one translation unit using the common rotation operations, written once with quat
# and once with GLM (glm/glm.hpp + glm/gtc/quaternion.hpp); prints both and the ratio quat / GLM.
# Usage: bench/compile_time.sh [compiler] [runs]   (defaults: g++, 7 runs; the median counts)
#        bench/compile_time.sh --instructions [compiler]
# The second form counts the instructions the compiler proper executes (valgrind's callgrind,
# one run each): deterministic where wall times on a shared machine swing by a fifth.
set -euo pipefail
instructions=false
if [ "${1:-}" = --instructions ]; then
    instructions=true
    shift
fi
cxx=${1:-g++}
runs=${2:-7}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cat >"$work/with_quat.cpp" <<'CPP'
#include <quat/quat.hpp>
float use(float a, float b, float c, float t) {
    const quat::quatf q = quat::to_quaternion(quat::axis_angle<float>{{0, 0, 1}, a});
    const quat::quatf r = quat::to_quaternion(quat::euler<float>{{a, b, c}});
    const quat::quatf s = quat::normalize(quat::slerp(q, r, t) * quat::inverse(q));
    const quat::vec3<float> v = quat::rotate(s, quat::vec3<float>{a, b, c});
    const quat::rotation_matrix<float> m = quat::to_matrix(s);
    const quat::quatf back = quat::to_quaternion(m);
    const quat::euler<float> e = quat::to_euler<quat::sequence::zyx>(back);
    return v.x + quat::rotate(m, v).y + e[0] + quat::to_axis_angle(back).angle;
}
CPP
cat >"$work/with_glm.cpp" <<'CPP'
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
float use(float a, float b, float c, float t) {
    const glm::quat q = glm::angleAxis(a, glm::vec3(0, 0, 1));
    const glm::quat r = glm::quat(glm::vec3(c, b, a));
    const glm::quat s = glm::normalize(glm::slerp(q, r, t) * glm::inverse(q));
    const glm::vec3 v = s * glm::vec3(a, b, c);
    const glm::mat3 m = glm::mat3_cast(s);
    const glm::quat back = glm::quat_cast(m);
    const glm::vec3 e = glm::eulerAngles(back);
    return v.x + (m * v).y + e.x + glm::angle(back);
}
CPP

# The two units are compiled alternately, so that a change in the machine's load falls on both alike;
# the median of the runs counts. Both code generation (-O2) and parsing alone (-fsyntax-only) are
# reported: the first is what a build pays, the second isolates the include graph.
measure() {  # measure FLAGS: prints "quat_median glm_median"
    local flags=$1 quat_times=() glm_times=()
    for _ in $(seq "$runs"); do
        for unit in quat glm; do
            local start end
            start=$(date +%s.%N)
            # shellcheck disable=SC2086
            "$cxx" -std=c++17 $flags -I"$root/include" -c "$work/with_$unit.cpp" -o "$work/out.o"
            end=$(date +%s.%N)
            local elapsed
            elapsed=$(awk -v a="$end" -v b="$start" 'BEGIN {print a - b}')
            if [ "$unit" = quat ]; then quat_times+=("$elapsed"); else glm_times+=("$elapsed"); fi
        done
    done
    median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2)}'; }
    echo "$(median "${quat_times[@]}") $(median "${glm_times[@]}")"
}
count() {  # count FLAGS UNIT: millions of instructions of the compiler proper (cc1plus, clang -cc1)
    # shellcheck disable=SC2054  # the commas belong to -wrapper's one argument
    local run=("$cxx" -wrapper valgrind,--tool=callgrind,--callgrind-out-file=/dev/null)
    # clang compiles in its driver's process (-fintegrated-cc1), which takes no -wrapper.
    if "$cxx" --version | grep -q clang; then
        run=(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$cxx")
    fi
    # shellcheck disable=SC2086
    "${run[@]}" -std=c++17 $1 -I"$root/include" -S "$work/with_$2.cpp" -o "$work/out.s" 2>&1 |
        awk '/Collected :/ {printf "%.0f\n", $NF / 1e6; exit}'
}
echo "compiler: $("$cxx" --version | head -1)"
if $instructions; then
    for flags in "-O2" "-fsyntax-only"; do
        quat_count=$(count "$flags" quat)
        glm_count=$(count "$flags" glm)
        echo "$flags: quat TU ${quat_count}M instructions, GLM TU ${glm_count}M (callgrind," \
            "-std=c++17), ratio quat / GLM $(echo "$quat_count $glm_count" | awk '{printf "%.2f", $1 / $2}')"
    done
    exit 0
fi
for flags in "-O2" "-fsyntax-only"; do
    read -r quat_time glm_time <<<"$(measure "$flags")"
    echo "$flags: quat TU ${quat_time} s, GLM TU ${glm_time} s (median of $runs, alternated, -std=c++17)," \
        "ratio quat / GLM $(echo "$quat_time $glm_time" | awk '{printf "%.2f", $1 / $2}')"
done
