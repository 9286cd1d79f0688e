#!/usr/bin/env bash
# Compile time of one translation unit using the common rotation operations, written once with quat
# and once with GLM (glm/glm.hpp + glm/gtc/quaternion.hpp); prints both and the ratio quat / GLM.
# Usage: bench/compile_time.sh [compiler] [runs]   (defaults: g++, 5 runs; best of the runs counts)
set -euo pipefail
cxx=${1:-g++}
runs=${2:-5}
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

best() {  # best wall time in seconds of compiling $1 with -O2
    local file=$1 best_time=1e9
    for _ in $(seq "$runs"); do
        local start end
        start=$(date +%s.%N)
        "$cxx" -std=c++17 -O2 -I"$root/include" -c "$file" -o "$work/out.o"
        end=$(date +%s.%N)
        best_time=$(echo "$end $start $best_time" | awk '{d = $1 - $2; print (d < $3 ? d : $3)}')
    done
    echo "$best_time"
}
quat_time=$(best "$work/with_quat.cpp")
glm_time=$(best "$work/with_glm.cpp")
echo "compiler: $("$cxx" --version | head -1)"
echo "quat TU: ${quat_time} s   GLM TU: ${glm_time} s   (best of $runs, -std=c++17 -O2)"
echo "ratio quat / GLM: $(echo "$quat_time $glm_time" | awk '{printf "%.2f", $1 / $2}')"
