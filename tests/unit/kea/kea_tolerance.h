// kea_tolerance.h: how closely two of Kea's answers to one problem must
// agree in the tests (relative to the answer's size): two exact solves
// that differ by their order of operations, a warm and a cold one, a
// stored matrix and an operator, a single-precision one and the double
// reference.
#pragma once

#include "MePrecision.h"  // KARMA_DOUBLE

namespace kea_test {

#if KARMA_DOUBLE
constexpr double kTol = 1e-8;
#else
constexpr double kTol = 2e-3;
#endif

}  // namespace kea_test
