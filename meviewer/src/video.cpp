/* video.cpp: -video FILE, frames assembled by ffmpeg after the run.
 *
 * ffmpeg is optional (Debian package ffmpeg). It reads the frames RRun
 * wrote (DIR/frame_*.png or .bmp, in name order, so -every gaps are fine)
 * at 30 frames per second:
 *   FILE.gif  palette made from the frames, then applied (split/palettegen/paletteuse)
 *   other     H.264, yuv420p, sides padded to even numbers (players need both)
 * Without ffmpeg on $PATH the context says so once at creation and the run
 * goes on without a video. */
#include "viewer_internal.h"

#include <cstdlib>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace karma::viewer {

std::string FindInPath(const std::string &name) {
  const char *path = std::getenv("PATH");
  if (!path) return {};
  std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t colon = dirs.find(':', start);
    const std::string dir = dirs.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return {};
}

bool AssembleVideo(const std::string &dir, bool bmp, const std::string &video) {
  const std::string ffmpeg = FindInPath("ffmpeg");
  if (ffmpeg.empty()) {
    MeWarning(0, "MeViewer: -video %s: ffmpeg is not installed (Debian package ffmpeg); no video made", video.c_str());
    return false;
  }
  const bool gif = video.size() >= 4 && video.compare(video.size() - 4, 4, ".gif") == 0;
  const std::string pattern = dir + "/frame_*." + (bmp ? "bmp" : "png");
  std::vector<std::string> args = {ffmpeg,          "-y",   "-loglevel", "error", "-framerate", "30",
                                   "-pattern_type", "glob", "-i",        pattern};
  if (gif) {
    args.insert(args.end(), {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse"});
  } else {
    args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"});
  }
  args.push_back(video);
  std::vector<char *> argv;
  for (std::string &a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, ffmpeg.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
    MeWarning(0, "MeViewer: -video %s: cannot start %s", video.c_str(), ffmpeg.c_str());
    return false;
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    MeWarning(0, "MeViewer: -video %s: ffmpeg failed (status %d); the frames are in %s", video.c_str(),
              WIFEXITED(status) ? WEXITSTATUS(status) : -1, dir.c_str());
    return false;
  }
  MeInfo(0, "MeViewer: video written to %s", video.c_str());
  return true;
}

}  // namespace karma::viewer
