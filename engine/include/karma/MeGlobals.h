/* MeGlobals.h: everything of the MeGlobals layer in one include. */
#ifndef KARMA_MEGLOBALS_H
#define KARMA_MEGLOBALS_H
#include "MeCall.h"
#include "MePrecision.h"
#include "MeMath.h"
#include "MeMemory.h"
#include "MePool.h"
#include "MeChunk.h"
#include "MeMessage.h"
#include "MeCommandLineOptions.h"
#include "MeProfile.h"
#include "MeDiagnostics.h"
#endif
