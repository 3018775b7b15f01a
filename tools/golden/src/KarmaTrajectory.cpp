/* The C API of KarmaTrajectory.h over karma::golden::TrajectoryWriter.
 * Invariant: no C++ exception crosses this file's functions. */
#include <karma/golden/KarmaTrajectory.h>

#include <karma/golden/GoldenKey.h>
#include <karma/golden/TrajectoryWriter.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>

struct KarmaTrajectoryWriter {
  std::unique_ptr<karma::golden::TrajectoryWriter> writer;
  std::string error; /* empty while all is well */
};

namespace {

/* Runs `f` on a healthy writer; records the first error. */
template <class F>
MeBool Guard(KarmaTrajectoryWriter *w, F &&f) {
  if (!w || !w->error.empty() || !w->writer) return FALSE;
  try {
    f(*w->writer);
    return TRUE;
  } catch (const std::exception &e) {
    w->error = e.what();
  } catch (...) {
    w->error = "unknown error";
  }
  return FALSE;
}

}  // namespace

KarmaTrajectoryWriter *MEAPI KarmaTrajectoryWriterCreate(const char *path, const KarmaTrajectoryInfo *info) {
  auto *w = new (std::nothrow) KarmaTrajectoryWriter;
  if (!w) return nullptr;
  try {
    if (!info || !info->program) {
      w->error = "KarmaTrajectoryWriterCreate: info and info->program are required";
      return w;
    }
    karma::golden::TrajectoryHeader header;
    header.program = info->program;
    header.step = info->step ? info->step : "main";
    header.backend = info->backend ? info->backend : "reference";
    header.sampling = info->sampling ? info->sampling : "";
    header.precision = karma::golden::kBuildPrecision;
    header.timeStep = info->timeStep;
    header.bodyCount = info->bodyCount;
    if (path)
      w->writer = std::make_unique<karma::golden::TrajectoryWriter>(header, std::filesystem::path(path));
    else
      w->writer = std::make_unique<karma::golden::TrajectoryWriter>(header, nullptr);
  } catch (const std::exception &e) {
    w->error = e.what();
  }
  return w;
}

MeBool MEAPI KarmaTrajectoryWriterBeginFrame(KarmaTrajectoryWriter *w, long frame, MeReal time) {
  return Guard(w, [&](karma::golden::TrajectoryWriter &t) { t.BeginFrame(frame, time); });
}

MeBool MEAPI KarmaTrajectoryWriterAddBody(KarmaTrajectoryWriter *w, const MeReal position[3],
                                          const MeReal quaternion[4], const MeReal linearVelocity[3],
                                          const MeReal angularVelocity[3]) {
  if (w && w->error.empty() && (!position || !quaternion || !linearVelocity || !angularVelocity)) {
    w->error = "KarmaTrajectoryWriterAddBody: NULL array";
    return FALSE;
  }
  return Guard(
      w, [&](karma::golden::TrajectoryWriter &t) { t.AddBody(position, quaternion, linearVelocity, angularVelocity); });
}

MeBool MEAPI KarmaTrajectoryWriterEndFrame(KarmaTrajectoryWriter *w) {
  return Guard(w, [](karma::golden::TrajectoryWriter &t) { t.EndFrame(); });
}

uint64_t MEAPI KarmaTrajectoryWriterHash(const KarmaTrajectoryWriter *w) {
  return (w && w->writer) ? w->writer->Hash() : 0;
}

const char *MEAPI KarmaTrajectoryWriterError(const KarmaTrajectoryWriter *w) {
  if (!w) return "NULL trajectory writer";
  return w->error.empty() ? nullptr : w->error.c_str();
}

MeBool MEAPI KarmaTrajectoryWriterDestroy(KarmaTrajectoryWriter *w) {
  if (!w) return FALSE;
  const MeBool ok = Guard(w, [](karma::golden::TrajectoryWriter &t) { t.Finish(); });
  delete w;
  return ok;
}

void MEAPI KarmaGoldenFormatHash(uint64_t hash, char *text) {
  if (!text) return;
  const std::string s = karma::golden::FormatHash(hash);
  std::memcpy(text, s.c_str(), KARMA_GOLDEN_HASH_TEXT_SIZE);
}

void MEAPI KarmaGoldenFrameFileName(long frame, char *name, int size) {
  if (!name || size <= 0) return;
  std::snprintf(name, static_cast<std::size_t>(size), "%s", karma::golden::FrameFileName(frame).c_str());
}
