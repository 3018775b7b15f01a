// tutorial_record.cpp: see tutorial_record.h. A thin layer over the golden
// toolkit's KarmaTrajectoryWriter: sampling, the options, the atexit end.
#include "tutorial_record.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <karma/golden/KarmaTrajectory.h>

// One body's state as the trajectory records it.
struct BodyState {
  MeVector3 x, v, w;
  MeVector4 q;
};

struct TutorialRecord {
  KarmaTrajectoryWriter *writer = nullptr;
  std::vector<MdtBodyID> bodies;
  // The state after the latest step when it was not written: the atexit
  // end writes it from here, since the program's own cleanup may already
  // have destroyed the bodies.
  std::vector<BodyState> latest;
  MeReal timeStep = 0;
  int every = 1;
  long steps = 0;
  long lastWritten = -1;  // the last frame written, -1 before Start
  char program[64] = {};
  char step[64] = {};
  char sampling[64] = {};
  const char *path = nullptr;
  // The backend -platform asked for, resolved to one the CPU runs; empty
  // without the option.
  char platform[32] = {};
  // The backend the recorded bodies' world steps on (the trajectory's
  // "backend" field), known at Start.
  char backend[32] = {};
};

namespace {

TutorialRecord *active = nullptr;  // the one record; ended by atexit

const char *OptionValue(int argc, char **argv, const char *name) {
  const char *value = nullptr;
  for (int i = 1; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], name)) value = argv[i + 1];
  return value;
}

bool KnownPlatform(const char *name) {
  for (int i = 0; i < MdtPlatformCount(); ++i)
    if (!std::strcmp(MdtPlatformName(i), name)) return true;
  return false;
}

// -platform NAME: an unknown name ends the program (status 2); a backend the
// CPU cannot run gives a warning and the best one. The process default is
// set so that worlds created from now on use it. MeViewer, whose context
// the programs create first, may have set it already: then nothing is done
// (and nothing is warned twice).
void ApplyPlatformOption(const char *program, const char *name, char (&resolvedOut)[32]) {
  if (!KnownPlatform(name)) {
    std::fprintf(stderr, "%s: no platform backend '%s' (available:", program, name);
    for (int i = 0; i < MdtPlatformCount(); ++i) std::fprintf(stderr, " %s", MdtPlatformName(i));
    std::fprintf(stderr, ")\n");
    std::exit(2);
  }
  const char *resolved = MdtPlatformIsSupported(name) ? name : MdtPlatformGetBestName();
  if (std::strcmp(MdtPlatformGetDefaultName(), resolved) != 0) MdtPlatformSetDefault(name);
  std::snprintf(resolvedOut, sizeof resolvedOut, "%s", resolved);
}

// At Start: the recorded bodies' worlds made before -platform was read
// are switched to it; the backend recorded is their world's.
void SettlePlatform(TutorialRecord *rec) {
  MdtWorldID world = rec->bodies.empty() ? nullptr : MdtBodyGetWorld(rec->bodies.front());
  if (rec->platform[0])
    for (MdtBodyID b : rec->bodies)
      if (std::strcmp(MdtWorldGetPlatformName(MdtBodyGetWorld(b)), rec->platform) != 0)
        MdtWorldSetPlatform(MdtBodyGetWorld(b), rec->platform);
  const char *name = world ? MdtWorldGetPlatformName(world) : MdtPlatformGetDefaultName();
  std::snprintf(rec->backend, sizeof rec->backend, "%s", name);
}

void Capture(const TutorialRecord *rec, std::vector<BodyState> &out) {
  out.resize(rec->bodies.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    MdtBodyID b = rec->bodies[i];
    MdtBodyGetPosition(b, out[i].x);
    MdtBodyGetQuaternion(b, out[i].q);
    MdtBodyGetLinearVelocity(b, out[i].v);
    MdtBodyGetAngularVelocity(b, out[i].w);
  }
}

