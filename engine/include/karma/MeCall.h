/* MeCall.h: calling-convention and symbol-visibility macros of the Karma API.
 *
 * MEAPI        the calling convention of every API function (empty on the
 *              platforms we build for: the System V ABI has only one).
 * MEAPI_CDECL  the convention of callbacks the C runtime calls (main, atexit).
 * MEPUBLIC     marks a symbol exported from a shared Karma library. */
#ifndef KARMA_MECALL_H
#define KARMA_MECALL_H

#if defined(_WIN32)
#  define MEAPI __stdcall
#  define MEAPI_CDECL __cdecl
#  if defined(KARMA_SHARED_BUILD)
#    define MEPUBLIC __declspec(dllexport)
#  elif defined(KARMA_SHARED)
#    define MEPUBLIC __declspec(dllimport)
#  else
#    define MEPUBLIC
#  endif
#else
#  define MEAPI
#  define MEAPI_CDECL
#  define MEPUBLIC __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
#  define ME_EXTERN_C_BEGIN extern "C" {
#  define ME_EXTERN_C_END }
#else
#  define ME_EXTERN_C_BEGIN
#  define ME_EXTERN_C_END
#endif

#endif /* KARMA_MECALL_H */
