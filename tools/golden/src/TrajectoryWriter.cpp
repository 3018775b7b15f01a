#include <karma/golden/TrajectoryWriter.h>

#include <karma/golden/Error.h>

#include "RealText.h"

#include <fstream>
#include <ostream>

namespace karma::golden {

namespace {

/* Header words (program, step, backend) are single tokens. */
bool IsWord(const std::string &s) {
  if (s.empty()) return false;
  for (unsigned char c : s)
    if (c <= ' ' || c == 0x7f) return false;
  return true;
}

bool IsOneLine(const std::string &s) { return s.find('\n') == std::string::npos && s.find('\r') == std::string::npos; }

void Put(std::ostream &out, const double *values, int count, Precision precision) {
  for (int i = 0; i < count; ++i) out << ' ' << detail::FormatReal(values[i], precision);
}

}  // namespace

TrajectoryWriter::TrajectoryWriter(const TrajectoryHeader &header, std::ostream *out)
    : header_(header), out_(out), path_("<stream>") {
  WriteHeader();
}

TrajectoryWriter::TrajectoryWriter(const TrajectoryHeader &header, const std::filesystem::path &path)
    : header_(header), path_(path.string()) {
  auto file = std::make_unique<std::ofstream>(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!*file) throw GoldenError("cannot create trajectory file " + path_);
  out_ = file.get();
  ownedStream_ = std::move(file);
  WriteHeader();
}

TrajectoryWriter::~TrajectoryWriter() = default;

void TrajectoryWriter::Fail(const std::string &message) {
  failed_ = true;
  throw GoldenError("trajectory " + path_ + ": " + message);
}

void TrajectoryWriter::Require(bool ok, const char *message) {
  if (!ok) Fail(message);
}

void TrajectoryWriter::CheckStream() {
  if (out_ && !*out_) Fail("write failed");
}

void TrajectoryWriter::WriteHeader() {
  Require(IsWord(header_.program), "program name must be one non-empty word");
  Require(IsWord(header_.step), "step name must be one non-empty word");
  Require(IsWord(header_.backend), "backend name must be one non-empty word");
  Require(IsOneLine(header_.sampling), "sampling description must fit on one line");
  Require(header_.bodyCount >= 0, "body count must not be negative");
  header_.timeStep = detail::RoundTo(header_.timeStep, header_.precision);
  if (!out_) return;
  std::ostream &o = *out_;
  o << "karma-trajectory 1\n";
  o << "program " << header_.program << '\n';
  o << "step " << header_.step << '\n';
  o << "backend " << header_.backend << '\n';
  o << "precision " << PrecisionName(header_.precision) << '\n';
  o << "bodies " << header_.bodyCount << '\n';
  o << "sampling " << header_.sampling << '\n';
  o << "timestep " << detail::FormatReal(header_.timeStep, header_.precision) << '\n';
  o << "# per frame: 'frame <index> time <t>', one 'body <i> pos x y z quat w x y z linvel x y z angvel x y z'\n"
       "# line per body, then 'hash': FNV-1a 64 over the state bytes of every frame so far.\n";
  CheckStream();
}

void TrajectoryWriter::BeginFrame(long index, double time) {
  Require(!failed_, "writer already failed");
  Require(!finished_, "BeginFrame after Finish");
  Require(!inFrame_, "BeginFrame while a frame is open (missing EndFrame)");
  if (index < 0 || index <= lastIndex_)
    Fail("frame " + std::to_string(index) + " does not follow frame " + std::to_string(lastIndex_) +
         " (indices must be >= 0 and strictly increasing)");
  inFrame_ = true;
  bodiesInFrame_ = 0;
  lastIndex_ = index;
  if (out_) *out_ << "frame " << index << " time " << detail::FormatReal(time, header_.precision) << '\n';
}

void TrajectoryWriter::AddBody(const MeReal position[3], const MeReal quaternion[4], const MeReal linearVelocity[3],
                               const MeReal angularVelocity[3]) {
  Require(header_.precision == kBuildPrecision, "AddBody(MeReal...) needs a header whose precision is the build's");
  BodyState body;
  for (int i = 0; i < 3; ++i) {
    body.position[i] = position[i];
    body.linearVelocity[i] = linearVelocity[i];
    body.angularVelocity[i] = angularVelocity[i];
  }
  for (int i = 0; i < 4; ++i) body.quaternion[i] = quaternion[i];
  AddBody(body);
}

void TrajectoryWriter::AddBody(const BodyState &input) {
  Require(!failed_, "writer already failed");
  Require(inFrame_, "AddBody outside a frame (missing BeginFrame)");
  if (bodiesInFrame_ >= header_.bodyCount)
    Fail("frame " + std::to_string(lastIndex_) + " gets more than the " + std::to_string(header_.bodyCount) +
         " bodies the header declares");
  BodyState body = input;
  for (Quantity q : kAllQuantities) {
    double *v = body.Values(q);
    for (int i = 0; i < QuantitySize(q); ++i) v[i] = detail::RoundTo(v[i], header_.precision);
  }
  hash_.AddBody(body, header_.precision);
  if (out_) {
    std::ostream &o = *out_;
    o << "body " << bodiesInFrame_;
    for (Quantity q : kAllQuantities) {
      o << ' ' << QuantityName(q);
      Put(o, body.Values(q), QuantitySize(q), header_.precision);
    }
    o << '\n';
  }
  ++bodiesInFrame_;
}

void TrajectoryWriter::EndFrame() {
  Require(!failed_, "writer already failed");
  Require(inFrame_, "EndFrame without BeginFrame");
  if (bodiesInFrame_ != header_.bodyCount)
    Fail("frame " + std::to_string(lastIndex_) + " has " + std::to_string(bodiesInFrame_) +
         " bodies, the header declares " + std::to_string(header_.bodyCount));
  inFrame_ = false;
  ++framesWritten_;
  if (out_) {
    *out_ << "hash " << FormatHash(hash_.Value()) << '\n';
    CheckStream();
  }
}

void TrajectoryWriter::Finish() {
  if (finished_) return;
  Require(!failed_, "writer already failed");
  Require(!inFrame_, "Finish while a frame is open (missing EndFrame)");
  finished_ = true;
  if (out_) {
    *out_ << "final-hash " << FormatHash(hash_.Value()) << '\n';
    out_->flush();
    CheckStream();
  }
  if (ownedStream_) {
    static_cast<std::ofstream *>(ownedStream_.get())->close();
    if (ownedStream_->fail()) Fail("closing the file failed");
  }
}

void WriteTrajectory(std::ostream &out, const Trajectory &trajectory) {
  TrajectoryWriter writer(trajectory.header, &out);
  for (const TrajectoryFrame &frame : trajectory.frames) {
    writer.BeginFrame(frame.index, frame.time);
    for (const BodyState &body : frame.bodies) writer.AddBody(body);
    writer.EndFrame();
  }
  writer.Finish();
}

void WriteTrajectoryFile(const std::filesystem::path &path, const Trajectory &trajectory) {
  TrajectoryWriter writer(trajectory.header, path);
  for (const TrajectoryFrame &frame : trajectory.frames) {
    writer.BeginFrame(frame.index, frame.time);
    for (const BodyState &body : frame.bodies) writer.AddBody(body);
    writer.EndFrame();
  }
  writer.Finish();
}

}  // namespace karma::golden
