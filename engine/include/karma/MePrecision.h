/* MePrecision.h: the scalar, vector and matrix types every Karma module uses.
 *
 * MeReal is float by default, as in Karma; configuring with KARMA_DOUBLE=ON
 * makes it double (the choice is recorded in MeConfig.h at configure time, so
 * an installed package and its users always agree).
 *
 * Layouts (the guide's "Conventions"):
 *   MeVector3  = MeReal[3]           MeVector4 = MeReal[4]
 *   MeMatrix3  = MeVector3[3]        rows are the images of the x, y, z axes
 *   MeMatrix4  = MeVector4[4]        an affine transform (TM): rows 0..2 hold
 *                                    the rotated axes with a 0 in column 3,
 *                                    row 3 holds the translation and a 1.
 *   A point p (row vector) maps to p' = p * R + t, i.e.
 *   p'[j] = sum_i p[i] * m[i][j] + m[3][j].
 * Quaternions are MeVector4 ordered (w, x, y, z). */
#ifndef KARMA_MEPRECISION_H
#define KARMA_MEPRECISION_H

#include "MeCall.h"
#include "MeConfig.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

#if KARMA_DOUBLE
typedef double MeReal;
#  define ME_REAL_MAX DBL_MAX
#  define ME_REAL_EPSILON DBL_EPSILON
#  define MeSqrt(x) sqrt(x)
#  define MeFabs(x) fabs(x)
#  define MeSin(x) sin(x)
#  define MeCos(x) cos(x)
#  define MeTan(x) tan(x)
#  define MeAcos(x) acos(x)
#  define MeAsin(x) asin(x)
#  define MeAtan2(y, x) atan2(y, x)
#  define MeFmod(x, y) fmod(x, y)
#  define MePow(x, y) pow(x, y)
#else
typedef float MeReal;
#  define ME_REAL_MAX FLT_MAX
#  define ME_REAL_EPSILON FLT_EPSILON
#  define MeSqrt(x) sqrtf(x)
#  define MeFabs(x) fabsf(x)
#  define MeSin(x) sinf(x)
#  define MeCos(x) cosf(x)
#  define MeTan(x) tanf(x)
#  define MeAcos(x) acosf(x)
#  define MeAsin(x) asinf(x)
#  define MeAtan2(y, x) atan2f(y, x)
#  define MeFmod(x, y) fmodf(x, y)
#  define MePow(x, y) powf(x, y)
#endif

#define MeRecip(x) ((MeReal)1 / (x))
#define MeSqr(x) ((x) * (x))

typedef MeReal MeVector3[3];
typedef MeReal MeVector4[4];
typedef MeVector3 MeMatrix3[3];
typedef MeVector4 MeMatrix4[4];

typedef MeReal *MeVector3Ptr;
typedef MeReal *MeVector4Ptr;
typedef MeVector3 *MeMatrix3Ptr;
typedef MeVector4 *MeMatrix4Ptr;

typedef int32_t MeI32;
typedef uint32_t MeU32;
typedef int16_t MeI16;
typedef uint16_t MeU16;
typedef int8_t MeI8;
typedef uint8_t MeU8;
typedef int MeBool;

#ifndef TRUE
#  define TRUE 1
#endif
#ifndef FALSE
#  define FALSE 0
#endif

/* MEINFINITY is the largest finite MeReal, not IEEE infinity: the guide uses it
 * for "unbounded" stiffnesses, forces and friction, and keeping it finite means
 * 0 * MEINFINITY is 0, never NaN. Treat any value >= MEINFINITY as unbounded. */
#define MEINFINITY ((MeReal)ME_REAL_MAX)

#define ME_PI ((MeReal)3.14159265358979323846)
#define ME_HALF_PI ((MeReal)1.57079632679489661923)
#define ME_TWO_PI ((MeReal)6.28318530717958647692)

/* MeALIGNDATA(type, name, bytes) declares `name` of `type` aligned to `bytes`,
 * as in `MeALIGNDATA(MeMatrix4, tm, 16) = { ... };`. */
#if defined(_MSC_VER)
#  define MeALIGNDATA(type, name, bytes) __declspec(align(bytes)) type name
#else
#  define MeALIGNDATA(type, name, bytes) type name __attribute__((aligned(bytes)))
#endif

#endif /* KARMA_MEPRECISION_H */
