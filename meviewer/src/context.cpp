/* context.cpp: creating and destroying render contexts, and the defaults
 * a new context starts with.
 *
 * Defaults: camera looking at the origin from distance 10 along +z
 * (theta = phi = 0), 45 degree vertical field of view; ambient light 0.3
 * grey; directional light 1 (white, diffuse 0.7, specular 0.4) travelling
 * along (-0.5, -1, -0.3) and light 2 (diffuse 0.3) along (0.6, -0.3, 0.8),
 * both on; the point light off, white, at (0, 5, 0) with attenuation
 * 1 + 0 d + 0 d^2. */
#include "viewer_internal.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <unistd.h>

using namespace karma::viewer;

namespace {

void Set3(float *d, float a, float b, float c) { d[0] = a, d[1] = b, d[2] = c; }

void SetDefaults(RRender *rc) {
  rc->m_AppName = rc->m_AppNameBuffer;
  std::strcpy(rc->m_AppNameBuffer, "Karma");
  rc->m_CameraLookAt[0] = rc->m_CameraLookAt[1] = rc->m_CameraLookAt[2] = 0;
  rc->m_CameraDist = 10;
  rc->m_CameraTheta = 0;
  rc->m_CameraPhi = 0;
  rc->m_CameraFOV = ME_PI / 4;
  RCameraUpdate(rc);

  Set3(rc->m_rgbAmbientLightColor, 0.3f, 0.3f, 0.3f);
  rc->m_bUseAmbientLight = 1;
  RDirectLight &d1 = rc->m_DirectLight1;
  d1.m_bUseLight = 1;
  Set3(d1.m_rgbAmbient, 0, 0, 0);
  Set3(d1.m_rgbDiffuse, 0.7f, 0.7f, 0.7f);
  Set3(d1.m_rgbSpecular, 0.4f, 0.4f, 0.4f);
  Set3(d1.m_Direction, -0.5f, -1.0f, -0.3f);
  RDirectLight &d2 = rc->m_DirectLight2;
  d2.m_bUseLight = 1;
  Set3(d2.m_rgbAmbient, 0, 0, 0);
  Set3(d2.m_rgbDiffuse, 0.3f, 0.3f, 0.3f);
  Set3(d2.m_rgbSpecular, 0, 0, 0);
  Set3(d2.m_Direction, 0.6f, -0.3f, 0.8f);
  RPointLight &p = rc->m_PointLight;
  p.m_bUseLight = 0;
  Set3(p.m_rgbAmbient, 0, 0, 0);
  Set3(p.m_rgbDiffuse, 1, 1, 1);
  Set3(p.m_rgbSpecular, 1, 1, 1);
  Set3(p.m_Position, 0, 5, 0);
  p.m_AttenuationConstant = 1;
  p.m_AttenuationLinear = 0;
  p.m_AttenuationQuadratic = 0;
  Set3(rc->m_BackgroundColour, 0.2f, 0.25f, 0.35f);
}

/* Creates the output directory if needed and proves it writable. */
bool PrepareOutputDir(const std::string &dir, std::string &error) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    error = "the output path '" + dir + "' exists and is not a directory";
    return false;
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    error = "cannot create the output directory '" + dir + "': " + ec.message();
    return false;
  }
  const std::filesystem::path probe = std::filesystem::path(dir) / ".meviewer-write-test";
  {
    std::ofstream f(probe);
    if (!f) {
      error = "cannot write into the output directory '" + dir + "' (permission denied?)";
      return false;
    }
  }
  std::filesystem::remove(probe, ec);
  return true;
}

/* The -keys text, then the -keyfile's, parsed as one script. */
bool ReadKeyScript(const ViewerOptions &opts, std::vector<KeyEvent> &script, std::string &error) {
  std::string text = opts.keys;
  if (!opts.keyFile.empty()) {
    std::ifstream f(opts.keyFile);
    if (!f) {
      error = "cannot read the key file '" + opts.keyFile + "'";
      return false;
    }
    text += "\n";
    text.append(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  }
  return ParseKeyScript(text, script, error);
}

void FreeList(RGraphic *g) {
  while (g) {
    RGraphic *next = g->m_pNext;
    g->m_pNext = nullptr;
    RGraphicDestroy(g);
    g = next;
  }
}

/* The window, the offscreen renderer or nothing, as the options ask. A
 * window that cannot open falls back to offscreen drawing with a warning.
 * NULL (with a warning) when nothing that draws can be made. */
std::unique_ptr<Backend> CreateBackend(ViewerOptions &opts, bool draws) {
  std::string error;
  if (opts.backend == BackendKind::Window) {
    if (std::unique_ptr<Backend> window = CreateWindowBackend(opts.width, opts.height, error)) return window;
    MeWarning(0, "RRenderContextCreate: %s; drawing offscreen instead", error.c_str());
    opts.backend = BackendKind::GL;
    opts.record.clear(), opts.screenshot.clear();
  }
  if (!draws) return CreateNullBackend();
  std::unique_ptr<Backend> gl = CreateGLBackend(opts.width, opts.height, error);
  if (!gl) MeWarning(0, "RRenderContextCreate: %s; no render context (try -null)", error.c_str());
  return gl;
}

}  // namespace

