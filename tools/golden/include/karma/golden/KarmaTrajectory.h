/* KarmaTrajectory.h: C API for writing trajectories and printing the state hash,
 * for C-style programs such as the tutorials. A thin layer over
 * karma::golden::TrajectoryWriter (TrajectoryWriter.h has the file format).
 *
 *   KarmaTrajectoryInfo info = {"demo", "main", "reference", "every 10th frame and the last", h, 3};
 *   KarmaTrajectoryWriter *w = KarmaTrajectoryWriterCreate(path_or_NULL, &info);
 *   ...per sampled frame:
 *     KarmaTrajectoryWriterBeginFrame(w, frame, time);
 *     KarmaTrajectoryWriterAddBody(w, pos, quat, linvel, angvel);   (once per body)
 *     KarmaTrajectoryWriterEndFrame(w);
 *   ...
 *   char text[KARMA_GOLDEN_HASH_TEXT_SIZE];
 *   KarmaGoldenFormatHash(KarmaTrajectoryWriterHash(w), text);
 *   printf("state hash: %s\n", text);
 *   if (!KarmaTrajectoryWriterDestroy(w)) ... the file is incomplete
 *
 * Errors never abort: a failing call returns 0 and records a message
 * (KarmaTrajectoryWriterError); later calls on that writer do nothing and
 * return 0. A NULL path keeps only the hash. */
#ifndef KARMA_GOLDEN_KARMATRAJECTORY_H
#define KARMA_GOLDEN_KARMATRAJECTORY_H

#include <karma/MePrecision.h>

#include <stdint.h>

ME_EXTERN_C_BEGIN

typedef struct KarmaTrajectoryWriter KarmaTrajectoryWriter;

typedef struct KarmaTrajectoryInfo {
  const char *program;  /* required */
  const char *step;     /* NULL = "main" */
  const char *backend;  /* NULL = "reference" */
  const char *sampling; /* NULL = "" */
  MeReal timeStep;
  int bodyCount;
} KarmaTrajectoryInfo;

/* "0x" + 16 hex digits + NUL. */
#define KARMA_GOLDEN_HASH_TEXT_SIZE 19

/* Never returns NULL except when out of memory; check KarmaTrajectoryWriterError. */
MEPUBLIC KarmaTrajectoryWriter *MEAPI KarmaTrajectoryWriterCreate(const char *path, const KarmaTrajectoryInfo *info);
MEPUBLIC MeBool MEAPI KarmaTrajectoryWriterBeginFrame(KarmaTrajectoryWriter *w, long frame, MeReal time);
MEPUBLIC MeBool MEAPI KarmaTrajectoryWriterAddBody(KarmaTrajectoryWriter *w, const MeReal position[3],
                                                   const MeReal quaternion[4], const MeReal linearVelocity[3],
                                                   const MeReal angularVelocity[3]);
MEPUBLIC MeBool MEAPI KarmaTrajectoryWriterEndFrame(KarmaTrajectoryWriter *w);
/* Running state hash over the frames ended so far. */
MEPUBLIC uint64_t MEAPI KarmaTrajectoryWriterHash(const KarmaTrajectoryWriter *w);
/* NULL while no error has happened. */
MEPUBLIC const char *MEAPI KarmaTrajectoryWriterError(const KarmaTrajectoryWriter *w);
/* Writes the final-hash line, closes the file and frees the writer. Returns 1
 * if the whole file was written without error. Accepts NULL. */
MEPUBLIC MeBool MEAPI KarmaTrajectoryWriterDestroy(KarmaTrajectoryWriter *w);

/* Writes "0x%016x" into text (KARMA_GOLDEN_HASH_TEXT_SIZE bytes). */
MEPUBLIC void MEAPI KarmaGoldenFormatHash(uint64_t hash, char *text);
/* Writes the golden frame file name ("frame_00042.png") into name (size bytes,
 * truncated and NUL-terminated if too small). */
MEPUBLIC void MEAPI KarmaGoldenFrameFileName(long frame, char *name, int size);

ME_EXTERN_C_END

#endif
