/* karma_demo: the project's placeholder demo until the tutorials replace it.
 *
 * Three balls launched under gravity bounce on the ground (balls.h), with no
 * physics engine involved: it exists to exercise the golden-output toolkit end
 * to end. Frame k is the state at time k h (frame 0 is the initial state).
 *
 *   karma_demo [-frames N] [-trajectory FILE] [-out DIR] [-size WxH] [-platform NAME] [-help]
 *
 * -trajectory writes every 10th frame and the last; -out writes frames 0, N/2
 * and N-1 as DIR/frame_NNNNN.png. The last line printed is the state hash of
 * the sampled frames, equal to the trajectory's final-hash. */
#define _POSIX_C_SOURCE 200809L

#include "balls.h"
#include "render.h"

#include <karma/golden/KarmaTrajectory.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SAMPLE_EVERY 10

typedef struct Options {
  int frames;
  const char *trajectory; /* NULL: only hash */
  const char *outDir;     /* NULL: no images */
  int width, height;
} Options;

static void Usage(FILE *f) {
  fprintf(f,
          "usage: karma_demo [-frames N] [-trajectory FILE] [-out DIR] [-size WxH] [-platform reference] [-help]\n"
          "  -frames N         frames to simulate (default 240; frame k is time k/60 s)\n"
          "  -trajectory FILE  write the trajectory (every %dth frame and the last)\n"
          "  -out DIR          write frames 0, N/2 and N-1 as DIR/frame_NNNNN.png\n"
          "  -size WxH         image size (default 320x240)\n"
          "  -platform NAME    only 'reference': the demo has no other backend\n",
          SAMPLE_EVERY);
}

/* Whole-string decimal integer in [lo, hi]. */
static int ParseInt(const char *text, int lo, int hi, int *out) {
  char *end;
  long v;
  errno = 0;
  v = strtol(text, &end, 10);
  if (errno || end == text || *end || v < lo || v > hi) return 0;
  *out = (int)v;
  return 1;
}

/* "WxH" with both in 16..8192. */
static int ParseSize(const char *text, int *width, int *height) {
  char w[16];
  const char *x = strchr(text, 'x');
  if (!x || x == text || x - text >= (long)sizeof w) return 0;
  memcpy(w, text, (size_t)(x - text));
  w[x - text] = '\0';
  return ParseInt(w, 16, 8192, width) && ParseInt(x + 1, 16, 8192, height);
}

/* Returns 0 to run, 1 after -help, 2 on a usage error. */
static int ParseOptions(int argc, char **argv, Options *o) {
  int i;
  o->frames = 240, o->trajectory = NULL, o->outDir = NULL, o->width = 320, o->height = 240;
  for (i = 1; i < argc; ++i) {
    const char *a = argv[i];
    const char *value = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "-help") || !strcmp(a, "--help") || !strcmp(a, "-h")) {
      Usage(stdout);
      return 1;
    }
    if (!value) {
      fprintf(stderr, "karma_demo: unknown option or missing value: %s\n", a);
      Usage(stderr);
      return 2;
    }
    if (!strcmp(a, "-frames")) {
      if (!ParseInt(value, 1, 10000000, &o->frames)) return fprintf(stderr, "karma_demo: bad -frames %s\n", value), 2;
    } else if (!strcmp(a, "-trajectory")) {
      o->trajectory = value;
    } else if (!strcmp(a, "-out")) {
      o->outDir = value;
    } else if (!strcmp(a, "-size")) {
      if (!ParseSize(value, &o->width, &o->height))
        return fprintf(stderr, "karma_demo: bad -size %s (want WxH, 16..8192)\n", value), 2;
    } else if (!strcmp(a, "-platform")) {
      if (strcmp(value, "reference"))
        return fprintf(stderr, "karma_demo: no platform backend '%s' (the demo has only 'reference')\n", value), 2;
    } else {
      fprintf(stderr, "karma_demo: unknown option %s\n", a);
      Usage(stderr);
      return 2;
    }
    ++i;
  }
  return 0;
}

static int IsImageFrame(int frame, int frames) { return frame == 0 || frame == frames / 2 || frame == frames - 1; }

