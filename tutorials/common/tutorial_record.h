/* tutorial_record.h: pins a tutorial run for its golden test.
 *
 * Every tutorial program (QuadBike's steps, RainbowChain, Ballman,
 * CarTerrain, the chapter samples) records the same thing: the state of its
 * bodies every `every` simulation steps and after the last one, written as a
 * golden trajectory (docs/GOLDEN.md) when the command line has
 * `-trajectory FILE`, and the run's state hash printed as
 * `state hash: 0x...` when the program ends.
 *
 *   TutorialRecord *rec = TutorialRecordCreate(argc, argv, "quadbike", "step05", h, 10);
 *   TutorialRecordAddBody(rec, chassis);  ... (file order = call order)
 *   TutorialRecordStart(rec);             frame 0: the state before any step
 *   ... after every MstUniverseStep / MdtWorldStep:
 *   TutorialRecordStep(rec);
 *
 * The program ends however it likes (RRun ends through exit()): an atexit
 * handler writes the last step's frame if it was not sampled (from a copy
 * taken at that step, so the program's own atexit cleanup may run first
 * and destroy the bodies), the final hash, and prints the hash. A failure to write the file is reported on
 * stderr; the exit status cannot change from atexit, so it is the golden
 * test that fails, on the incomplete file.
 *
 * Options read (and left in argv for MeViewer, which ignores them):
 *   -trajectory FILE   write the trajectory there
 *   -platform NAME     the platform backend (MdtPlatform.h): the process
 *                      default from TutorialRecordCreate on, and, at
 *                      TutorialRecordStart, the backend of the recorded
 *                      bodies' world if it was made earlier. A backend the
 *                      CPU cannot run gives a warning and the best one; an
 *                      unknown name prints an error and exits with status 2.
 * The trajectory's "backend" field and the line "platform backend: NAME"
 * printed before the hash name the backend the recorded world stepped on.
 * Only one record may exist at a time. */
#ifndef KARMA_TUTORIAL_RECORD_H
#define KARMA_TUTORIAL_RECORD_H

#include "Mdt.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct TutorialRecord TutorialRecord;

/* Reads the options; `every` >= 1. Returns NULL (after a message) only
 * when out of memory or when a record already exists. */
TutorialRecord *TutorialRecordCreate(int argc, char **argv, const char *program, const char *step, MeReal timeStep,
                                     int every);
/* Adds a body to the recorded set; only before TutorialRecordStart. */
void TutorialRecordAddBody(TutorialRecord *rec, MdtBodyID body);
/* Writes frame 0 (the state before the first step). */
void TutorialRecordStart(TutorialRecord *rec);
/* Counts one simulation step and samples it when due. */
void TutorialRecordStep(TutorialRecord *rec);
/* Steps counted so far. */
long TutorialRecordSteps(const TutorialRecord *rec);

#ifdef __cplusplus
}
#endif

#endif
