/* window_backend.cpp: the -window backend, a window on the display through
 * SDL2 (Debian libsdl2-dev).
 *
 * Frames are drawn by the offscreen OSMesa backend exactly as without a
 * window, then copied into the window's surface (SDL_UpdateWindowSurface):
 * no second OpenGL implementation enters the process, and the window shows,
 * pixel for pixel, the frame that -out writes. Input: SDL's key and mouse
 * events become LiveKey / LiveMouse / LiveQuit (controls.cpp), which run the
 * same control callbacks as a key script's events and, with -record FILE,
 * write them down as a key script. The screenshot (-screenshot FILE) reads
 * the window's pixels back from the X server (XGetImage, as xwd does). */
#include "viewer_internal.h"

#include <SDL.h>
#include <SDL_syswm.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace karma::viewer {
namespace {

/* MeViewer's key for an SDL key, or -1 for keys it does not know. */
int KeyFromSdl(SDL_Keycode sym) {
  switch (sym) {
    case SDLK_UP:
      return kKeyUp;
    case SDLK_DOWN:
      return kKeyDown;
    case SDLK_LEFT:
      return kKeyLeft;
    case SDLK_RIGHT:
      return kKeyRight;
    case SDLK_RETURN:
    case SDLK_KP_ENTER:
      return kKeyReturn;
    case SDLK_ESCAPE:
      return kKeyEscape;
    case SDLK_TAB:
      return kKeyTab;
    case SDLK_SPACE:
      return kKeySpace;
    default:
      break;
  }
  if (sym >= SDLK_F1 && sym <= SDLK_F12) return kKeyF1 + int(sym - SDLK_F1);
  if (sym > 32 && sym < 127) return int(sym);
  return -1;
}

/* SDL button number -> MeViewer's button bit (0 left, 1 middle, 2 right). */
int ButtonBit(Uint8 button) {
  switch (button) {
    case SDL_BUTTON_LEFT:
      return 1;
    case SDL_BUTTON_MIDDLE:
      return 2;
    case SDL_BUTTON_RIGHT:
      return 4;
    default:
      return 0;
  }
}

/* Bit position of the lowest set bit of a colour mask (0 for 0). */
int MaskShift(unsigned long mask) {
  int shift = 0;
  while (mask && !(mask & 1ul)) mask >>= 1, ++shift;
  return shift;
}

class WindowBackend final : public Backend {
 public:
  WindowBackend(std::unique_ptr<Backend> offscreen, SDL_Window *window, int width, int height)
      : offscreen_(std::move(offscreen)), window_(window), width_(width), height_(height) {}
  ~WindowBackend() override {
    SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
  }
  WindowBackend(const WindowBackend &) = delete;
  WindowBackend &operator=(const WindowBackend &) = delete;

  bool Draws() const override { return true; }
  bool Live() const override { return true; }
  void DrawFrame(RRender *rc) override {
    offscreen_->DrawFrame(rc);
    UpdateTitle(rc);
    Present();
  }
  bool ReadFrame(Image &out) override { return offscreen_->ReadFrame(out); }
  void PollInput(RRender *rc) override;
  bool Screenshot(Image &out, std::string &error) override;

 private:
  void UpdateTitle(const RRender *rc) {
    const std::string title = rc->m_AppName ? rc->m_AppName : "Karma";
    if (title != title_) SDL_SetWindowTitle(window_, title.c_str()), title_ = title;
  }
  /* Copies the offscreen frame (RGB, top row first) into the window. */
  void Present() {
    if (!offscreen_->ReadFrame(frame_)) return;
    SDL_Surface *surface = SDL_GetWindowSurface(window_);
    if (!surface || surface->w != width_ || surface->h != height_) return;
    if (SDL_MUSTLOCK(surface) && SDL_LockSurface(surface) != 0) return;
    SDL_ConvertPixels(width_, height_, SDL_PIXELFORMAT_RGB24, frame_.pixels.data(), width_ * 3, surface->format->format,
                      surface->pixels, surface->pitch);
    if (SDL_MUSTLOCK(surface)) SDL_UnlockSurface(surface);
    SDL_UpdateWindowSurface(window_);
  }

