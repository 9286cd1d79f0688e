// Instantiates fitting/align_vectors.hpp, registration/align_points.hpp and fitting/mean.hpp
// (align_vectors, try_align_vectors, align_vectors_with_sensitivity, align_points[_with_scale] and
// their try_ forms, hand_eye, try_hand_eye, hand_eye_from_poses, try_hand_eye_from_poses, mean,
// try_mean) for float, double and long double under the strict warning flags, with weights of
// another scalar type beside them (a double weight converts to T). Compiled, not run, by the strict_warnings CTest test.
#include <array>
#include <vector>

#include <quat/fitting/align_vectors.hpp>
#include <quat/fitting/mean.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>

namespace {

template <class T>
T estimation() {
    using namespace quat;
    const std::vector<vec3<T>> sources{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::array<vec3<T>, 3> targets{vec3<T>{0, 1, 0}, vec3<T>{-1, 0, 0}, vec3<T>{0, 0, 1}};
    const std::vector<T> weights{1, 2, 3};
    const std::vector<double> double_weights{1, 2, 3};
    const alignment<T> plain = align_vectors(targets, sources);
    const alignment<T> weighted = align_vectors(targets, sources, double_weights);
    const alignment_with_sensitivity<T> with =
        align_vectors_with_sensitivity(targets, sources, weights);
    const quaternion<T> rotation = with.rotation;
    T sum = plain.rotation.w + weighted.rssd + rotation.x + with.rssd + with.sensitivity(0, 1);
    sum += with.unique ? T(1) : T(0);
    sum += try_align_vectors(targets, sources).value_or(plain).rssd +
           try_align_vectors(targets, sources, double_weights).value_or(plain).rssd;
    const point_alignment<T> points = align_points(targets, sources);
    const similarity_alignment<T> similar =
        align_points_with_scale(targets, sources, double_weights);
    sum += points.rms + points.motion.real.w + similar.scale +
           align_points(targets, sources, weights).rms;
    sum += try_align_points(targets, sources).value_or(points).rms +
           try_align_points(targets, sources, weights).value_or(points).rms +
           try_align_points_with_scale(targets, sources).value_or(similar).scale +
           try_align_points_with_scale(targets, sources, double_weights).value_or(similar).scale;
    const std::vector<dual_quaternion<T>> hand{to_dual_quaternion(rotation, sources[0]),
                                               to_dual_quaternion(rotation_x(T(1)), sources[1])};
    const std::array<dual_quaternion<T>, 2> eye{hand[1], hand[0]};
    const hand_eye_calibration<T> mount = hand_eye(hand, eye);
    sum += mount.rotation_rms + mount.mount.real.w +
           try_hand_eye(hand, eye).value_or(mount).translation_rms +
           hand_eye(hand, eye, hand_eye_method::rotation_first).rotation_rms;
    const hand_eye_with_target<T> poses = hand_eye_from_poses(hand, eye);
    sum += poses.calibration.rotation_rms + poses.target.real.w +
           try_hand_eye_from_poses(hand, eye).value_or(poses).calibration.translation_rms;
    const std::vector<quaternion<T>> rotations{quaternion<T>::identity(), rotation, -rotation};
    sum += mean(rotations).w + mean(rotations, weights).x;
    sum += try_mean(rotations).value_or(quaternion<T>::identity()).y;
    sum += try_mean(rotations, double_weights).value_or(quaternion<T>::identity()).z;
    return sum;
}

}  // namespace

int main() {
    return estimation<float>() + static_cast<float>(estimation<double>()) +
                       static_cast<float>(estimation<long double>()) >
                   0
               ? 0
               : 1;
}
