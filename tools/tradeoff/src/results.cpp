// results.cpp: medians, the fronts and their summary (results.h).
#include "results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pareto.h"

namespace karma::tradeoff {

namespace {

std::string Number(double v, const char *format = "%.3g") {
  char text[32];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

bool Same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

}  // namespace

double ResultRow::median() const {
  if (micros.empty()) return std::nan("");
  std::vector<double> m = micros;
  std::sort(m.begin(), m.end());
  const size_t n = m.size();
  return n % 2 ? m[n / 2] : (m[n / 2 - 1] + m[n / 2]) / 2;
}

double ResultRow::low() const {
  return micros.empty() ? std::nan("") : *std::min_element(micros.begin(), micros.end());
}
double ResultRow::high() const {
  return micros.empty() ? std::nan("") : *std::max_element(micros.begin(), micros.end());
}

void MarkFronts(std::vector<ResultRow> &rows, const std::string &scene) {
  std::vector<size_t> index;
  std::vector<CostError> drift, error;
  for (size_t i = 0; i < rows.size(); ++i) {
    const ResultRow &r = rows[i];
    if (r.scene != scene || r.isPeer()) continue;
    index.push_back(i);
    drift.push_back({r.perFrame(), r.drift, r.held});
    error.push_back({r.perFrame(), r.sceneError, r.held});
  }
  const std::vector<bool> a = ParetoFront(drift), b = ParetoFront(error);
  for (size_t k = 0; k < index.size(); ++k) {
    rows[index[k]].frontDrift = a[k];
    rows[index[k]].frontScene = b[k];
  }
}

std::string DifferingKnobs(const Setting &a, const Setting &b) {
  std::vector<std::string> knobs;
  if (a.solver() != b.solver()) knobs.push_back("solver");
  if (!Same(a.epsilon, b.epsilon)) knobs.push_back("epsilon");
  if (!Same(a.gamma, b.gamma)) knobs.push_back("gamma");
  if (a.h != b.h) knobs.push_back("h");
  if (!Same(a.tolerance, b.tolerance)) knobs.push_back("tolerance");
  if (a.cap != b.cap) knobs.push_back("cap");
  if (a.projection != b.projection) knobs.push_back("joint projection");
  if (a.warm != b.warm) knobs.push_back("kept warm starts");
  if (!Same(a.reuse, b.reuse)) knobs.push_back("contact reuse");
  if (a.precision != b.precision) knobs.push_back("precision");
  std::string out;
  for (size_t i = 0; i < knobs.size(); ++i) out += (i == 0 ? "" : i + 1 == knobs.size() ? " and " : ", ") + knobs[i];
  return out.empty() ? "nothing" : out;
}

std::string FrontSummary(const std::vector<ResultRow> &rows, const std::string &scene, bool sceneError) {
  std::vector<const ResultRow *> front;
  for (const ResultRow &r : rows)
    if (r.scene == scene && !r.isPeer() && (sceneError ? r.frontScene : r.frontDrift)) front.push_back(&r);
  if (front.empty()) return "No setting held: the sweep has no front.";
  std::sort(front.begin(), front.end(),
            [](const ResultRow *a, const ResultRow *b) { return a->perFrame() < b->perFrame(); });
  auto error = [&](const ResultRow *r) { return sceneError ? r->sceneError : r->drift; };
  const ResultRow *fast = front.front(), *best = front.back();
  if (front.size() == 1)
    return std::string("`") + fast->setting.label() +
           "` is both the fastest and the most accurate setting that held (" + Number(fast->perFrame()) +
           " µs per 1/60 s, error " + Number(error(fast)) + ").";
  // The segment of the front with the largest error reduction per unit
  // of log time: log(e_i / e_i+1) / log(t_i+1 / t_i).
  size_t bestSegment = 0;
  double bestGain = -1;
  for (size_t i = 0; i + 1 < front.size(); ++i) {
    const double e0 = std::max(error(front[i]), 1e-12), e1 = std::max(error(front[i + 1]), 1e-12);
    const double t = std::log(std::max(front[i + 1]->perFrame() / front[i]->perFrame(), 1.0 + 1e-9));
    const double gain = std::log(e0 / e1) / t;
    if (gain > bestGain) bestGain = gain, bestSegment = i;
  }
  const ResultRow *a = front[bestSegment], *b = front[bestSegment + 1];
  return std::string("The front runs from `") + fast->setting.label() + "` (" + Number(fast->perFrame()) +
         " µs per 1/60 s, error " + Number(error(fast)) + ") to `" + best->setting.label() + "` (" +
         Number(best->perFrame()) + " µs per 1/60 s, error " + Number(error(best)) +
         "); the most accuracy per microsecond comes from changing " + DifferingKnobs(a->setting, b->setting) + " (`" +
         a->setting.label() + "` to `" + b->setting.label() + "`: error ÷" +
         Number(error(a) / std::max(error(b), 1e-12), "%.2g") + " for ×" +
         Number(b->perFrame() / a->perFrame(), "%.2g") + " the time).";
}

}  // namespace karma::tradeoff
