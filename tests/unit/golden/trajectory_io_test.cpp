/* Trajectory files: writer -> reader round trip, the state hash, malformed input. */
#include "GoldenTestSupport.h"

#include <karma/golden/Error.h>
#include <karma/golden/StateHash.h>
#include <karma/golden/TrajectoryReader.h>
#include <karma/golden/TrajectoryWriter.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace kg = karma::golden;
namespace ts = karma::golden::test_support;

namespace {

/* Bit pattern of a value in the build precision, for bit-identity checks. */
std::uint64_t Bits(double v) {
  if (kg::kBuildPrecision == kg::Precision::Single) {
    const float f = static_cast<float>(v);
    std::uint32_t b = 0;
    std::memcpy(&b, &f, sizeof b);
    return b;
  }
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

/* Streams the synthetic trajectory through TrajectoryWriter using the MeReal API. */
std::string WriteSynthetic(std::uint64_t *writerHash, std::vector<std::uint64_t> *writerFrameHashes) {
  const kg::Trajectory model = ts::SyntheticTrajectory();
  std::ostringstream out;
  kg::TrajectoryWriter w(model.header, &out);
  for (const kg::TrajectoryFrame &f : model.frames) {
    w.BeginFrame(f.index, f.time);
    for (const kg::BodyState &b : f.bodies) {
      MeReal pos[3], quat[4], lin[3], ang[3];
      for (int i = 0; i < 3; ++i) {
        pos[i] = static_cast<MeReal>(b.position[i]);
        lin[i] = static_cast<MeReal>(b.linearVelocity[i]);
        ang[i] = static_cast<MeReal>(b.angularVelocity[i]);
      }
      for (int i = 0; i < 4; ++i) quat[i] = static_cast<MeReal>(b.quaternion[i]);
      w.AddBody(pos, quat, lin, ang);
    }
    w.EndFrame();
    if (writerFrameHashes) writerFrameHashes->push_back(w.Hash());
  }
  w.Finish();
  EXPECT_EQ(w.FramesWritten(), ts::kSyntheticFrames);
  if (writerHash) *writerHash = w.Hash();
  return out.str();
}

std::vector<std::string> Lines(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string Join(const std::vector<std::string> &lines) {
  std::string s;
  for (const std::string &l : lines) s += l + "\n";
  return s;
}

}  // namespace

TEST(TrajectoryIo, RoundTripIsBitIdenticalAndHashesAgree) {
  std::uint64_t writerHash = 0;
  std::vector<std::uint64_t> writerFrameHashes;
  const std::string text = WriteSynthetic(&writerHash, &writerFrameHashes);
  std::istringstream in(text);
  const kg::Trajectory read = kg::ReadTrajectory(in, "roundtrip");
  const kg::Trajectory model = ts::SyntheticTrajectory();

  EXPECT_EQ(read.header, model.header);
  ASSERT_EQ(read.frames.size(), model.frames.size());
  for (std::size_t f = 0; f < model.frames.size(); ++f) {
    EXPECT_EQ(read.frames[f].index, model.frames[f].index);
    EXPECT_EQ(Bits(read.frames[f].time), Bits(model.frames[f].time)) << "frame " << f;
    ASSERT_EQ(read.frames[f].bodies.size(), static_cast<std::size_t>(ts::kSyntheticBodies));
    for (int b = 0; b < ts::kSyntheticBodies; ++b) {
      for (kg::Quantity q : kg::kAllQuantities) {
        for (int i = 0; i < kg::QuantitySize(q); ++i) {
          EXPECT_EQ(Bits(read.frames[f].bodies[b].Values(q)[i]), Bits(model.frames[f].bodies[b].Values(q)[i]))
              << "frame " << f << " body " << b << " " << kg::QuantityName(q) << "[" << i << "]";
        }
      }
      EXPECT_EQ(read.frames[f].bodies[b], model.frames[f].bodies[b]);
    }
  }

  std::vector<std::uint64_t> perFrame;
  const std::uint64_t recomputed = kg::HashTrajectory(read, &perFrame);
  ASSERT_EQ(perFrame.size(), read.frames.size());
  for (std::size_t f = 0; f < perFrame.size(); ++f) {
    EXPECT_EQ(perFrame[f], read.frames[f].hash) << "frame " << f;
    EXPECT_EQ(perFrame[f], writerFrameHashes[f]) << "frame " << f;
  }
  EXPECT_EQ(recomputed, read.finalHash);
  EXPECT_EQ(recomputed, writerHash);
  EXPECT_EQ(recomputed, perFrame.back());
  EXPECT_NE(recomputed, kg::StateHash::kOffsetBasis);
  EXPECT_NE(text.find("final-hash " + kg::FormatHash(writerHash) + "\n"), std::string::npos);
}

TEST(TrajectoryIo, FileRoundTripAndHashOnlyWriter) {
  ts::TempDir dir("io_file");
  const kg::Trajectory model = ts::SyntheticTrajectory();
  const auto path = dir.path() / "trajectory.txt";
  kg::WriteTrajectoryFile(path, model);
  const kg::Trajectory read = kg::ReadTrajectoryFile(path);
  ASSERT_EQ(read.frames.size(), model.frames.size());
  for (std::size_t f = 0; f < model.frames.size(); ++f) EXPECT_EQ(read.frames[f].bodies, model.frames[f].bodies);
  EXPECT_EQ(kg::HashTrajectory(read), read.finalHash);

  /* A writer without a stream keeps the same hash. */
  kg::TrajectoryWriter hashOnly(model.header, static_cast<std::ostream *>(nullptr));
  for (const kg::TrajectoryFrame &f : model.frames) {
    hashOnly.BeginFrame(f.index, f.time);
    for (const kg::BodyState &b : f.bodies) hashOnly.AddBody(b);
    hashOnly.EndFrame();
  }
  hashOnly.Finish();
  EXPECT_EQ(hashOnly.Hash(), read.finalHash);
}

TEST(StateHash, MatchesTheDocumentedFnv1aDefinition) {
  kg::StateHash h;
  EXPECT_EQ(h.Value(), 0xcbf29ce484222325ull);
  h.AddValue(1.0, kg::Precision::Single); /* float 1.0 = 0x3f800000, fed LSB first: 00 00 80 3f */
  std::uint64_t expected = 0xcbf29ce484222325ull;
  for (std::uint8_t byte : {0x00, 0x00, 0x80, 0x3f}) {
    expected ^= byte;
    expected *= 0x100000001b3ull;
  }
  EXPECT_EQ(h.Value(), expected);

  kg::StateHash plusZero, minusZero;
  plusZero.AddValue(0.0, kg::Precision::Double);
  minusZero.AddValue(-0.0, kg::Precision::Double);
  EXPECT_NE(plusZero.Value(), minusZero.Value());

  EXPECT_EQ(kg::FormatHash(0x0123456789abcdefull), "0x0123456789abcdef");
  EXPECT_EQ(kg::ParseHash("0x0123456789abcdef"), std::optional<std::uint64_t>(0x0123456789abcdefull));
  EXPECT_FALSE(kg::ParseHash("0x0123").has_value());
  EXPECT_FALSE(kg::ParseHash("0x0123456789abcdeg").has_value());
}

TEST(StateHash, IdenticalRunsHashIdenticallyAndOneBitChangesIt) {
  const kg::Trajectory a = ts::SyntheticTrajectory();
  const kg::Trajectory b = ts::SyntheticTrajectory();
  EXPECT_EQ(kg::HashTrajectory(a), kg::HashTrajectory(b));
  kg::Trajectory c = a;
  c.frames[2].bodies[1].angularVelocity[2] =
      static_cast<double>(std::nextafter(static_cast<MeReal>(c.frames[2].bodies[1].angularVelocity[2]), MeReal(1)));
  EXPECT_NE(kg::HashTrajectory(a), kg::HashTrajectory(c));
  /* Frame numbers and times do not enter the hash. */
  kg::Trajectory d = a;
  d.frames[0].time = ts::Real(0.123);
  d.frames[4].index = 99;
  EXPECT_EQ(kg::HashTrajectory(a), kg::HashTrajectory(d));
}

TEST(TrajectoryReaderErrors, BadNumberReportsItsLine) {
  std::vector<std::string> lines = Lines(WriteSynthetic(nullptr, nullptr));
  /* The second body line of the third frame. */
  int bodyLines = 0;
  std::size_t target = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("body 1 ", 0) == 0 && ++bodyLines == 3) {
      target = i;
      break;
    }
  }
  ASSERT_NE(target, 0u);
  const std::size_t at = lines[target].find(" pos ") + 5;
  const std::size_t end = lines[target].find(' ', at);
  lines[target].replace(at, end - at, "1.2.3");
  const int lineNumber = static_cast<int>(target) + 1;

