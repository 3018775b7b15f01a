/* TrajectoryWriter.h: writing trajectory files.
 *
 * File format, version 1 (plain text, one record per line, fields separated by
 * single spaces, '\n' line ends; lines that are empty or start with '#' are
 * comments):
 *
 *   karma-trajectory 1
 *   program <name>                 no spaces
 *   step <name>                    "main" for programs without steps
 *   backend <name>                 platform backend, e.g. "reference"
 *   precision single|double        the precision of every number below
 *   bodies <N>
 *   sampling <free text>           which frames are sampled, for people
 *   timestep <real>
 *   then per sampled frame, frame indices strictly increasing:
 *   frame <index> time <real>
 *   body <i> pos x y z quat w x y z linvel x y z angvel x y z     N lines, i = 0..N-1
 *   hash 0x<16 hex>                running state hash after this frame
 *   and last:
 *   final-hash 0x<16 hex>          the hash of the run (= last frame's hash)
 *
 * Every <real> is printed as the shortest decimal that reads back to the same
 * value of the file's precision (std::to_chars; at most 9 significant digits
 * for single, 17 for double), so reading a file gives back the exact bits and
 * the hash recomputed from the text equals the recorded one. Output does not
 * depend on the C locale. The hash is defined in StateHash.h. */
#ifndef KARMA_GOLDEN_TRAJECTORYWRITER_H
#define KARMA_GOLDEN_TRAJECTORYWRITER_H

#include <karma/golden/StateHash.h>
#include <karma/golden/Trajectory.h>

#include <filesystem>
#include <iosfwd>
#include <memory>

namespace karma::golden {

/* Streams a trajectory frame by frame, as a simulation runs:
 *
 *   TrajectoryWriter w(header, "out/trajectory.txt");   // or nullptr: hash only
 *   for each sampled frame:
 *     w.BeginFrame(frame, time);
 *     for each body: w.AddBody(pos, quat, linvel, angvel);
 *     w.EndFrame();
 *   w.Finish();                                          // writes final-hash
 *   printf("state hash: %s\n", FormatHash(w.Hash()).c_str());
 *
 * Calls out of order (a frame with the wrong number of bodies, indices not
 * increasing, anything after Finish) and write failures throw GoldenError;
 * after an error the writer refuses further calls. */
class MEPUBLIC TrajectoryWriter {
 public:
  /* Writes to `out` (not owned; may be null to only keep the hash). */
  TrajectoryWriter(const TrajectoryHeader &header, std::ostream *out);
  /* Creates or truncates the file at `path`. Throws GoldenError if it cannot. */
  TrajectoryWriter(const TrajectoryHeader &header, const std::filesystem::path &path);
  ~TrajectoryWriter();
  TrajectoryWriter(const TrajectoryWriter &) = delete;
  TrajectoryWriter &operator=(const TrajectoryWriter &) = delete;

  void BeginFrame(long index, double time);
  /* The build's MeReal arrays; requires header.precision == kBuildPrecision. */
  void AddBody(const MeReal position[3], const MeReal quaternion[4], const MeReal linearVelocity[3],
               const MeReal angularVelocity[3]);
  /* Any precision: values are rounded to the header's precision first. */
  void AddBody(const BodyState &body);
  void EndFrame();
  /* Writes the final-hash line and flushes. Idempotent. A writer destroyed
   * without Finish leaves a file the reader rejects as truncated. */
  void Finish();

  /* Running hash over the frames ended so far. */
  std::uint64_t Hash() const noexcept { return hash_.Value(); }
  const TrajectoryHeader &Header() const noexcept { return header_; }
  long FramesWritten() const noexcept { return framesWritten_; }

 private:
  void Fail(const std::string &message);
  void Require(bool ok, const char *message);
  void WriteHeader();
  void CheckStream();

  TrajectoryHeader header_;
  std::unique_ptr<std::ostream> ownedStream_;
  std::ostream *out_ = nullptr;
  std::string path_; /* for messages */
  StateHash hash_;
  long lastIndex_ = -1;
  long framesWritten_ = 0;
  int bodiesInFrame_ = 0;
  bool inFrame_ = false;
  bool finished_ = false;
  bool failed_ = false;
};

/* Writes a whole model. Values are rounded to the header's precision and the
 * hash lines are recomputed (the model's recorded hashes are ignored). */
MEPUBLIC void WriteTrajectory(std::ostream &out, const Trajectory &trajectory);
MEPUBLIC void WriteTrajectoryFile(const std::filesystem::path &path, const Trajectory &trajectory);

}  // namespace karma::golden

#endif
