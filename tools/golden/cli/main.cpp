/* karma-golden: compare and inspect golden outputs (docs/GOLDEN.md).
 *
 * Exit codes: 0 = match (or within tolerance), 1 = mismatch, 2 = usage or
 * I/O error (unreadable or malformed files, missing directories). */
#include "Options.h"

#include <karma/golden/Error.h>
#include <karma/golden/GoldenCheck.h>
#include <karma/golden/ImageCompare.h>
#include <karma/golden/StateHash.h>
#include <karma/golden/TrajectoryCompare.h>
#include <karma/golden/TrajectoryReader.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace kg = karma::golden;
using karma::golden::cli::Options;
using karma::golden::cli::UsageError;

namespace {

constexpr int kMatch = 0, kMismatch = 1, kError = 2;

void Usage(std::ostream &o) {
  o << "usage:\n"
       "  karma-golden compare-trajectory EXPECTED ACTUAL [trajectory tolerances]\n"
       "  karma-golden compare-image EXPECTED ACTUAL [--channel-tol N] [--max-fraction F] [--diff OUT.png]\n"
       "  karma-golden check --golden-dir DIR --actual-dir DIR [trajectory and image tolerances]\n"
       "  karma-golden hash FILE        print the state hash recomputed from a trajectory's values\n"
       "  karma-golden defaults         print the default tolerances\n"
       "exit code: 0 match, 1 mismatch, 2 usage or I/O error\n"
    << kg::cli::OptionHelp();
}

void RequirePositional(const Options &o, std::size_t n, const char *what) {
  if (o.positional.size() != n) throw UsageError(std::string("expected ") + what);
}

int CompareTrajectory(const std::vector<std::string> &args) {
  const Options o = kg::cli::ParseOptions(args, kg::cli::kTrajectoryOptions);
  RequirePositional(o, 2, "EXPECTED and ACTUAL trajectory files");
  const kg::Trajectory expected = kg::ReadTrajectoryFile(o.positional[0]);
  const kg::Trajectory actual = kg::ReadTrajectoryFile(o.positional[1]);
  const kg::TrajectoryTolerances tolerances =
      o.trajectory.ApplyTo(kg::DefaultTrajectoryTolerances(expected.header.precision));
  const kg::TrajectoryComparison c = kg::CompareTrajectories(expected, actual, tolerances);
  std::cout << kg::ReportText(c, o.positional[0], o.positional[1]);
  return c.passed ? kMatch : kMismatch;
}

int CompareImage(const std::vector<std::string> &args) {
  const Options o = kg::cli::ParseOptions(args, kg::cli::kImageOptions | kg::cli::kDiffOption);
  RequirePositional(o, 2, "EXPECTED and ACTUAL PNG files");
  const kg::ImageComparison c = kg::CompareImageFiles(o.positional[0], o.positional[1], o.image, o.diffPath);
  std::cout << kg::ReportText(c, o.positional[0], o.positional[1]);
  return c.passed ? kMatch : kMismatch;
}

int Check(const std::vector<std::string> &args) {
  const Options o =
      kg::cli::ParseOptions(args, kg::cli::kTrajectoryOptions | kg::cli::kImageOptions | kg::cli::kCheckDirs);
  RequirePositional(o, 0, "only options (--golden-dir DIR --actual-dir DIR)");
  if (o.goldenDir.empty() || o.actualDir.empty()) throw UsageError("check needs --golden-dir and --actual-dir");
  kg::CheckOptions options;
  options.trajectory = o.trajectory;
  options.image = o.image;
  const kg::CheckResult r = kg::CheckAgainstGolden(o.goldenDir, o.actualDir, options);
  std::cout << r.report;
  return static_cast<int>(r.status);
}

int Hash(const std::vector<std::string> &args) {
  const Options o = kg::cli::ParseOptions(args, 0);
  RequirePositional(o, 1, "one trajectory file");
  const kg::Trajectory t = kg::ReadTrajectoryFile(o.positional[0]);
  const std::uint64_t hash = kg::HashTrajectory(t);
  std::cout << kg::FormatHash(hash) << "\n";
  if (hash != t.finalHash) {
    std::cerr << o.positional[0] << ": the recorded final-hash " << kg::FormatHash(t.finalHash)
              << " does not match the values (edited by hand?)\n";
    return kMismatch;
  }
  return kMatch;
}

int Defaults(const std::vector<std::string> &args) {
  RequirePositional(kg::cli::ParseOptions(args, 0), 0, "no arguments");
  for (kg::Precision p : {kg::Precision::Single, kg::Precision::Double}) {
    const kg::TrajectoryTolerances t = kg::DefaultTrajectoryTolerances(p);
    for (kg::Quantity q : kg::kAllQuantities) {
      std::printf("trajectory %-6s %-6s abs %-7g rel %g\n", std::string(kg::PrecisionName(p)).c_str(),
                  std::string(kg::QuantityName(q)).c_str(), t[q].absolute, t[q].relative);
    }
  }
  std::printf("image channel-tol %d max-fraction %g\n", kg::kDefaultImageTolerances.channelTolerance,
              kg::kDefaultImageTolerances.maxDifferingFraction);
  return kMatch;
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  if (args.empty()) {
    Usage(std::cerr);
    return kError;
  }
  const std::string command = args.front();
  args.erase(args.begin());
  try {
    if (command == "compare-trajectory") return CompareTrajectory(args);
    if (command == "compare-image") return CompareImage(args);
    if (command == "check") return Check(args);
    if (command == "hash") return Hash(args);
    if (command == "defaults") return Defaults(args);
    if (command == "help" || command == "--help" || command == "-h") {
      Usage(std::cout);
      return kMatch;
    }
    throw UsageError("unknown command '" + command + "'");
  } catch (const UsageError &e) {
    std::cerr << "karma-golden: " << e.what() << "\n";
    Usage(std::cerr);
  } catch (const std::exception &e) {
    std::cerr << "karma-golden: " << e.what() << "\n";
  }
  return kError;
}