  std::istringstream in(Join(lines));
  try {
    kg::ReadTrajectory(in, "bad.txt");
    FAIL() << "a bad number was accepted";
  } catch (const kg::TrajectoryFormatError &e) {
    EXPECT_EQ(e.line(), lineNumber);
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.txt:" + std::to_string(lineNumber) + ":"), std::string::npos) << what;
    EXPECT_NE(what.find("1.2.3"), std::string::npos) << what;
  }
}

TEST(TrajectoryReaderErrors, TruncatedFileIsRejected) {
  std::vector<std::string> lines = Lines(WriteSynthetic(nullptr, nullptr));
  ASSERT_EQ(lines.back().rfind("final-hash ", 0), 0u);
  lines.pop_back();
  {
    std::istringstream in(Join(lines));
    EXPECT_THROW(kg::ReadTrajectory(in, "truncated.txt"), kg::TrajectoryFormatError);
  }
  /* Cut in the middle of a frame too. */
  lines.resize(lines.size() / 2);
  {
    std::istringstream in(Join(lines));
    EXPECT_THROW(kg::ReadTrajectory(in, "half.txt"), kg::TrajectoryFormatError);
  }
  /* A writer destroyed without Finish leaves a truncated file. */
  ts::TempDir dir("io_trunc");
  const auto path = dir.path() / "unfinished.txt";
  {
    const kg::Trajectory model = ts::SyntheticTrajectory();
    kg::TrajectoryWriter w(model.header, path);
    w.BeginFrame(0, 0.0);
    for (const kg::BodyState &b : model.frames[0].bodies) w.AddBody(b);
    w.EndFrame();
  }
  EXPECT_THROW(kg::ReadTrajectoryFile(path), kg::TrajectoryFormatError);
}