int main(int argc, char **argv) {
  Options o;
  DemoWorld world;
  DemoRenderer *renderer = NULL;
  KarmaTrajectoryWriter *trajectory;
  KarmaTrajectoryInfo info;
  const MeReal h = (MeReal)1 / (MeReal)60;
  char hashText[KARMA_GOLDEN_HASH_TEXT_SIZE];
  int frame, i, ok = 1;
  const int parsed = ParseOptions(argc, argv, &o);
  if (parsed) return parsed == 1 ? 0 : 2;

  printf(
      "karma_demo: %d balls launched under gravity, bouncing on the ground (restitution 0.7)\n"
      "and spinning at constant rates; semi-implicit Euler, h = 1/60 s, %d frames, MeReal = %s.\n",
      DEMO_BALL_COUNT, o.frames, KARMA_DOUBLE ? "double" : "float");

  if (o.outDir) {
    if (mkdir(o.outDir, 0777) != 0 && errno != EEXIST) {
      fprintf(stderr, "karma_demo: cannot create %s: %s\n", o.outDir, strerror(errno));
      return 2;
    }
    renderer = DemoRendererCreate(o.width, o.height, o.frames);
    if (!renderer) return fprintf(stderr, "karma_demo: out of memory\n"), 2;
  }

  info.program = "demo";
  info.step = "main";
  info.backend = "reference";
  info.sampling = "every 10th frame and the last";
  info.timeStep = h;
  info.bodyCount = DEMO_BALL_COUNT;
  trajectory = KarmaTrajectoryWriterCreate(o.trajectory, &info);
  if (!trajectory || KarmaTrajectoryWriterError(trajectory)) {
    fprintf(stderr, "karma_demo: %s\n", trajectory ? KarmaTrajectoryWriterError(trajectory) : "out of memory");
    KarmaTrajectoryWriterDestroy(trajectory);
    DemoRendererDestroy(renderer);
    return 2;
  }

  DemoWorldInit(&world);
  for (frame = 0; frame < o.frames && ok; ++frame) {
    if (frame > 0) DemoWorldStep(&world, h);
    if (frame % SAMPLE_EVERY == 0 || frame == o.frames - 1) {
      ok = KarmaTrajectoryWriterBeginFrame(trajectory, frame, (MeReal)frame * h);
      for (i = 0; i < DEMO_BALL_COUNT; ++i) {
        const DemoBall *b = &world.balls[i];
        ok = ok && KarmaTrajectoryWriterAddBody(trajectory, b->position, b->quaternion, b->linearVelocity,
                                                b->angularVelocity);
      }
      ok = ok && KarmaTrajectoryWriterEndFrame(trajectory);
    }
    if (renderer) {
      DemoRendererRecord(renderer, &world, frame);
      if (IsImageFrame(frame, o.frames)) {
        char name[64], path[4096];
        KarmaGoldenFrameFileName(frame, name, (int)sizeof name);
        snprintf(path, sizeof path, "%s/%s", o.outDir, name);
        if (!DemoRendererWritePng(renderer, &world, frame, o.frames, path)) {
          fprintf(stderr, "karma_demo: cannot write %s\n", path);
          ok = 0;
        }
      }
    }
  }

  for (i = 0; i < DEMO_BALL_COUNT; ++i) {
    const DemoBall *b = &world.balls[i];
    printf("ball %d at (%.3f, %.3f) moving (%.3f, %.3f) m/s\n", i, (double)b->position[0], (double)b->position[1],
           (double)b->linearVelocity[0], (double)b->linearVelocity[1]);
  }
  KarmaGoldenFormatHash(KarmaTrajectoryWriterHash(trajectory), hashText);
  if (KarmaTrajectoryWriterError(trajectory))
    fprintf(stderr, "karma_demo: %s\n", KarmaTrajectoryWriterError(trajectory));
  if (!KarmaTrajectoryWriterDestroy(trajectory)) {
    if (ok)
      fprintf(stderr, "karma_demo: could not finish the trajectory file %s\n", o.trajectory ? o.trajectory : "(none)");
    ok = 0;
  }
  DemoRendererDestroy(renderer);
  printf("state hash: %s\n", hashText);
  return ok ? 0 : 1;
}
