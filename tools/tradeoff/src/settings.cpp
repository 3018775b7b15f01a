// settings.cpp: the sweep syntax (settings.h) and applying a setting.
#include "settings.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace karma::tradeoff {

namespace {

bool IsPowerOfTen(double v) {
  const double e = std::log10(v);
  return std::fabs(e - std::round(e)) < 1e-9;
}

std::vector<std::string> Split(const std::string &text, char separator) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, separator))
    if (!item.empty()) out.push_back(item);
  return out;
}

bool ParseSolver(const std::string &text, Setting &s) {
  const size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  int n = 0;
  if (colon != std::string::npos) {
    double v = 0;
    if (!ParseNumber(text.substr(colon + 1), v) || v < 1 || v != std::floor(v)) return false;
    n = (int)v;
  }
  s.budget = 0;
  if (kind == "budget" && n > 0) {
    s.method = MdtKeaMethodActiveSet;
    s.budget = n;
    n = 0;
  } else if (kind == "exact") {
    s.method = MdtKeaMethodActiveSet;
  } else if ((kind == "iterative" || kind == "pgs") && n > 0) {
    s.method = MdtKeaMethodPGS;
  } else {
    return false;
  }
  s.iterations = n;
  return true;
}

// Sets knob `name` of every setting in `in` to each value in turn.
bool Multiply(const std::string &name, const std::string &values, std::vector<Setting> &settings, std::string &error) {
  std::vector<Setting> out;
  if (name == "solver") {
    for (const Setting &base : settings)
      for (const std::string &v : Split(values, ',')) {
        Setting s = base;
        if (!ParseSolver(v, s)) {
          error = "bad solver '" + v + "' (exact, exact:N, iterative:N or budget:US)";
          return false;
        }
        out.push_back(s);
      }
    settings = out;
    return true;
  }
  std::vector<double> list;
  if (!ExpandValues(values, list, error)) return false;
  for (const Setting &base : settings)
    for (double v : list) {
      Setting s = base;
      if (name == "epsilon" && v >= 0)
        s.epsilon = v;
      else if (name == "gamma" && v >= 0)
        s.gamma = v;
      else if (name == "h" && v > 0)
        s.h = v;
      else if (name == "tolerance" && v >= 0)
        s.tolerance = v;
      else if (name == "cap" && v >= 0 && v == std::floor(v))
        s.cap = (int)v;
      else if (name == "projection" && v >= 0 && v == std::floor(v))
        s.projection = (int)v;
      else if (name == "warm" && (v == 0 || v == 1))
        s.warm = (int)v;
      else if (name == "reuse" && v >= 0)
        s.reuse = v;
      else {
        error = "bad knob or value: " + name + "=" + FormatValue(v);
        return false;
      }
      out.push_back(s);
    }
  settings = out;
  return true;
}

}  // namespace

bool ParseNumber(const std::string &text, double &out) {
  if (text.empty()) return false;
  const size_t slash = text.find('/');
  char *end = nullptr;
  if (slash != std::string::npos) {
    double a = 0, b = 0;
    if (!ParseNumber(text.substr(0, slash), a) || !ParseNumber(text.substr(slash + 1), b) || b == 0) return false;
    out = a / b;
    return true;
  }
  out = std::strtod(text.c_str(), &end);
  return end && *end == 0 && std::isfinite(out);
}

