/* viewer_internal.h: the private state behind an RRender (not installed).
 *
 * RRender (MeViewerTypes.h) holds what the guide lets programs touch; the
 * rest lives in RRenderPrivate: the parsed options, the texture table, the
 * backend and the loop's bookkeeping. */
#ifndef KARMA_MEVIEWER_INTERNAL_H
#define KARMA_MEVIEWER_INTERNAL_H

#include "MeViewer.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace karma::viewer {

enum class BackendKind { GL, Null, Bench, Profile, Window };

/* Everything the viewer reads from the command line. */
struct ViewerOptions {
  BackendKind backend = BackendKind::GL;
  bool backendGiven = false; /* a backend option was on the command line */
  long frames = -1;          /* < 0: no limit */
  std::string outDir;        /* empty: no images */
  int every = 1;             /* write frames whose index is a multiple of this */
  bool bmp = false;          /* BMP instead of PNG */
  int width = 640, height = 480;
  bool help = false;
  std::string keys;       /* -keys SCRIPT, then -keyfile FILE's text appended */
  std::string keyFile;    /* -keyfile FILE */
  std::string video;      /* -video FILE (.gif: GIF, anything else: H.264 MP4) */
  std::string record;     /* -record FILE: the window's live input as a key script */
  std::string screenshot; /* -screenshot FILE: the window as the display shows it, at exit */
  bool accuracy = false;  /* -accuracy: the accuracy overlay */
  std::string platform;   /* -platform NAME: a known backend; empty: not given */
};
/* True when a display is there to open windows on ($DISPLAY not empty). */
bool DisplayPresent();

/* The options text -help prints. */
const char *HelpText();
/* Reads the viewer's options, `options` first, then `overrides` (which
 * win). On a malformed value writes a one-line reason to `error` and
 * returns false. */
bool ParseViewerOptions(MeCommandLineOptions *options, MeCommandLineOptions *overrides, bool eat, ViewerOptions &out,
                        std::string &error);
/* Warns about arguments left in `options` that look like misspelt viewer
 * options, and notes other unknown ones. */
void ReportUnknownOptions(const MeCommandLineOptions *options);
/* -platform NAME (a known backend): makes it the process default of the
 * dynamics worlds created from now on (MdtPlatform.h), or the best
 * supported one, with a warning, when the CPU cannot run it. Nothing is
 * done, or warned, when the default already is what the name resolves to. */
void ApplyPlatformOption(const std::string &name);
/* The backends the program's dynamics worlds ran on, read from the
 * diagnostic sources ("avx2", "reference and avx2"); without any source
 * the process default, so marked. */
std::string PlatformReport();

/* An RGB(A) image in memory, rows from the top. */
struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> pixels;
};

/* Reads a Windows BMP that MeViewer accepts as a texture: uncompressed,
 * 24 bits per pixel, 128x128 or 256x256. On failure returns false with the
 * reason in `error`. The image comes out as RGB, top row first. */
bool LoadTextureBmp(const std::string &path, Image &out, std::string &error);
/* As LoadTextureBmp, from bytes in memory (the loader proper; testable). */
bool DecodeTextureBmp(const std::uint8_t *data, std::size_t size, Image &out, std::string &error);

enum class TextureState { Pending, Loaded, Failed };

struct Texture {
  std::string name; /* as the program gave it */
  TextureState state = TextureState::Pending;
  Image image;         /* RGB (files) or RGBA (the font) */
  unsigned glName = 0; /* the backend's texture object, 0 = not uploaded */
};

/* The font texture: 16 x 6 cells of kFontCellW x kFontCellH texels for
 * the printable ASCII characters 32..126, white with coverage in alpha. */
constexpr int kFontCellW = 16, kFontCellH = 28, kFontColumns = 16, kFontRows = 6;
constexpr int kFontTextureSize = 256;
constexpr int kFontTextureID = R_MAX_TEXTURES; /* outside the program's IDs */
Image MakeFontImage();
/* Horizontal advance of a character in font units (= 2D units). */
int FontAdvance(unsigned char c);

/* The directories searched for texture files, in order (ARCHITECTURE.md). */
std::vector<std::string> TextureSearchPath();
/* A data file (texture, object) by the search path: the first existing
 * DIR/file, or file itself when absolute; empty if none. */
std::string FindDataFile(const std::string &file);
/* Triangles read from an ASE file: 3 vertices per face, positions as in
 * the file, normals unit, texture v flipped to MeViewer's (0 = top). */
