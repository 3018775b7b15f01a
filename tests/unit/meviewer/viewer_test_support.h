// viewer_test_support.h: helpers for the MeViewer tests: capturing Karma's
// messages, making render contexts from a command-line string, and scratch
// directories.
#ifndef KARMA_TESTS_MEVIEWER_SUPPORT_H
#define KARMA_TESTS_MEVIEWER_SUPPORT_H

#include "MeViewer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace viewer_test {

// While alive, warnings and infos are recorded instead of printed.
class Messages {
 public:
  Messages() {
    Warnings().clear(), Infos().clear();
    prevWarning_ = MeSetWarningHandler(&OnWarning);
    prevInfo_ = MeSetInfoHandler(&OnInfo);
  }
  ~Messages() {
    MeSetWarningHandler(prevWarning_);
    MeSetInfoHandler(prevInfo_);
  }
  Messages(const Messages &) = delete;
  Messages &operator=(const Messages &) = delete;
  static std::vector<std::string> &Warnings() {
    static std::vector<std::string> w;
    return w;
  }
  static std::vector<std::string> &Infos() {
    static std::vector<std::string> i;
    return i;
  }
  // True if some warning contains `text`.
  static bool Warned(const std::string &text) {
    for (const std::string &w : Warnings())
      if (w.find(text) != std::string::npos) return true;
    return false;
  }
  static std::string All() {
    std::string s;
    for (const std::string &w : Warnings()) s += "[" + w + "] ";
    return s;
  }

 private:
  static void MEAPI OnWarning(int, const char *m) { Warnings().emplace_back(m); }
  static void MEAPI OnInfo(int, const char *m) { Infos().emplace_back(m); }
  MeMessageHandler prevWarning_, prevInfo_;
};

// A render context from a command line such as "prog -null".
inline RRender *MakeContext(const std::string &commandLine) {
  MeCommandLineOptions *o = MeCommandLineOptionsCreateFromString(commandLine.c_str());
  RRender *rc = RRenderContextCreate(o, nullptr, 1);
  MeCommandLineOptionsDestroy(o);
  return rc;
}

// A fresh directory under the working directory (ctest runs each build's
// tests in its own build tree), named after the test, so a death-test
// child, which runs the test body again, finds the same directory. Removed
// on destruction.
class TempDir {
 public:
  explicit TempDir(const std::string &tag) {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ =
        std::filesystem::current_path() / "meviewer-scratch" / (tag + "-" + (info ? std::string(info->name()) : "x"));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  const std::filesystem::path &path() const { return path_; }
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace viewer_test

#endif
