/* gl_backend.cpp: the -gl backend, OpenGL rendered offscreen by OSMesa into
 * an RGBA buffer of the frame size (24-bit depth buffer), and the -null
 * backend, which draws nothing. Each render context owns its OSMesa
 * context and makes it current before drawing, so several contexts can
 * coexist. GL texture objects die with the OSMesa context. */
#include "gl_draw.h"

#include <GL/osmesa.h>

namespace karma::viewer {
namespace {

class NullBackend final : public Backend {
 public:
  bool Draws() const override { return false; }
  void DrawFrame(RRender *) override {}
  bool ReadFrame(Image &) override { return false; }
};

class GLBackend final : public Backend {
 public:
  GLBackend(OSMesaContext context, int width, int height)
      : context_(context), width_(width), height_(height), buffer_(std::size_t(width) * std::size_t(height) * 4) {}
  ~GLBackend() override { OSMesaDestroyContext(context_); }
  GLBackend(const GLBackend &) = delete;
  GLBackend &operator=(const GLBackend &) = delete;

  bool MakeCurrent() { return OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_); }
  bool Draws() const override { return true; }
  void DrawFrame(RRender *rc) override {
    if (!MakeCurrent()) {
      MeWarning(0, "MeViewer: OSMesaMakeCurrent failed; the frame is not drawn");
      return;
    }
    DrawSceneGL(rc);
    drawn_ = true;
  }
  /* The buffer holds rows bottom first; frames go out top first, RGB. */
  bool ReadFrame(Image &out) override {
    if (!drawn_) return false;
    out.width = width_, out.height = height_, out.channels = 3;
    out.pixels.resize(std::size_t(width_) * std::size_t(height_) * 3);
    for (int y = 0; y < height_; ++y) {
      const std::uint8_t *src = buffer_.data() + std::size_t(height_ - 1 - y) * std::size_t(width_) * 4;
      std::uint8_t *dst = out.pixels.data() + std::size_t(y) * std::size_t(width_) * 3;
      for (int x = 0; x < width_; ++x)
        dst[3 * x] = src[4 * x], dst[3 * x + 1] = src[4 * x + 1], dst[3 * x + 2] = src[4 * x + 2];
    }
    return true;
  }

 private:
  OSMesaContext context_;
  int width_, height_;
  std::vector<std::uint8_t> buffer_;
  bool drawn_ = false;
};

}  // namespace

std::unique_ptr<Backend> CreateNullBackend() { return std::make_unique<NullBackend>(); }

std::unique_ptr<Backend> CreateGLBackend(int width, int height, std::string &error) {
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context) {
    error = "OSMesa could not create an offscreen OpenGL context";
    return nullptr;
  }
  auto backend = std::make_unique<GLBackend>(context, width, height);
  if (!backend->MakeCurrent()) {
    error = "OSMesa could not make a " + std::to_string(width) + "x" + std::to_string(height) + " buffer current";
    return nullptr;
  }
  return backend;
}

}  // namespace karma::viewer

/* Mesa's OSMesa keeps the framebuffer records OSMesaMakeCurrent allocates
 * in a private list that OSMesaDestroyContext never frees (Mesa 22), so
 * LeakSanitizer reports them at exit in every program that draws. Builds
 * with AddressSanitizer tell LeakSanitizer to ignore leaks from inside
 * libOSMesa only; leaks of our own allocations are still reported. The
 * window's libraries (SDL2, X11 and what SDL loads) keep caches of their own
 * until exit and are ignored the same way. The hook is weak, so a program
 * that defines its own wins. */
#if defined(__SANITIZE_ADDRESS__)
extern "C" __attribute__((weak, visibility("default"))) const char *__lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libSDL2\nleak:libX11\nleak:libdbus\n";
}
#endif
