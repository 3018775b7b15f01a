#include <karma/golden/TrajectoryCompare.h>

#include <karma/golden/StateHash.h>

#include "RealText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace karma::golden {

namespace {

/* |a - b| treating equal values (also infinities) as 0 and NaN against a number as infinite. */
double Difference(double actual, double expected) {
  if (actual == expected) return 0.0;
  if (std::isnan(actual) || std::isnan(expected)) return (std::isnan(actual) && std::isnan(expected)) ? 0.0 : HUGE_VAL;
  return std::fabs(actual - expected);
}

std::string FrameList(const Trajectory &t) {
  std::string s;
  const std::size_t n = t.frames.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (n > 8 && i == 4) {
      s += " ...";
      i = n - 3;
    }
    s += ' ';
    s += std::to_string(t.frames[i].index);
  }
  return s.empty() ? " (none)" : s;
}

void CompareHeaders(const Trajectory &e, const Trajectory &a, TrajectoryComparison &c) {
  const TrajectoryHeader &he = e.header, &ha = a.header;
  auto mismatch = [&](const std::string &what, const std::string &ev, const std::string &av) {
    c.headerMismatches.push_back(what + " differs: expected " + ev + ", actual " + av);
  };
  if (he.bodyCount != ha.bodyCount) mismatch("body count", std::to_string(he.bodyCount), std::to_string(ha.bodyCount));
  if (he.program != ha.program) mismatch("program", he.program, ha.program);
  if (he.step != ha.step) mismatch("step", he.step, ha.step);
  if (he.precision != ha.precision)
    mismatch("precision", std::string(PrecisionName(he.precision)), std::string(PrecisionName(ha.precision)));
  if (he.timeStep != ha.timeStep)
    mismatch("time step", detail::FormatReal(he.timeStep, he.precision), detail::FormatReal(ha.timeStep, ha.precision));
  bool sameFrames = e.frames.size() == a.frames.size();
  for (std::size_t i = 0; sameFrames && i < e.frames.size(); ++i) sameFrames = e.frames[i].index == a.frames[i].index;
  if (!sameFrames)
    c.headerMismatches.push_back("frame set differs: expected " + std::to_string(e.frames.size()) + " frames (" +
                                 FrameList(e).substr(1) + "), actual " + std::to_string(a.frames.size()) + " (" +
                                 FrameList(a).substr(1) + ")");
  if (he.backend != ha.backend)
    c.notes.push_back("backends differ (expected " + he.backend + ", actual " + ha.backend +
                      "): comparing across backends");
  if (he.sampling != ha.sampling) c.notes.push_back("sampling descriptions differ");
}

void NoteRecordedHashes(const Trajectory &t, const char *which, std::uint64_t recomputed, TrajectoryComparison &c) {
  std::vector<std::uint64_t> perFrame;
  HashTrajectory(t, &perFrame);
  bool consistent = t.finalHash == recomputed;
  for (std::size_t i = 0; consistent && i < perFrame.size(); ++i) consistent = perFrame[i] == t.frames[i].hash;
  if (!consistent)
    c.notes.push_back(std::string("the ") + which +
                      " file's recorded hashes do not match its values (edited by hand?); recomputed hashes are used");
}

/* Compares two bodies; quaternions as the sign of `a` that is closer to `e`. */
void CompareBody(const TrajectoryFrame &fe, const BodyState &e, const BodyState &a, int body, TrajectoryComparison &c) {
  BodyDeviation &dev = c.deviations[static_cast<std::size_t>(body)];
  for (Quantity q : kAllQuantities) {
    const int qi = static_cast<int>(q);
    const Tolerance &tol = c.tolerances[q];
    const double *ev = e.Values(q);
    const double *av = a.Values(q);
    double sign = 1.0;
    if (q == Quantity::Quaternion) {
      double plus = 0.0, minus = 0.0;
      for (int i = 0; i < 4; ++i) {
        plus = std::max(plus, Difference(av[i], ev[i]));
        minus = std::max(minus, Difference(-av[i], ev[i]));
      }
      if (minus < plus) sign = -1.0;
    }
    for (int i = 0; i < QuantitySize(q); ++i) {
      const double actual = sign * av[i];
      const double d = Difference(actual, ev[i]);
      ++c.comparedValues;
      if (d > dev.maxDifference[qi]) {
        dev.maxDifference[qi] = d;
        dev.atFrame[qi] = fe.index;
      }
      if (tol.Accepts(actual, ev[i])) continue;
      dev.withinTolerance[qi] = false;
      ++c.failingValues;
      if (!c.firstFailure)
        c.firstFailure = ValueDifference{fe.index, fe.time, body, q, i, ev[i], actual, d, tol.Allowed(ev[i])};
    }
  }
}

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}

const char *ComponentName(Quantity q, int i) {
  static const char *const xyz[] = {"x", "y", "z"};
  static const char *const wxyz[] = {"w", "x", "y", "z"};
  return q == Quantity::Quaternion ? wxyz[i & 3] : xyz[i < 3 ? i : 0];
}

}  // namespace