bool ParseAse(const std::string &text, std::vector<RObjectVertex> &out, std::string &error);
/* Loads every pending texture (called when RRun starts and each frame). */
void LoadPendingTextures(RRender *rc);

/* What draws frames. The null backend draws nothing. */
class Backend {
 public:
  virtual ~Backend() = default;
  virtual bool Draws() const = 0;
  /* Draws the context's lists into the offscreen buffer. */
  virtual void DrawFrame(RRender *rc) = 0;
  /* The last frame as RGB, top row first. */
  virtual bool ReadFrame(Image &out) = 0;
  /* A window: paced to real time, with live input and screenshots. */
  virtual bool Live() const { return false; }
  /* Hands the window's pending input to LiveKey / LiveMouse / LiveQuit. */
  virtual void PollInput(RRender *) {}
  /* The window's pixels as the display shows them (RGB, top row first). */
  virtual bool Screenshot(Image &, std::string &error) {
    error = "only a window has a screenshot";
    return false;
  }
};
std::unique_ptr<Backend> CreateNullBackend();
/* NULL with `error` set when OSMesa cannot make a context. */
std::unique_ptr<Backend> CreateGLBackend(int width, int height, std::string &error);
/* A window of the frame size showing the OSMesa frames; NULL with `error`
 * set when no window can be opened. */
std::unique_ptr<Backend> CreateWindowBackend(int width, int height, std::string &error);

/* Writes DIR/frame_NNNNN.png (or .bmp); false with `error` on failure. */
bool WriteFrameImage(const std::string &dir, long frame, bool bmp, const Image &image, std::string &error);
/* Writes `image` as a PNG file at `path`; false with `error` on failure. */
bool WritePng(const std::string &path, const Image &image, std::string &error);
/* "frame_00042.png" */
std::string FrameFileName(long frame, bool bmp);

/* -video: the path of an executable `name` on $PATH, or empty. */
std::string FindInPath(const std::string &name);
/* Runs ffmpeg on the frames written to `dir` to make `video`; reports the
 * outcome through MeInfo / MeWarning. Returns true on success. */
bool AssembleVideo(const std::string &dir, bool bmp, const std::string &video);

/* The progress line of a render to files (progress.cpp). */
class ProgressLine {
 public:
  /* total < 0: no frame limit. `what` says where the frames go. */
  ProgressLine(long total, std::string what);
  ~ProgressLine();
  ProgressLine(const ProgressLine &) = delete;
  ProgressLine &operator=(const ProgressLine &) = delete;
  /* `done` frames (1 or more) have been drawn and written. */
  void FrameDone(long done);

 private:
  using Clock = std::chrono::steady_clock;
  long total_;
  std::string what_;
  bool terminal_;
  Clock::time_point start_, last_;
  bool printed_ = false;
};

/* Per-phase timings of the loop, for -bench and -profile. */
struct FrameTimes {
  std::vector<double> input, tick, render, output, total; /* milliseconds */
};
void PrintBenchReport(const FrameTimes &t, std::FILE *f);
void PrintProfileReport(const FrameTimes &t, std::FILE *f);

/* Builds the matrices for a frame (camera.cpp). */
void PerspectiveMatrix(const RRender *rc, float out[16]);
void CameraMatrixFloat(const RRender *rc, float out[16]);

}  // namespace karma::viewer

