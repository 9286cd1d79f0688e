#include "isa_mix.hpp"

rotate_function baseline_rotate() { return &quat::rotate<float>; }