TrajectoryComparison CompareTrajectories(const Trajectory &expected, const Trajectory &actual,
                                         const TrajectoryTolerances &tolerances) {
  TrajectoryComparison c;
  c.tolerances = tolerances;
  c.expectedHash = HashTrajectory(expected);
  c.actualHash = HashTrajectory(actual);
  NoteRecordedHashes(expected, "expected", c.expectedHash, c);
  NoteRecordedHashes(actual, "actual", c.actualHash, c);
  CompareHeaders(expected, actual, c);
  /* Equal hashes over the same values' bytes; the precisions must also agree
   * (a float and a double run could collide only by accident). */
  c.hashesMatch = c.expectedHash == c.actualHash && expected.header.precision == actual.header.precision;

  const bool sameBodies = expected.header.bodyCount == actual.header.bodyCount;
  if (sameBodies) {
    c.deviations.resize(static_cast<std::size_t>(expected.header.bodyCount));
    /* Compare frames present in both (by index), even when the sets differ. */
    std::size_t j = 0;
    for (const TrajectoryFrame &fe : expected.frames) {
      while (j < actual.frames.size() && actual.frames[j].index < fe.index) ++j;
      if (j == actual.frames.size()) break;
      const TrajectoryFrame &fa = actual.frames[j];
      if (fa.index != fe.index) continue;
      for (int b = 0; b < expected.header.bodyCount; ++b)
        CompareBody(fe, fe.bodies[static_cast<std::size_t>(b)], fa.bodies[static_cast<std::size_t>(b)], b, c);
    }
  }

  c.passed = c.headerMismatches.empty() && c.failingValues == 0;
  if (c.passed && c.hashesMatch)
    c.verdict = "MATCH: bit-identical (state hash " + FormatHash(c.actualHash) + ")";
  else if (c.passed)
    c.verdict = "PASS: within tolerance, but hashes differ (not bit-identical)";
  else if (!c.headerMismatches.empty())
    c.verdict = "FAIL: " + c.headerMismatches.front();
  else {
    const ValueDifference &f = *c.firstFailure;
    c.verdict = "FAIL: " + std::to_string(c.failingValues) + " of " + std::to_string(c.comparedValues) +
                " values out of tolerance, first at frame " + std::to_string(f.frame) + " body " +
                std::to_string(f.body) + " " + std::string(QuantityName(f.quantity));
  }
  return c;
}

std::string ReportText(const TrajectoryComparison &c, const std::string &expectedName, const std::string &actualName) {
  std::ostringstream o;
  o << "trajectory comparison\n";
  o << "  expected: " << expectedName << "\n";
  o << "  actual:   " << actualName << "\n";
  if (c.hashesMatch)
    o << "  hashes match: " << FormatHash(c.expectedHash) << "\n";
  else
    o << "  hashes differ: expected " << FormatHash(c.expectedHash) << ", actual " << FormatHash(c.actualHash) << "\n";
  for (const std::string &m : c.headerMismatches) o << "  header mismatch: " << m << "\n";
  for (const std::string &n : c.notes) o << "  note: " << n << "\n";
  o << "  tolerances (|actual - expected| <= abs + rel*|expected|):";
  for (Quantity q : kAllQuantities)
    o << " " << QuantityName(q) << " abs " << Num(c.tolerances[q].absolute) << " rel " << Num(c.tolerances[q].relative)
      << (q == Quantity::AngularVelocity ? "" : ";");
  o << "\n";
  if (c.firstFailure) {
    const ValueDifference &f = *c.firstFailure;
    o << "  first difference beyond tolerance: frame " << f.frame << " (time " << Num(f.time) << "), body " << f.body
      << ", " << QuantityName(f.quantity) << "." << ComponentName(f.quantity, f.component) << ": expected "
      << Num(f.expected) << ", actual " << Num(f.actual) << ", |difference| " << Num(f.difference) << " > allowed "
      << Num(f.allowed) << "\n";
  }
  if (!c.deviations.empty() && !c.hashesMatch) {
    o << "  largest |actual - expected| per body over the run (frame in brackets, * = beyond tolerance):\n";
    auto row = [&o](const std::string &body, const std::array<std::string, kQuantityCount> &cells) {
      std::string line = "    " + std::string(body.size() < 6 ? 6 - body.size() : 0, ' ') + body;
      for (const std::string &cell : cells)
        line += "  " + cell + std::string(cell.size() < 24 ? 24 - cell.size() : 0, ' ');
      while (!line.empty() && line.back() == ' ') line.pop_back();
      o << line << "\n";
    };
    row("body", {"pos", "quat", "linvel", "angvel"});
    for (std::size_t b = 0; b < c.deviations.size(); ++b) {
      const BodyDeviation &d = c.deviations[b];
      std::array<std::string, kQuantityCount> cells;
      for (int q = 0; q < kQuantityCount; ++q)
        cells[q] =
            Num(d.maxDifference[q]) + (d.withinTolerance[q] ? "" : "*") + " [" + std::to_string(d.atFrame[q]) + "]";
      row(std::to_string(b), cells);
    }
  }
  o << "verdict: " << c.verdict << "\n";
  return o.str();
}

}  // namespace karma::golden
