/* progress.cpp: the progress line of a render to files.
 *
 * While frames are written (-out, or -video's frames), a run prints
 *   MeViewer: frame n of N, E s elapsed, about R s to go
 * with R = E (N - n) / n, the rate so far carried to the end. On a terminal
 * the line is rewritten in place at most 4 times a second; in a log (stderr
 * not a terminal) a line is printed every 10 s, so short renders print none.
 * Without -frames the total is unknown and the line gives n and E only. */
#include "viewer_internal.h"

#include <unistd.h>

namespace karma::viewer {

ProgressLine::ProgressLine(long total, std::string what)
    : total_(total),
      what_(std::move(what)),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      last_(start_) {}

void ProgressLine::FrameDone(long done) {
  const Clock::time_point now = Clock::now();
  const double sinceLast = std::chrono::duration<double>(now - last_).count();
  const bool last = total_ > 0 && done >= total_;
  if (sinceLast < (terminal_ ? 0.25 : 10.0) && !(last && printed_)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, terminal_ ? "\rMeViewer: frame %ld" : "MeViewer: frame %ld", done);
  if (total_ > 0)
    std::fprintf(stderr, " of %ld, %.1f s elapsed, about %.1f s to go", total_, elapsed,
                 elapsed * double(total_ - done) / double(done));
  else
    std::fprintf(stderr, ", %.1f s elapsed", elapsed);
  std::fprintf(stderr, " (%s)%s", what_.c_str(), terminal_ ? "   " : "\n");
  std::fflush(stderr);
  printed_ = true;
}

ProgressLine::~ProgressLine() {
  if (printed_ && terminal_) std::fputc('\n', stderr);
}

}  // namespace karma::viewer
