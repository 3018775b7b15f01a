/* backends.h: the kernel tables of the backends (not installed; kernels.h
 * says what each kernel computes). */
#ifndef KARMA_PLATFORM_BACKENDS_H
#define KARMA_PLATFORM_BACKENDS_H

#include "kernels.h"

namespace karma::platform {

extern const Kernels kReferenceKernels; /* reference.cpp */
extern const Kernels kSse4Kernels;      /* sse4.cpp */
extern const Kernels kAvx2Kernels;      /* avx2.cpp */
extern const Kernels kAvx512Kernels;    /* avx512.cpp */

}  // namespace karma::platform

#endif