  std::unique_ptr<Backend> offscreen_;
  SDL_Window *window_;
  int width_, height_;
  int buttons_ = 0; /* MeViewer's button bits held now */
  std::string title_;
  Image frame_;
};

void WindowBackend::PollInput(RRender *rc) {
  SDL_Event e;
  while (SDL_PollEvent(&e)) {
    switch (e.type) {
      case SDL_QUIT:
        LiveQuit(rc);
        break;
      case SDL_KEYDOWN:
      case SDL_KEYUP: {
        if (e.key.repeat) break; /* held keys press once (controls.cpp) */
        const int key = KeyFromSdl(e.key.keysym.sym);
        if (key >= 0) LiveKey(rc, key, e.type == SDL_KEYDOWN);
        break;
      }
      case SDL_MOUSEMOTION:
        LiveMouse(rc, e.motion.x, e.motion.y, buttons_);
        break;
      case SDL_MOUSEBUTTONDOWN:
      case SDL_MOUSEBUTTONUP:
        if (e.type == SDL_MOUSEBUTTONDOWN)
          buttons_ |= ButtonBit(e.button.button);
        else
          buttons_ &= ~ButtonBit(e.button.button);
        LiveMouse(rc, e.button.x, e.button.y, buttons_);
        break;
      default:
        break;
    }
  }
}

bool WindowBackend::Screenshot(Image &out, std::string &error) {
  SDL_SysWMinfo info;
  SDL_VERSION(&info.version);
  if (!SDL_GetWindowWMInfo(window_, &info) || info.subsystem != SDL_SYSWM_X11) {
    error = "the window is not an X11 window; no screenshot";
    return false;
  }
  Display *display = info.info.x11.display;
  XSync(display, False);
  XImage *image =
      XGetImage(display, info.info.x11.window, 0, 0, unsigned(width_), unsigned(height_), AllPlanes, ZPixmap);
  if (!image) {
    error = "XGetImage could not read the window";
    return false;
  }
  const int rs = MaskShift(image->red_mask), gs = MaskShift(image->green_mask), bs = MaskShift(image->blue_mask);
  out.width = width_, out.height = height_, out.channels = 3;
  out.pixels.resize(std::size_t(width_) * std::size_t(height_) * 3);
  std::uint8_t *dst = out.pixels.data();
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x, dst += 3) {
      const unsigned long p = XGetPixel(image, x, y);
      dst[0] = std::uint8_t((p & image->red_mask) >> rs);
      dst[1] = std::uint8_t((p & image->green_mask) >> gs);
      dst[2] = std::uint8_t((p & image->blue_mask) >> bs);
    }
  XDestroyImage(image);
  return true;
}

}  // namespace

std::unique_ptr<Backend> CreateWindowBackend(int width, int height, std::string &error) {
  std::unique_ptr<Backend> offscreen = CreateGLBackend(width, height, error);
  if (!offscreen) return nullptr;
  /* The window surface through X11's own image transfer, not an OpenGL
   * renderer: GLX and OSMesa in one process crash in Mesa. */
  SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
  /* X11 (also under XWayland), where -screenshot can read the window back;
   * $SDL_VIDEODRIVER still chooses another. */
  SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
    error = std::string("SDL cannot use the display: ") + SDL_GetError();
    return nullptr;
  }
  SDL_Window *window =
      SDL_CreateWindow("Karma", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, width, height, SDL_WINDOW_SHOWN);
  if (!window) {
    error = std::string("SDL cannot open a window: ") + SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    return nullptr;
  }
  return std::make_unique<WindowBackend>(std::move(offscreen), window, width, height);
}

}  // namespace karma::viewer
