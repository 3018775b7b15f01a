#include "Options.h"

#include <cmath>
#include <cstdlib>

namespace karma::golden::cli {

namespace {

double ParseNonNegative(const std::string &option, const std::string &text) {
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < 0.0)
    throw UsageError(option + " needs a non-negative number, got '" + text + "'");
  return v;
}

struct ToleranceFlag {
  const char *suffix; /* pos, quat, linvel, angvel */
  Quantity quantity;
};
constexpr ToleranceFlag kFlags[] = {{"pos", Quantity::Position},
                                    {"quat", Quantity::Quaternion},
                                    {"linvel", Quantity::LinearVelocity},
                                    {"angvel", Quantity::AngularVelocity}};

}  // namespace

Options ParseOptions(const std::vector<std::string> &args, unsigned groups) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i];
    if (name.size() < 2 || name.compare(0, 2, "--") != 0) {
      o.positional.push_back(name);
      continue;
    }
    std::string value;
    bool hasValue = false;
    if (const std::size_t eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      hasValue = true;
    }
    auto takeValue = [&]() -> std::string {
      if (hasValue) return value;
      if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
      return args[++i];
    };

    bool known = false;
    if (groups & kTrajectoryOptions) {
      for (const ToleranceFlag &f : kFlags) {
        const int q = static_cast<int>(f.quantity);
        if (name == std::string("--abs-") + f.suffix) {
          o.trajectory.absolute[q] = ParseNonNegative(name, takeValue());
          known = true;
        } else if (name == std::string("--rel-") + f.suffix) {
          o.trajectory.relative[q] = ParseNonNegative(name, takeValue());
          known = true;
        }
      }
    }
    if (!known && (groups & kImageOptions)) {
      if (name == "--channel-tol") {
        const double v = ParseNonNegative(name, takeValue());
        if (v > 255.0 || v != std::floor(v)) throw UsageError("--channel-tol needs an integer 0..255");
        o.image.channelTolerance = static_cast<int>(v);
        known = true;
      } else if (name == "--max-fraction") {
        const double v = ParseNonNegative(name, takeValue());
        if (v > 1.0) throw UsageError("--max-fraction needs a number in 0..1");
        o.image.maxDifferingFraction = v;
        known = true;
      }
    }
    if (!known && (groups & kDiffOption) && name == "--diff") {
      o.diffPath = takeValue();
      known = true;
    }
    if (!known && (groups & kCheckDirs)) {
      if (name == "--golden-dir") {
        o.goldenDir = takeValue();
        known = true;
      } else if (name == "--actual-dir") {
        o.actualDir = takeValue();
        known = true;
      }
    }
    if (!known) throw UsageError("unknown option " + name + " for this command");
  }
  return o;
}

std::string OptionHelp() {
  return "trajectory tolerances (defaults depend on the expected file's precision; see `karma-golden defaults`):\n"
         "  --abs-pos X --rel-pos Y        position (m)\n"
         "  --abs-quat X --rel-quat Y      quaternion components (compared up to sign)\n"
         "  --abs-linvel X --rel-linvel Y  linear velocity (m/s)\n"
         "  --abs-angvel X --rel-angvel Y  angular velocity (rad/s)\n"
         "  a value passes if |actual - expected| <= abs + rel * |expected|\n"
         "image tolerances:\n"
         "  --channel-tol N                a pixel differs if a channel differs by more than N (0..255)\n"
         "  --max-fraction F               fail if more than this fraction of pixels differ (0..1)\n";
}

}  // namespace karma::golden::cli