void WriteFrame(TutorialRecord *rec, const std::vector<BodyState> &states) {
  if (!rec->writer) return;
  KarmaTrajectoryWriterBeginFrame(rec->writer, rec->steps, (MeReal)rec->steps * rec->timeStep);
  for (const BodyState &s : states) KarmaTrajectoryWriterAddBody(rec->writer, s.x, s.q, s.v, s.w);
  KarmaTrajectoryWriterEndFrame(rec->writer);
  rec->lastWritten = rec->steps;
}

void Finish() {
  TutorialRecord *rec = active;
  if (!rec) return;
  active = nullptr;
  if (rec->writer) {
    if (rec->lastWritten >= 0 && rec->lastWritten != rec->steps) WriteFrame(rec, rec->latest);
    char hash[KARMA_GOLDEN_HASH_TEXT_SIZE];
    KarmaGoldenFormatHash(KarmaTrajectoryWriterHash(rec->writer), hash);
    std::printf("platform backend: %s\n", rec->backend);
    std::printf("state hash: %s\n", hash);
    std::fflush(stdout);
    if (const char *error = KarmaTrajectoryWriterError(rec->writer))
      std::fprintf(stderr, "%s: trajectory: %s\n", rec->program, error);
    KarmaTrajectoryWriterDestroy(rec->writer);
  }
  delete rec;
}

}  // namespace

extern "C" {

TutorialRecord *TutorialRecordCreate(int argc, char **argv, const char *program, const char *step, MeReal timeStep,
                                     int every) {
  if (active) {
    std::fprintf(stderr, "%s: a tutorial record already exists\n", program);
    return nullptr;
  }
  char platform[32] = {};
  if (const char *name = OptionValue(argc, argv, "-platform")) ApplyPlatformOption(program, name, platform);
  auto *rec = new (std::nothrow) TutorialRecord;
  if (!rec) return nullptr;
  std::snprintf(rec->platform, sizeof rec->platform, "%s", platform);
  std::snprintf(rec->program, sizeof rec->program, "%s", program);
  std::snprintf(rec->step, sizeof rec->step, "%s", step ? step : "main");
  rec->every = every < 1 ? 1 : every;
  rec->timeStep = timeStep;
  std::snprintf(rec->sampling, sizeof rec->sampling, "every %dth step and the last", rec->every);
  rec->path = OptionValue(argc, argv, "-trajectory");
  active = rec;
  std::atexit(Finish);
  return rec;
}

void TutorialRecordAddBody(TutorialRecord *rec, MdtBodyID body) {
  if (!rec || !body) return;
  if (rec->lastWritten >= 0) {
    std::fprintf(stderr, "%s: TutorialRecordAddBody after TutorialRecordStart; ignored\n", rec->program);
    return;
  }
  rec->bodies.push_back(body);
}

void TutorialRecordStart(TutorialRecord *rec) {
  if (!rec || rec->lastWritten >= 0) return;
  SettlePlatform(rec);
  KarmaTrajectoryInfo info = {rec->program,  rec->step,     rec->backend,
                              rec->sampling, rec->timeStep, (int)rec->bodies.size()};
  rec->writer = KarmaTrajectoryWriterCreate(rec->path, &info);
  if (rec->writer && KarmaTrajectoryWriterError(rec->writer))
    std::fprintf(stderr, "%s: trajectory: %s\n", rec->program, KarmaTrajectoryWriterError(rec->writer));
  Capture(rec, rec->latest);
  WriteFrame(rec, rec->latest);
}

void TutorialRecordStep(TutorialRecord *rec) {
  if (!rec) return;
  ++rec->steps;
  if (rec->lastWritten < 0) return;
  Capture(rec, rec->latest);
  if (rec->steps % rec->every == 0) WriteFrame(rec, rec->latest);
}

long TutorialRecordSteps(const TutorialRecord *rec) { return rec ? rec->steps : 0; }

}  // extern "C"
