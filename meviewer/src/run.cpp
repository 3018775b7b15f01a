/* run.cpp: RRun, the main loop of the guide:
 *
 *   while no exit request:  handle input;  tick(rc, userdata);  draw
 *
 * then exit(0), so the program's atexit cleanup runs. An exit request is
 * RRenderQuit, or -frames N once N frames have been drawn (frame numbers
 * start at 0; with -out, frame k goes to DIR/frame_k.png when k is a
 * multiple of -every). In a window a frame lasts at least 1/60 s, so the
 * simulation runs no faster than real time at the guide's 60 steps/s; with
 * -screenshot the window is saved as the display shows it after the last
 * frame. */
#include "viewer_internal.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

using namespace karma::viewer;

namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

/* Writes frame `frame` if the options ask for it. A failed write stops
 * further writing with one message. */
void OutputFrame(RRender *rc, bool &writeFailed) {
  RRenderPrivate *p = rc->m_pPrivate;
  const ViewerOptions &o = p->options;
  if (o.outDir.empty() || writeFailed || rc->m_nFrame % o.every != 0) return;
  Image image;
  std::string error;
  if (!p->backend->ReadFrame(image) || !WriteFrameImage(o.outDir, rc->m_nFrame, o.bmp, image, error)) {
    MeWarning(0, "RRun: %s; no further frames will be written",
              error.empty() ? "cannot read the frame" : error.c_str());
    writeFailed = true;
    return;
  }
}

/* The shortest frame in a window: 1/60 s. */
constexpr std::chrono::microseconds kWindowFrame{16667};

void SaveScreenshot(RRender *rc) {
  RRenderPrivate *p = rc->m_pPrivate;
  Image shot;
  std::string error;
  if (!p->backend->Screenshot(shot, error) || !WritePng(p->options.screenshot, shot, error))
    MeWarning(0, "RRun: -screenshot %s: %s", p->options.screenshot.c_str(), error.c_str());
}

}  // namespace

void MEAPI RRun(RRender *rc, RMainLoopCallBack tick, void *userdata) {
  if (!rc) {
    MeWarning(0, "RRun: rc is NULL (did RRenderContextCreate fail?); the program ends");
    std::exit(1);
  }
  RRenderPrivate *p = rc->m_pPrivate;
  const ViewerOptions &o = p->options;
  std::unique_ptr<ProgressLine> progress;
  if (!o.outDir.empty())
    progress = std::make_unique<ProgressLine>(
        o.frames, p->videoTempDir.empty() ? "written to " + o.outDir : "for the video " + o.video);
  if (o.frames < 0 && p->backend->Draws() && !p->backend->Live())
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
    SampleAccuracy(rc);
    if (p->backend->Draws()) {
      LoadPendingTextures(rc);
      if (profiled) MeProfileStartSection("render");
      p->backend->DrawFrame(rc);
      if (profiled) MeProfileEndSection("render");
    }
    const Clock::time_point t3 = Clock::now();
    OutputFrame(rc, writeFailed);
    if (progress) progress->FrameDone(rc->m_nFrame + 1);
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
    if (p->backend->Live()) std::this_thread::sleep_until(t0 + kWindowFrame);
  }
  progress.reset();
  if (!o.screenshot.empty()) SaveScreenshot(rc);
  if (!o.video.empty() && !writeFailed) AssembleVideo(o.outDir, o.bmp, o.video);
  if (!p->videoTempDir.empty()) { /* frames made only for the video */
    std::error_code ec;
    std::filesystem::remove_all(p->videoTempDir, ec);
    p->videoTempDir.clear();
  }
  if (o.backend == BackendKind::Bench) PrintBenchReport(times, stdout);
  if (o.backend == BackendKind::Profile) PrintProfileReport(times, stdout);
  if (o.backend == BackendKind::Profile && !p->accuracy.frames.empty()) PrintAccuracyReport(p->accuracy, stdout);
  std::fflush(stdout);
  p->running = false;
  std::exit(0);
}

namespace {

struct NoDataTick {
  RMainLoopCallBackNoData tick;
};

void MEAPI CallNoDataTick(RRender *rc, void *userdata) { static_cast<NoDataTick *>(userdata)->tick(rc); }

}  // namespace

/* The record lives in this frame, which RRun never returns to. */
void MEAPI RRunNoData(RRender *rc, RMainLoopCallBackNoData tick, void *userdata) {
  (void)userdata; /* a tick without user data cannot receive it */
  NoDataTick record{tick};
  RRun(rc, tick ? CallNoDataTick : nullptr, &record);
}