TEST(TrajectoryReaderErrors, MissingFileThrows) {
  ts::TempDir dir("io_missing");
  const auto path = dir.path() / "does_not_exist.txt";
  try {
    kg::ReadTrajectoryFile(path);
    FAIL() << "reading a missing file did not throw";
  } catch (const kg::TrajectoryFormatError &e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find("does_not_exist.txt"), std::string::npos) << e.what();
  }
}

TEST(TrajectoryReaderErrors, WrongBodyCountInFrameIsRejected) {
  std::vector<std::string> lines = Lines(WriteSynthetic(nullptr, nullptr));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("body 2 ", 0) == 0) {
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    }
  }
  std::istringstream in(Join(lines));
  EXPECT_THROW(kg::ReadTrajectory(in, "short.txt"), kg::TrajectoryFormatError);
}

TEST(TrajectoryWriterErrors, OutOfOrderCallsThrow) {
  const kg::Trajectory model = ts::SyntheticTrajectory();
  std::ostringstream out;
  kg::TrajectoryWriter w(model.header, &out);
  w.BeginFrame(5, 0.0);
  for (const kg::BodyState &b : model.frames[0].bodies) w.AddBody(b);
  w.EndFrame();
  EXPECT_THROW(w.BeginFrame(5, 0.1), kg::GoldenError); /* not increasing */

  kg::TrajectoryWriter w2(model.header, &out);
  w2.BeginFrame(0, 0.0);
  w2.AddBody(model.frames[0].bodies[0]);
  EXPECT_THROW(w2.EndFrame(), kg::GoldenError); /* too few bodies */
}
