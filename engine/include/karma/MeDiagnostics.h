/* MeDiagnostics.h: a process-wide list of diagnostic sources, so a tool
 * that knows only MeGlobals (MeViewer's -accuracy overlay and -profile) can
 * read accuracy figures from every simulation a program made, without the
 * program naming them. An extension; the guide has no counterpart.
 *
 * Every MdtWorld registers itself when created and unregisters when
 * destroyed. A source fills MeDiagnosticFigures:
 *   jointError   the largest gap of a joint whose two attachment points
 *                should coincide (ball-and-socket, hinge, universal,
 *                skeletal), m
 *   penetration  the deepest penetration of the enabled contacts, m
 *   energyDrift  kinetic plus potential energy of the bodies now, minus
 *                its value when first read (a body first seen later joins
 *                at its energy then), J
 *   residual     the exact solver's largest residual in the last step
 *   platform     the name of the platform backend the source's last step
 *                ran on (MdtPlatform.h), or NULL for a source without one;
 *                a static string
 * Sources are listed in registration order. Not thread-safe: register,
 * unregister and read from one thread. */
#ifndef KARMA_ME_DIAGNOSTICS_H
#define KARMA_ME_DIAGNOSTICS_H

#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct MeDiagnosticFigures {
  MeReal jointError;
  MeReal penetration;
  MeReal energyDrift;
  MeReal residual;
  const char *platform;
} MeDiagnosticFigures;

typedef void(MEAPI *MeDiagnosticRead)(void *owner, MeDiagnosticFigures *figures);

/* Adds `owner` with its reader; an owner already listed is not added twice.
 * NULL owner or reader: a warning, nothing added. */
MEPUBLIC void MEAPI MeDiagnosticSourceRegister(void *owner, MeDiagnosticRead read);
/* Removes `owner`; an owner not listed is ignored. */
MEPUBLIC void MEAPI MeDiagnosticSourceUnregister(void *owner);
/* How many sources are listed. */
MEPUBLIC int MEAPI MeDiagnosticSourceCount(void);
/* Fills `figures` from source i (0 <= i < count); FALSE, figures zeroed,
 * when i is out of range. */
MEPUBLIC MeBool MEAPI MeDiagnosticSourceRead(int i, MeDiagnosticFigures *figures);

ME_EXTERN_C_END

#endif