namespace karma::viewer {

/* Keys: printable ASCII characters are themselves; named keys follow. */
enum Key : int {
  kKeyUp = 256,
  kKeyDown,
  kKeyLeft,
  kKeyRight,
  kKeyReturn,
  kKeyEscape,
  kKeyTab,
  kKeySpace,
  kKeyF1,
  kKeyF12 = kKeyF1 + 11
};
/* The key's name as scripts and help text write it ("Up", "Return", "q"). */
std::string KeyName(int key);
/* Parses a key name or single printable character; -1 if unknown. */
int ParseKeyName(const std::string &name);

/* One scripted input event (keyscript.cpp has the grammar). */
struct KeyEvent {
  enum Kind { Press, Release, Tap, Action, Mouse, Quit } kind = Press;
  long frame = 0;
  int key = 0;                   /* Press, Release, Tap */
  int action = 0;                /* Action */
  int x = 0, y = 0, buttons = 0; /* Mouse */
};
/* Parses a key script; on error returns false with a message naming the
 * event (by number and text) in `error`. Events come out sorted by frame,
 * keeping their written order within a frame. */
bool ParseKeyScript(const std::string &text, std::vector<KeyEvent> &out, std::string &error);
/* Help text for the script grammar (-help prints it). */
const char *KeyScriptHelp();

struct Controls {
  RButtonPressCallBack arrows[8] = {}; /* Up Up2 Down Down2 Left Left2 Right Right2 */
  RButtonPressCallBack action[R_MAX_ACTIONS] = {};
  void *actionData[R_MAX_ACTIONS] = {};
  int actionKey[R_MAX_ACTIONS] = {kKeySpace, kKeyTab, kKeyReturn, 'x', 'c', 'v'};
  RMouseCallBack mouse = nullptr;
  void *mouseData = nullptr;
  std::vector<int> held; /* keys down */
  std::vector<KeyEvent> script;
  std::size_t next = 0;        /* first script event not yet applied */
  std::FILE *record = nullptr; /* -record: live events written as a key script */
};
/* The input phase of a frame: applies the script's events for this frame. */
void ProcessInput(RRender *rc);
/* A key going down / up, as a user would press it. */
void PressKey(RRender *rc, int key);
void ReleaseKey(RRender *rc, int key);
/* Live input from a window, in the current frame's input phase: the same
 * effect as the key-script events "F:press KEY" / "F:release KEY",
 * "F:mouse X,Y,B" and "F:quit" at this frame F, which -record writes. */
void LiveKey(RRender *rc, int key, bool down);
void LiveMouse(RRender *rc, int x, int y, int buttons);
void LiveQuit(RRender *rc);
/* The open menu's reaction to a key; false if the menu does not use it. */
bool MenuHandleKey(RRender *rc, int key);
/* The open menu as 2D graphics (in no list), for one frame; the caller
 * destroys them. Empty when no menu is open. */
std::vector<RGraphic *> MenuOverlay(RRender *rc);
/* RParseText into a std::string (no length limit). */
std::string ParseText(const RRender *rc, const char *text);
/* The help panel as 2D graphics for one frame (empty when hidden). */
std::vector<RGraphic *> HelpOverlay(RRender *rc);
/* The performance bar as 2D graphics for one frame (empty without a bar). */
std::vector<RGraphic *> PerformanceBarOverlay(RRender *rc);
void DestroyPerformanceBar(RRender *rc);
/* The accuracy figures of the frames so far (RRenderSetAccuracySource). */
struct AccuracyState {
  RAccuracySource source = nullptr;
  void *data = nullptr;
  bool have = false; /* `last` holds a reading */
  RAccuracyFigures last{};
  std::vector<RAccuracyFigures> frames; /* one per frame read, for -profile */
};
/* Reads the source after a tick when -accuracy or -profile asks for it. */
void SampleAccuracy(RRender *rc);
/* The accuracy overlay as 2D graphics for one frame (empty without
 * -accuracy). */
std::vector<RGraphic *> AccuracyOverlay(RRender *rc);
/* -profile's accuracy table: the largest magnitude of each figure in each
 * quarter of the run, and its value at the end. */
void PrintAccuracyReport(const AccuracyState &a, std::FILE *f);
/* Frees every menu of the context (RRenderContextDestroy). */
void DestroyMenus(RRender *rc);

}  // namespace karma::viewer

struct RRenderPrivate {
  karma::viewer::ViewerOptions options;
  std::vector<karma::viewer::Texture> textures; /* index = texture ID */
  karma::viewer::Texture font;
  std::unique_ptr<karma::viewer::Backend> backend;
  bool quit = false;
  bool running = false;
  /* The light settings the renderer applies (copied when forced). */
  RDirectLight appliedDirect1{}, appliedDirect2{};
  RPointLight appliedPoint{};
  bool lightsApplied = false;
  karma::viewer::Controls controls;
  RMenu *defaultMenu = nullptr;
  RMenu *shownMenu = nullptr;
  std::vector<RMenu *> menus;    /* every menu made in this context */
  std::vector<std::string> help; /* parsed help lines */
  bool helpShown = false;
  bool paused = false; /* toggled with the help: no tick */
  RPerformanceBar *bar = nullptr;
  karma::viewer::AccuracyState accuracy;
  std::string videoTempDir; /* frames for -video without -out, removed after */
};

/* RGraphic creation shared by the primitives (graphic.cpp). */
RGraphic *RGraphicCreateSized(int numVertices, int numUsed);
/* Fills the common part of a primitive: colour (with a small specular
 * highlight), transform, list. Returns rg. */
RGraphic *RGraphicFinishPrimitive(RRender *rc, RGraphic *rg, const float color[4], MeMatrix4Ptr matrix, int is2D);
/* Sets vertex i. */
void RSetVertex(RObjectVertex *v, float x, float y, float z, float nx, float ny, float nz, float u, float w);

#endif