bool ExpandValues(const std::string &text, std::vector<double> &out, std::string &error) {
  out.clear();
  const size_t dots = text.find("..");
  if (dots == std::string::npos) {
    for (const std::string &v : Split(text, ',')) {
      double x = 0;
      if (!ParseNumber(v, x)) {
        error = "bad value '" + v + "'";
        return false;
      }
      out.push_back(x);
    }
    if (out.empty()) error = "no value in '" + text + "'";
    return !out.empty();
  }
  std::string hiText = text.substr(dots + 2);
  int count = 0;
  const size_t colon = hiText.find(':');
  double lo = 0, hi = 0, n = 0;
  if (colon != std::string::npos) {
    if (!ParseNumber(hiText.substr(colon + 1), n) || n < 2 || n > 1000 || n != std::floor(n)) {
      error = "bad point count in '" + text + "'";
      return false;
    }
    count = (int)n;
    hiText = hiText.substr(0, colon);
  }
  if (!ParseNumber(text.substr(0, dots), lo) || !ParseNumber(hiText, hi) || lo <= 0 || hi <= 0) {
    error = "bad range '" + text + "' (lo..hi, both positive)";
    return false;
  }
  const double ratio = hi / lo;
  if (count == 0) {
    const double factor = IsPowerOfTen(lo) && IsPowerOfTen(hi) ? 10 : 2;
    count = (int)std::lround(std::fabs(std::log(ratio) / std::log(factor))) + 1;
  }
  // lo * ratio^(i/(count-1)), the ends exact.
  for (int i = 0; i < count; ++i) {
    const double x = i == 0 ? lo : i == count - 1 ? hi : lo * std::pow(ratio, (double)i / (count - 1));
    out.push_back(x);
  }
  return true;
}

bool ParseSweep(const std::string &text, std::vector<Setting> &out, std::string &error) {
  out.assign(1, Setting{});
  std::istringstream in(text);
  std::string term;
  while (in >> term) {
    const size_t eq = term.find('=');
    if (eq == std::string::npos || eq == 0) {
      error = "expected knob=values, got '" + term + "'";
      return false;
    }
    if (!Multiply(term.substr(0, eq), term.substr(eq + 1), out, error)) return false;
  }
  return true;
}

std::string FormatValue(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

std::string FormatStep(double h) {
  const double n = 1 / h;
  if (std::fabs(n - std::round(n)) < 1e-6 * n) return "1/" + FormatValue(std::round(n));
  return FormatValue(h);
}

std::string Setting::solver() const {
  if (budget > 0) return "budget:" + FormatValue(budget);
  if (method == MdtKeaMethodPGS) return "iterative:" + std::to_string(iterations);
  return iterations > 0 ? "exact:" + std::to_string(iterations) : "exact";
}

std::string Setting::label() const {
  std::string s = solver();
  if (!std::isnan(epsilon)) s += " epsilon=" + FormatValue(epsilon);
  if (!std::isnan(gamma)) s += " gamma=" + FormatValue(gamma);
  s += " h=" + FormatStep(h);
  if (!std::isnan(tolerance)) s += " tolerance=" + FormatValue(tolerance);
  if (cap >= 0) s += " cap=" + std::to_string(cap);
  if (projection >= 0) s += " projection=" + std::to_string(projection);
  if (warm >= 0) s += " warm=" + std::to_string(warm);
  if (!std::isnan(reuse)) s += " reuse=" + FormatValue(reuse);
  if (!precision.empty()) s += " " + precision;
  return s;
}

void Setting::apply(MdtWorldID world, McdFrameworkID framework) const {
  MdtWorldSetKeaMethod(world, method);
  MdtWorldSetKeaIterativeRows(world, 0);  // the named solver for every partition, whatever its size
  MdtWorldSetKeaMaxIterations(world, iterations);
  MdtWorldSetStepBudget(world, (MeReal)budget);
  if (!std::isnan(epsilon)) MdtWorldSetEpsilon(world, (MeReal)epsilon);
  if (!std::isnan(gamma)) MdtWorldSetGamma(world, (MeReal)gamma);
  if (!std::isnan(tolerance)) MdtWorldSetKeaTolerance(world, (MeReal)tolerance);
  if (cap >= 0) MdtWorldSetMaxMatrixSize(world, cap);
  if (projection >= 0) MdtWorldSetJointProjection(world, projection);
  if (warm >= 0) MdtWorldSetKeaAcceptWarmStart(world, warm);
  if (!std::isnan(reuse) && framework) McdFrameworkSetContactReuseDistance(framework, (MeReal)reuse);
}

}  // namespace karma::tradeoff
