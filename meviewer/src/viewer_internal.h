/* viewer_internal.h: the private state behind an RRender (not installed).
 *
 * RRender (MeViewerTypes.h) holds what the guide lets programs touch; the
 * rest lives in RRenderPrivate: the parsed options, the texture table, the
 * backend and the loop's bookkeeping. */
#ifndef KARMA_MEVIEWER_INTERNAL_H
#define KARMA_MEVIEWER_INTERNAL_H

#include "MeViewer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace karma::viewer {

enum class BackendKind { GL, Null, Bench, Profile };

/* Everything the viewer reads from the command line. */
struct ViewerOptions {
  BackendKind backend = BackendKind::GL;
  long frames = -1;     /* < 0: no limit */
  std::string outDir;   /* empty: no images */
  int every = 1;        /* write frames whose index is a multiple of this */
  bool bmp = false;     /* BMP instead of PNG */
  int width = 640, height = 480;
  bool help = false;
};

/* The options text -help prints. */
const char *HelpText();
/* Reads the viewer's options, `options` first, then `overrides` (which
 * win). On a malformed value writes a one-line reason to `error` and
 * returns false. */
bool ParseViewerOptions(MeCommandLineOptions *options, MeCommandLineOptions *overrides, bool eat,
                        ViewerOptions &out, std::string &error);
/* Warns about arguments left in `options` that look like misspelt viewer
 * options, and notes other unknown ones. */
void ReportUnknownOptions(const MeCommandLineOptions *options);

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
  std::string name;       /* as the program gave it */
  TextureState state = TextureState::Pending;
  Image image;            /* RGB (files) or RGBA (the font) */
  unsigned glName = 0;    /* the backend's texture object, 0 = not uploaded */
};

/* The font texture: 16 x 6 cells of R_FONT_CELL_W x R_FONT_CELL_H texels for
 * the printable ASCII characters 32..126, white with coverage in alpha. */
constexpr int kFontCellW = 16, kFontCellH = 28, kFontColumns = 16, kFontRows = 6;
constexpr int kFontTextureSize = 256;
constexpr int kFontTextureID = R_MAX_TEXTURES; /* outside the program's IDs */
Image MakeFontImage();
/* Horizontal advance of a character in font units (= 2D units). */
int FontAdvance(unsigned char c);

/* The directories searched for texture files, in order (ARCHITECTURE.md). */
std::vector<std::string> TextureSearchPath();
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
};
std::unique_ptr<Backend> CreateNullBackend();
/* NULL with `error` set when OSMesa cannot make a context. */
std::unique_ptr<Backend> CreateGLBackend(int width, int height, std::string &error);

/* Writes DIR/frame_NNNNN.png (or .bmp); false with `error` on failure. */
bool WriteFrameImage(const std::string &dir, long frame, bool bmp, const Image &image, std::string &error);
/* "frame_00042.png" */
std::string FrameFileName(long frame, bool bmp);

/* Per-phase timings of the loop, for -bench and -profile. */
struct FrameTimes {
  std::vector<double> input, tick, render, output, total; /* milliseconds */
};
void PrintBenchReport(const FrameTimes &t, std::FILE *f);
void PrintProfileReport(const FrameTimes &t, std::FILE *f);

/* Builds the matrices for a frame (camera.cpp). */
void PerspectiveMatrix(const RRender *rc, float out[16]);
void CameraMatrixFloat(const RRender *rc, float out[16]);

} // namespace karma::viewer

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
};

/* RGraphic creation shared by the primitives (graphic.cpp). */
RGraphic *RGraphicCreateSized(int numVertices, int numUsed);
/* Fills the common part of a primitive: colour (with a small specular
 * highlight), transform, list. Returns rg. */
RGraphic *RGraphicFinishPrimitive(RRender *rc, RGraphic *rg, const float color[4], MeMatrix4Ptr matrix, int is2D);
/* Sets vertex i. */
void RSetVertex(RObjectVertex *v, float x, float y, float z, float nx, float ny, float nz, float u, float w);

#endif
