/* texture.cpp: texture IDs and finding texture files.
 *
 * A name gets an ID (0..R_MAX_TEXTURES-1) the first time it is seen; the
 * same name keeps it. The file is NAME.bmp (NAME as given when it already
 * ends in .bmp), loaded when RRun starts, or at the next frame for names
 * added later. It is looked for, in order, in
 *   1. the working directory,
 *   2. $KARMA_DATA_DIR, when set,
 *   3. the program's directory, its data/ folder and its ../share/karma/,
 *   4. the build tree's share/karma/ (where the build writes the textures
 *      the project makes, e.g. checkerboard.bmp),
 *   5. the installed share/karma/.
 * An absolute NAME is used as it is. A texture that cannot be found or
 * read draws untextured, after one message naming the file and why. */
#include "viewer_internal.h"

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#ifndef KARMA_BUILD_DATA_DIR
#  define KARMA_BUILD_DATA_DIR ""
#endif
#ifndef KARMA_INSTALL_DATA_DIR
#  define KARMA_INSTALL_DATA_DIR ""
#endif

namespace fs = std::filesystem;

namespace karma::viewer {
namespace {

std::string ExecutableDir() {
  char buffer[4096];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n <= 0) return {};
  buffer[n] = 0;
  return fs::path(buffer).parent_path().string();
}

std::string FileName(const std::string &name) {
  const std::string ext = ".bmp";
  if (name.size() >= ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0) return name;
  return name + ext;
}

}  // namespace

std::vector<std::string> TextureSearchPath() {
  std::vector<std::string> dirs{"."};
  if (const char *env = std::getenv("KARMA_DATA_DIR"); env && *env) dirs.emplace_back(env);
  const std::string exe = ExecutableDir();
  if (!exe.empty()) {
    dirs.push_back(exe);
    dirs.push_back(exe + "/data");
    dirs.push_back(exe + "/../share/karma");
  }
  if (*KARMA_BUILD_DATA_DIR) dirs.emplace_back(KARMA_BUILD_DATA_DIR);
  if (*KARMA_INSTALL_DATA_DIR) dirs.emplace_back(KARMA_INSTALL_DATA_DIR);
  return dirs;
}

std::string FindDataFile(const std::string &file) {
  std::error_code ec;
  if (fs::path(file).is_absolute()) return fs::is_regular_file(file, ec) ? file : std::string();
  for (const std::string &dir : TextureSearchPath())
    if (fs::is_regular_file(fs::path(dir) / file, ec)) return (fs::path(dir) / file).string();
  return {};
}

void LoadPendingTextures(RRender *rc) {
  for (Texture &t : rc->m_pPrivate->textures) {
    if (t.state != TextureState::Pending) continue;
    const std::string file = FileName(t.name);
    const std::string found = FindDataFile(file);
    if (found.empty()) {
      std::string where;
      for (const std::string &dir : TextureSearchPath()) where += (where.empty() ? "" : ", ") + dir;
      MeWarning(0, "MeViewer: texture '%s': no %s in %s; drawing untextured", t.name.c_str(), file.c_str(),
                where.c_str());
      t.state = TextureState::Failed;
      continue;
    }
    std::string error;
    if (LoadTextureBmp(found, t.image, error)) {
      t.state = TextureState::Loaded;
    } else {
      MeWarning(0, "MeViewer: texture '%s': %s; drawing untextured", t.name.c_str(), error.c_str());
      t.state = TextureState::Failed;
    }
  }
}

}  // namespace karma::viewer

using namespace karma::viewer;

int MEAPI RRenderTextureCreate(RRender *rc, char *filename) {
  ME_REQUIRE_ARG_RET(rc && filename, -1, "RRenderTextureCreate", "rc or filename is NULL");
  ME_REQUIRE_ARG_RET(*filename, -1, "RRenderTextureCreate", "the texture name is empty");
  std::vector<Texture> &textures = rc->m_pPrivate->textures;
  for (std::size_t i = 0; i < textures.size(); ++i)
    if (textures[i].name == filename) return int(i);
  if (textures.size() >= R_MAX_TEXTURES) {
    MeWarning(0, "RRenderTextureCreate: all %d texture IDs are taken; '%s' gets none and draws untextured",
              R_MAX_TEXTURES, filename);
    return -1;
  }
  Texture t;
  t.name = filename;
  textures.push_back(std::move(t));
  return int(textures.size() - 1);
}

int MEAPI RGraphicSetTexture(RRender *rc, RGraphic *rg, char *filename) {
  ME_REQUIRE_ARG_RET(rc && rg, -1, "RGraphicSetTexture", "rc or rg is NULL");
  const int id = RRenderTextureCreate(rc, filename);
  rg->m_pObject->m_nTextureID = id;
  return id;
}
