#include <karma/golden/TrajectoryReader.h>

#include <karma/golden/StateHash.h>

#include "RealText.h"

#include <charconv>
#include <fstream>
#include <istream>
#include <map>
#include <optional>
#include <string_view>

namespace karma::golden {

namespace {

std::vector<std::string_view> SplitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::optional<long> ParseLong(std::string_view text) {
  long value = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string Quoted(std::string_view s) {
  constexpr std::size_t kMax = 40;
  std::string out(1, '\'');
  out.append(s.substr(0, kMax));
  if (s.size() > kMax) out += "...";
  out += '\'';
  return out;
}

/* Parses one file; every error carries the current line number. */
class Parser {
 public:
  Parser(std::istream &in, const std::string &source) : in_(in), source_(source) {}

  Trajectory Parse() {
    ReadMagic();
    ReadHeader();
    ReadFrames();
    return std::move(result_);
  }

 private:
  [[noreturn]] void Error(const std::string &problem) const { throw TrajectoryFormatError(source_, line_, problem); }

  /* Next non-comment line split into words; false at end of file. */
  bool Next(std::vector<std::string_view> &words) {
    while (std::getline(in_, text_)) {
      ++line_;
      if (!text_.empty() && text_.back() == '\r') text_.pop_back(); /* CRLF checkouts */
      if (text_.find('\0') != std::string::npos) Error("contains a NUL byte (not a text file?)");
      words = SplitWords(text_);
      if (words.empty() || words[0][0] == '#') continue;
      return true;
    }
    if (in_.bad()) Error("read error");
    return false;
  }

  void ReadMagic() {
    std::vector<std::string_view> w;
    if (!Next(w)) Error("empty file: expected 'karma-trajectory 1'");
    if (w[0] != "karma-trajectory")
      Error("not a trajectory file: expected 'karma-trajectory 1', found " + Quoted(text_));
    if (w.size() != 2 || w[1] != "1") Error("unsupported trajectory format version (this reader knows version 1)");
  }

  void ReadHeader() {
    static const char *const kKeys[] = {"program", "step", "backend", "precision", "bodies", "sampling", "timestep"};
    std::map<std::string, std::pair<std::string, int>> values; /* key -> (value, line) */
    std::vector<std::string_view> w;
    for (;;) {
      if (!Next(w)) Error("file ends inside the header");
      if (w[0] == "frame" || w[0] == "final-hash") break;
      const std::string key(w[0]);
      bool known = false;
      for (const char *k : kKeys) known = known || key == k;
      if (!known) Error("unknown header field " + Quoted(key));
      if (values.count(key)) Error("header field '" + key + "' appears twice");
      std::string value;
      if (key == "sampling") { /* free text: the rest of the line */
        const std::size_t at = text_.find("sampling") + 8;
        value = text_.substr(at);
        if (!value.empty() && value[0] == ' ') value.erase(0, 1);
      } else {
        if (w.size() != 2) Error("header field '" + key + "' takes exactly one value");
        value = std::string(w[1]);
      }
      values[key] = {value, line_};
    }
    const int firstDataLine = line_;
    for (const char *k : kKeys)
      if (!values.count(k))
        Error(std::string("header lacks the '") + k + "' field (it must come before the first frame)");

    TrajectoryHeader &h = result_.header;
    h.program = values["program"].first;
    h.step = values["step"].first;
    h.backend = values["backend"].first;
    h.sampling = values["sampling"].first;
    line_ = values["precision"].second;
    auto precision = ParsePrecision(values["precision"].first);
    if (!precision) Error("precision must be 'single' or 'double', found " + Quoted(values["precision"].first));
    h.precision = *precision;
    line_ = values["bodies"].second;
    auto bodies = ParseLong(values["bodies"].first);
    if (!bodies || *bodies < 0 || *bodies > 100000000) Error("bad body count " + Quoted(values["bodies"].first));
    h.bodyCount = static_cast<int>(*bodies);
    line_ = values["timestep"].second;
    auto step = detail::ParseReal(values["timestep"].first, h.precision);
    if (!step) Error("bad time step " + Quoted(values["timestep"].first));
    h.timeStep = *step;
    line_ = firstDataLine;
    pending_ = std::move(w);
  }

  double Number(std::string_view word, const char *what) const {
    auto v = detail::ParseReal(word, result_.header.precision);
    if (!v)
      Error(Quoted(word) + " is not a " + std::string(PrecisionName(result_.header.precision)) + "-precision number (" +
            what + ")");
    return *v;
  }

  void ReadFrames() {
    std::vector<std::string_view> w = std::move(pending_);
    for (;;) {
      if (w[0] == "final-hash") {
        if (w.size() != 2) Error("'final-hash' takes one value");
        auto hash = ParseHash(w[1]);
        if (!hash) Error("bad hash " + Quoted(w[1]) + " (expected 0x and 16 hex digits)");
        result_.finalHash = *hash;
        if (Next(w)) Error("unexpected " + Quoted(text_) + " after the final-hash line");
        return;
      }
      if (w[0] != "frame") Error("expected 'frame' or 'final-hash', found " + Quoted(w[0]));
      ReadFrame(w);
      if (!Next(w)) Error("file ends before the final-hash line (truncated?)");
    }
  }

  void ReadFrame(const std::vector<std::string_view> &w) {
    if (w.size() != 4 || w[2] != "time") Error("expected 'frame <index> time <t>'");
    TrajectoryFrame frame;
    auto index = ParseLong(w[1]);
    if (!index || *index < 0) Error("bad frame index " + Quoted(w[1]));
    frame.index = *index;
    if (!result_.frames.empty() && frame.index <= result_.frames.back().index)
      Error("frame " + std::to_string(frame.index) + " does not come after frame " +
            std::to_string(result_.frames.back().index));
    frame.time = Number(w[3], "frame time");

    std::vector<std::string_view> b;
    for (int i = 0; i < result_.header.bodyCount; ++i) {
      if (!Next(b)) Error("file ends inside frame " + std::to_string(frame.index));
      if (b[0] != "body")
        Error("frame " + std::to_string(frame.index) + " has " + std::to_string(i) + " body lines, the header says " +
              std::to_string(result_.header.bodyCount) + " (found " + Quoted(b[0]) + ")");
      frame.bodies.push_back(ReadBody(b, i));
    }
    if (!Next(b)) Error("file ends inside frame " + std::to_string(frame.index));
    if (b[0] == "body")
      Error("frame " + std::to_string(frame.index) + " has more than the " + std::to_string(result_.header.bodyCount) +
            " bodies the header declares");
    if (b[0] != "hash" || b.size() != 2) Error("expected 'hash 0x...' to end frame " + std::to_string(frame.index));
    auto hash = ParseHash(b[1]);
    if (!hash) Error("bad hash " + Quoted(b[1]) + " (expected 0x and 16 hex digits)");
    frame.hash = *hash;
    result_.frames.push_back(std::move(frame));
  }

  BodyState ReadBody(const std::vector<std::string_view> &w, int expectedIndex) {
    if (w.size() < 2 || ParseLong(w[1]) != std::optional<long>(expectedIndex))
      Error("expected 'body " + std::to_string(expectedIndex) + "'" +
            (w.size() >= 2 ? ", found body " + Quoted(w[1]) : ""));
    BodyState body;
    std::size_t at = 2;
    for (Quantity q : kAllQuantities) {
      const std::string name(QuantityName(q));
      if (at >= w.size() || w[at] != name)
        Error("body " + std::to_string(expectedIndex) + ": expected '" + name + "'" +
              (at < w.size() ? ", found " + Quoted(w[at]) : " but the line ends"));
      ++at;
      double *v = body.Values(q);
      for (int i = 0; i < QuantitySize(q); ++i, ++at) {
        if (at >= w.size())
          Error("body " + std::to_string(expectedIndex) + ": '" + name + "' needs " + std::to_string(QuantitySize(q)) +
                " numbers");
        const std::string what = "body " + std::to_string(expectedIndex) + " " + name;
        v[i] = Number(w[at], what.c_str());
      }
    }
    if (at != w.size())
      Error("body " + std::to_string(expectedIndex) + ": unexpected " + Quoted(w[at]) + " after angvel");
    return body;
  }

  std::istream &in_;
  std::string source_;
  std::string text_;
  int line_ = 0;
  std::vector<std::string_view> pending_; /* views into text_: valid until the next Next() */
  Trajectory result_;
};

}  // namespace

Trajectory ReadTrajectory(std::istream &in, const std::string &sourceName) { return Parser(in, sourceName).Parse(); }

Trajectory ReadTrajectoryFile(const std::filesystem::path &path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw TrajectoryFormatError(path.string(), 0, "is a directory, not a trajectory file");
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if (!in) throw TrajectoryFormatError(path.string(), 0, "cannot open trajectory file");
  return ReadTrajectory(in, path.string());
}

}  // namespace karma::golden
