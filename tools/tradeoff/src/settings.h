// settings.h: one combination of the accuracy knobs (a "setting") and the
// sweep syntax that expands into a list of them.
//
// Sweep syntax: space-separated `knob=values`; every combination of the
// knobs' values is one setting (the first knob varies slowest).
//   solver     exact | exact:N | iterative:N | budget:US
//              exact: Kea's active-set method (MdtKeaMethodActiveSet),
//              exact:N caps it at N iterations (solves of the free block);
//              iterative:N is projected Gauss-Seidel with N sweeps
//              (MdtKeaMethodPGS). "pgs:N" is a synonym of iterative:N.
//              budget:US lets the engine choose within US microseconds
//              per MdtWorldStep (MdtWorldSetStepBudget).
//   epsilon    constraint softness (MdtWorldSetEpsilon)
//   gamma      constraint relaxation per step (MdtWorldSetGamma)
//   h          step size in seconds (1/60 is accepted)
//   tolerance  Kea's relative tolerance (MdtWorldSetKeaTolerance)
//   cap        matrix capping, rows per partition (MdtWorldSetMaxMatrixSize)
//   projection joint projection iterations after each step
//              (MdtWorldSetJointProjection; 0 = off)
//   warm       1: the exact solver keeps a warm start that already meets a
//              sixteenth of the tolerance, with no solve (the default);
//              0: it solves every partition
//              (MdtWorldSetKeaAcceptWarmStart)
//   reuse      contact reuse distance in metres: a resting pair's contacts
//              are served from memory while it moves less than this
//              (McdFrameworkSetContactReuseDistance; 0 = every pair tested
//              every step; no effect in a scene without collision)
// Values: a comma list `a,b,c`, or a geometric range `lo..hi` (both ends
// included; ratio 10 when both ends are powers of ten, otherwise 2), or
// `lo..hi:N` (N points, geometric). A knob left out keeps the scene's own
// value (the world's default unless the scene sets it); h defaults to 1/60.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "McdFrame.h"
#include "MdtWorld.h"

namespace karma::tradeoff {

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

struct Setting {
  MdtKeaMethod method = MdtKeaMethodActiveSet;
  int iterations = 0;       // 0: Kea's default cap
  double budget = 0;        // microseconds per MdtWorldStep; 0: no budget
  double epsilon = kUnset;  // NaN: the scene's own
  double gamma = kUnset;
  double h = 1.0 / 60;
  double tolerance = kUnset;
  int cap = -1;         // < 0: the scene's own
  int projection = -1;  // < 0: the scene's own
  int warm = -1;        // < 0: the scene's own; 0 or 1
  double reuse = kUnset;
  // "single" or "double" when a sweep runs both (--precision); empty
  // otherwise. Not a world setting: the precision of the build that ran.
  std::string precision;
  // "exact", "exact:8", "iterative:50", "budget:300".
  std::string solver() const;
  // The knobs that are set, e.g. "exact:8 epsilon=1e-3 h=1/120 projection=2 warm=0 reuse=0".
  std::string label() const;
  // Applies every knob that is set (not h: the runner steps with it); the
  // collision knob to `framework` when the scene has one (may be NULL).
  void apply(MdtWorldID world, McdFrameworkID framework) const;
};

// "1/120" when 1/h is a whole number, else "%g".
std::string FormatStep(double h);
// "%g" of a value.
std::string FormatValue(double v);

// Parses a sweep; on error returns false and says why in `error`.
bool ParseSweep(const std::string &text, std::vector<Setting> &out, std::string &error);
// A value: a number or a fraction "a/b". False when it is neither.
bool ParseNumber(const std::string &text, double &out);
// Expands "a,b,c", "lo..hi" or "lo..hi:N" (see the top).
bool ExpandValues(const std::string &text, std::vector<double> &out, std::string &error);

}  // namespace karma::tradeoff
