/* run.cpp: RRun, the main loop of the guide:
 *
 *   while no exit request:  handle input;  tick(rc, userdata);  draw
 *
 * then exit(0), so the program's atexit cleanup runs. An exit request is
 * RRenderQuit, or -frames N once N frames have been drawn (frame numbers
 * start at 0; with -out, frame k goes to DIR/frame_k.png when k is a
 * multiple of -every). */
#include "viewer_internal.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

using namespace karma::viewer;

namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

/* Writes frame `frame` if the options ask for it; shows progress on a
 * terminal. A failed write stops further writing with one message. */
void OutputFrame(RRender *rc, bool &writeFailed, bool progress) {
  RRenderPrivate *p = rc->m_pPrivate;
  const ViewerOptions &o = p->options;
  if (o.outDir.empty() || writeFailed || rc->m_nFrame % o.every != 0) return;
  Image image;
  std::string error;
  if (!p->backend->ReadFrame(image) || !WriteFrameImage(o.outDir, rc->m_nFrame, o.bmp, image, error)) {
    MeWarning(0, "RRun: %s; no further frames will be written", error.empty() ? "cannot read the frame" : error.c_str());
    writeFailed = true;
    return;
  }
  if (progress) {
    if (o.frames >= 0)
      std::fprintf(stderr, "\rMeViewer: frame %d of %ld written to %s", rc->m_nFrame + 1, o.frames, o.outDir.c_str());
    else
      std::fprintf(stderr, "\rMeViewer: frame %d written to %s", rc->m_nFrame + 1, o.outDir.c_str());
    std::fflush(stderr);
  }
}

} // namespace

void MEAPI RRun(RRender *rc, RMainLoopCallBack tick, void *userdata) {
  if (!rc) {
    MeWarning(0, "RRun: rc is NULL (did RRenderContextCreate fail?); the program ends");
    std::exit(1);
  }
  RRenderPrivate *p = rc->m_pPrivate;
  const ViewerOptions &o = p->options;
  const bool progress = !o.outDir.empty() && p->videoTempDir.empty() && isatty(STDERR_FILENO);
  if (o.frames < 0 && p->backend->Draws())
    MeInfo(0, "MeViewer: drawing offscreen with no frame limit; pass -frames N to stop after N frames");
  p->running = true;
  LoadPendingTextures(rc);

  FrameTimes times;
  const bool timed = o.backend == BackendKind::Bench || o.backend == BackendKind::Profile;
  bool writeFailed = false;
  while (!p->quit && (o.frames < 0 || rc->m_nFrame < o.frames)) {
    const bool profiled = p->bar != nullptr; /* the bar reads MeProfile's last frame */
    if (profiled) MeProfileStartFrame();
    const Clock::time_point t0 = Clock::now();
    ProcessInput(rc); /* the key script's events for this frame */
    const Clock::time_point t1 = Clock::now();
    if (tick && !p->paused) tick(rc, userdata); /* the help pauses the simulation */
    const Clock::time_point t2 = Clock::now();
    if (p->backend->Draws()) {
      LoadPendingTextures(rc);
      if (profiled) MeProfileStartSection("render");
      p->backend->DrawFrame(rc);
      if (profiled) MeProfileEndSection("render");
    }
    const Clock::time_point t3 = Clock::now();
    OutputFrame(rc, writeFailed, progress);
    const Clock::time_point t4 = Clock::now();
    if (timed) {
      times.input.push_back(Ms(t0, t1));
      times.tick.push_back(Ms(t1, t2));
      times.render.push_back(Ms(t2, t3));
      times.output.push_back(Ms(t3, t4));
      times.total.push_back(Ms(t0, t4));
    }
    if (profiled) MeProfileEndFrame();
    ++rc->m_nFrame;
  }
  if (progress) std::fputc('\n', stderr);
  if (!o.video.empty() && !writeFailed) AssembleVideo(o.outDir, o.bmp, o.video);
  if (!p->videoTempDir.empty()) { /* frames made only for the video */
    std::error_code ec;
    std::filesystem::remove_all(p->videoTempDir, ec);
    p->videoTempDir.clear();
  }
  if (o.backend == BackendKind::Bench) PrintBenchReport(times, stdout);
  if (o.backend == BackendKind::Profile) PrintProfileReport(times, stdout);
  std::fflush(stdout);
  p->running = false;
  std::exit(0);
}

namespace {

struct NoDataTick {
  RMainLoopCallBackNoData tick;
};

void MEAPI CallNoDataTick(RRender *rc, void *userdata) { static_cast<NoDataTick *>(userdata)->tick(rc); }

} // namespace

/* The record lives in this frame, which RRun never returns to. */
void MEAPI RRunNoData(RRender *rc, RMainLoopCallBackNoData tick, void *userdata) {
  (void)userdata; /* a tick without user data cannot receive it */
  NoDataTick record{tick};
  RRun(rc, tick ? CallNoDataTick : nullptr, &record);
}