RRender *MEAPI RRenderContextCreate(MeCommandLineOptions *options, MeCommandLineOptions *overrideOptions, MeBool eat) {
  ViewerOptions opts;
  std::string error;
  if (!ParseViewerOptions(options, overrideOptions, eat != 0, opts, error)) {
    MeWarning(0, "RRenderContextCreate: %s ('-help' lists the viewer's options); no render context", error.c_str());
    return nullptr;
  }
  if (opts.help) {
    std::fputs(HelpText(), stdout);
    std::fputs(KeyScriptHelp(), stdout);
    std::fflush(stdout);
    std::exit(0);
  }
  ReportUnknownOptions(options);
  ApplyPlatformOption(opts.platform);

  std::vector<KeyEvent> script;
  if (!ReadKeyScript(opts, script, error)) {
    MeWarning(0, "RRenderContextCreate: %s; no render context", error.c_str());
    return nullptr;
  }

  const bool draws =
      opts.backend == BackendKind::GL || opts.backend == BackendKind::Profile || opts.backend == BackendKind::Window;
  if (opts.backend != BackendKind::Window && (!opts.record.empty() || !opts.screenshot.empty())) {
    MeWarning(0, "RRenderContextCreate: -record and -screenshot need a window (-window); ignored");
    opts.record.clear(), opts.screenshot.clear();
  }
  if (!draws && !opts.outDir.empty()) {
    MeWarning(0, "RRenderContextCreate: -out %s is ignored: the %s backend draws nothing", opts.outDir.c_str(),
              opts.backend == BackendKind::Null ? "-null" : "-bench");
    opts.outDir.clear();
  }
  std::string videoTempDir;
  if (!opts.video.empty()) {
    if (!draws) {
      MeWarning(0, "RRenderContextCreate: -video %s is ignored: nothing is drawn", opts.video.c_str());
      opts.video.clear();
    } else if (FindInPath("ffmpeg").empty()) {
      MeWarning(0,
                "RRenderContextCreate: -video %s: ffmpeg is not installed (Debian package ffmpeg); no video "
                "will be made%s",
                opts.video.c_str(), opts.outDir.empty() ? "" : ", the frames are still written");
      opts.video.clear();
    } else if (opts.outDir.empty()) {
      /* Frames for the video only: a private directory, removed after. */
      std::string pattern = (std::filesystem::temp_directory_path() / "meviewer-video-XXXXXX").string();
      if (!mkdtemp(pattern.data())) {
        MeWarning(0, "RRenderContextCreate: -video: cannot make a temporary frame directory; no render context");
        return nullptr;
      }
      opts.outDir = videoTempDir = pattern;
    }
  }
  if (!opts.outDir.empty() && !PrepareOutputDir(opts.outDir, error)) {
    MeWarning(0, "RRenderContextCreate: %s; no render context", error.c_str());
    return nullptr;
  }

  std::unique_ptr<Backend> backend = CreateBackend(opts, draws);
  if (!backend) return nullptr;

  RRender *rc = static_cast<RRender *>(MeMemoryAPI.createZeroed(sizeof(RRender)));
  if (!rc) {
    MeWarning(0, "RRenderContextCreate: out of memory");
    return nullptr;
  }
  rc->m_pPrivate = new (std::nothrow) RRenderPrivate;
  if (!rc->m_pPrivate) {
    MeMemoryAPI.destroy(rc);
    MeWarning(0, "RRenderContextCreate: out of memory");
    return nullptr;
  }
  rc->m_pPrivate->options = opts;
  rc->m_pPrivate->backend = std::move(backend);
  rc->m_pPrivate->controls.script = std::move(script);
  if (!opts.record.empty()) {
    rc->m_pPrivate->controls.record = std::fopen(opts.record.c_str(), "w");
    if (!rc->m_pPrivate->controls.record)
      MeWarning(0, "RRenderContextCreate: cannot write the key record '%s'; nothing is recorded", opts.record.c_str());
  }
  rc->m_pPrivate->videoTempDir = videoTempDir;
  rc->m_pPrivate->font.name = "font";
  rc->m_pPrivate->font.image = MakeFontImage();
  rc->m_pPrivate->font.state = TextureState::Loaded;
  rc->m_nWidth = opts.width;
  rc->m_nHeight = opts.height;
  SetDefaults(rc);
  return rc;
}

int MEAPI RRenderContextDestroy(RRender *rc) {
  if (!rc) return 0;
  DestroyMenus(rc);
  DestroyPerformanceBar(rc);
  FreeList(rc->m_pRG_First);
  FreeList(rc->m_pRG_First2D);
  for (RNativeLine *l = rc->m_pNL_First; l;) {
    RNativeLine *next = l->m_pNext;
    MeMemoryAPI.destroy(l);
    l = next;
  }
  if (!rc->m_pPrivate->videoTempDir.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(rc->m_pPrivate->videoTempDir, ec);
  }
  if (rc->m_pPrivate->controls.record) std::fclose(rc->m_pPrivate->controls.record);
  delete rc->m_pPrivate;
  MeMemoryAPI.destroy(rc);
  return 0;
}

void MEAPI RRenderQuit(RRender *rc) {
  ME_REQUIRE_ARG(rc, "RRenderQuit", "rc is NULL");
  rc->m_pPrivate->quit = true;
}
