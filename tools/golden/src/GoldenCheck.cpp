#include <karma/golden/GoldenCheck.h>

#include <karma/golden/Error.h>
#include <karma/golden/GoldenKey.h>
#include <karma/golden/ImageCompare.h>
#include <karma/golden/TrajectoryCompare.h>
#include <karma/golden/TrajectoryReader.h>

#include <algorithm>
#include <sstream>
#include <vector>

namespace karma::golden {

namespace fs = std::filesystem;

namespace {

bool EndsWith(const std::string &s, const std::string &suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/* Golden frames: *.png except diff images, sorted by name for a stable report. */
std::vector<std::string> GoldenImages(const fs::path &dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry &entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && EndsWith(name, ".png") && !EndsWith(name, ".diff.png")) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

CheckResult CheckAgainstGolden(const fs::path &goldenDir, const fs::path &actualDir, const CheckOptions &options) {
  CheckResult result;
  std::ostringstream o;
  bool error = false;
  auto fail = [&](const std::string &what) {
    ++result.itemsFailed;
    o << "FAIL: " << what << "\n";
  };

  std::error_code ec;
  if (!fs::is_directory(goldenDir, ec)) {
    result.report = "error: golden directory " + goldenDir.string() + " does not exist\n";
    return result;
  }
  if (!fs::is_directory(actualDir, ec)) {
    result.report = "error: actual output directory " + actualDir.string() + " does not exist\n";
    return result;
  }

  try {
    const fs::path goldenTrajectory = goldenDir / kTrajectoryFileName;
    if (fs::exists(goldenTrajectory)) {
      ++result.itemsChecked;
      const fs::path actualTrajectory = actualDir / kTrajectoryFileName;
      if (!fs::exists(actualTrajectory)) {
        fail("the run wrote no " + actualTrajectory.string());
      } else {
        const Trajectory expected = ReadTrajectoryFile(goldenTrajectory);
        const Trajectory actual = ReadTrajectoryFile(actualTrajectory);
        const TrajectoryTolerances tolerances =
            options.trajectory.ApplyTo(DefaultTrajectoryTolerances(expected.header.precision));
        const TrajectoryComparison c = CompareTrajectories(expected, actual, tolerances);
        o << ReportText(c, goldenTrajectory.string(), actualTrajectory.string()) << "\n";
        if (!c.passed) ++result.itemsFailed;
      }
    }

    for (const std::string &name : GoldenImages(goldenDir)) {
      ++result.itemsChecked;
      const fs::path actualImage = actualDir / name;
      if (!fs::exists(actualImage)) {
        fail("the run wrote no " + actualImage.string() + " (the golden has " + name + ")");
        continue;
      }
      const ImageComparison c = CompareImageFiles(goldenDir / name, actualImage, options.image);
      o << ReportText(c, (goldenDir / name).string(), actualImage.string()) << "\n";
      if (!c.passed) ++result.itemsFailed;
    }
  } catch (const GoldenError &e) {
    o << "error: " << e.what() << "\n";
    error = true;
  } catch (const fs::filesystem_error &e) {
    o << "error: " << e.what() << "\n";
    error = true;
  }

  if (!error && result.itemsChecked == 0) {
    o << "error: golden directory " << goldenDir.string() << " holds neither " << kTrajectoryFileName
      << " nor any PNG frame\n";
    error = true;
  }
  if (error)
    result.status = CheckStatus::Error;
  else
    result.status = result.itemsFailed ? CheckStatus::Mismatch : CheckStatus::Match;
  o << "check: " << result.itemsChecked << " item(s) checked, " << result.itemsFailed << " failed: "
    << (result.status == CheckStatus::Match      ? "MATCH"
        : result.status == CheckStatus::Mismatch ? "MISMATCH"
                                                 : "ERROR")
    << "\n";
  result.report = o.str();
  return result;
}

}  // namespace karma::golden
