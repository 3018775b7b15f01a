// peers.cpp: reading peer_bench's table (peers.h).
#include "peers.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "builtin_scenes.h"
#include "scene_spec.h"

namespace karma::tradeoff {

namespace {

std::vector<std::string> Cells(const std::string &line) {
  std::vector<std::string> cells;
  std::string cell;
  for (size_t i = 1; i < line.size(); ++i) {  // after the leading '|'
    if (line[i] == '|') {
      const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

// "1,921 [1,900–2,000]" -> 1921.
double LeadingNumber(const std::string &text) {
  std::string digits;
  for (char c : text) {
    if (c == ',') continue;
    if ((c >= '0' && c <= '9') || c == '.')
      digits += c;
    else
      break;
  }
  return digits.empty() ? std::nan("") : std::atof(digits.c_str());
}

double TopBoxStart(const scenes::SceneSpec &spec) {
  return spec.watched.empty() ? 0 : spec.bodies[(size_t)spec.watched[0]].position[1];
}

// The scene error from the figures cell, NaN when it does not parse.
double SceneErrorOf(const std::string &scene, const std::string &figures, double penetrationMm) {
  double a = 0, b = 0, c = 0, d = 0;
  if (scene == "car") {
    const size_t x = figures.find("x ");
    if (x != std::string::npos && std::sscanf(figures.c_str() + x, "x %lf m (analytic %lf)", &a, &b) == 2)
      return std::fabs(a - b);
  } else if (scene == "topple") {
    const size_t x = figures.find("drift ");
    if (x != std::string::npos && std::sscanf(figures.c_str() + x, "drift %lf mm, drop %lf mm", &a, &b) == 2)
      return std::fmax(a / 1e3, std::fabs(b / 1e3 - StackClosure(scenes::ToppleSpec())));
  } else if (scene == "stack21") {
    if (std::sscanf(figures.c_str(), "top box drift %lf mm, height %lf m", &a, &b) == 2)
      return std::fmax(a / 1e3,
                       std::fabs(TopBoxStart(scenes::Stack21Spec()) - b - StackClosure(scenes::Stack21Spec())));
  } else if (scene == "ragdoll") {
    if (std::sscanf(figures.c_str(), "joint error: max %lf mm, end %lf mm", &c, &d) >= 1) return c / 1e3;
  } else if (scene == "pile1000") {
    return penetrationMm / 1e3;
  }
  return std::nan("");
}

}  // namespace

bool ParsePeerRow(const std::string &line, ResultRow &out) {
  if (line.size() < 2 || line[0] != '|' || line.find("---") != std::string::npos) return false;
  const std::vector<std::string> c = Cells(line);
  // scene (steps) | engine | µs | × step | × quick | stable | figures | max speed | penetration
  if (c.size() < 9 || c[0].rfind("scene", 0) == 0) return false;
  out = ResultRow{};
  out.scene = c[0].substr(0, c[0].find(' '));
  out.engine = c[1];
  // "median [low–high]": all three, so that the row's median and range
  // read back.
  const size_t open = c[2].find('['), dash = c[2].find("–");
  const double median = LeadingNumber(c[2]);
  const double low = open == std::string::npos ? median : LeadingNumber(c[2].substr(open + 1));
  const double high = dash == std::string::npos ? median : LeadingNumber(c[2].substr(dash + std::string("–").size()));
  out.micros = {low, median, high};
  out.held = c[5].rfind("yes", 0) == 0;
  out.detail = c[6];
  out.maxSpeed = LeadingNumber(c[7]);
  out.penetration = LeadingNumber(c[8]) / 1e3;
  out.sceneError = SceneErrorOf(out.scene, c[6], LeadingNumber(c[8]));
  out.drift = out.jointError = out.energyError = out.momentumError = out.residual = std::nan("");
  return !std::isnan(median) && !out.engine.empty();
}

bool ReadPeerTable(const std::string &path, std::vector<ResultRow> &out, std::string &error) {
  std::ifstream in(path);
  if (!in) {
    error = "cannot read the peers' table " + path;
    return false;
  }
  std::string line;
  while (std::getline(in, line)) {
    ResultRow row;
    if (ParsePeerRow(line, row)) out.push_back(row);
  }
  return true;
}

}  // namespace karma::tradeoff
