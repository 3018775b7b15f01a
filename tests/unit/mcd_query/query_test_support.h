// query_test_support.h: a framework with models placed by the test.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "Mcd.h"

namespace mcd_query_test {

// A framework with every built-in type and interaction; models made through
// it own their TM (kept alive here) and are updated on placement.
class Scene {
 public:
  Scene() : fw_(McdInit(0, 64, 64, 1)) {
    McdPrimitivesRegisterTypes(fw_);
    McdPrimitivesRegisterInteractions(fw_);
  }
  ~Scene() {
    McdFrameworkDestroyAllModelsAndGeometries(fw_);
    McdTerm(fw_);
  }
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;

  McdFrameworkID fw() const { return fw_; }

  // A model of g at position p (rotation R rows, identity when null).
  McdModelID place(McdGeometryID g, MeReal x, MeReal y, MeReal z,
                   const MeMatrix3 *R = nullptr) {
    tms_.push_back(std::make_unique<Tm>());
    MeMatrix4Ptr tm = tms_.back()->m;
    MeMatrix4TMMakeIdentity(tm);
    if (R) MeMatrix4TMSetRotation(tm, *R);
    MeMatrix4TMSetPosition(tm, x, y, z);
    McdModelID m = McdModelCreate(g);
    McdModelSetTransformPtr(m, tm);
    McdModelUpdate(m);
    return m;
  }

 private:
  struct Tm {
    MeMatrix4 m;
  };
  McdFrameworkID fw_;
  std::vector<std::unique_ptr<Tm>> tms_;
};

// Records warnings while alive.
class Warnings {
 public:
  Warnings() : previous_(MeSetWarningHandler(&Warnings::handler)) { log().clear(); }
  ~Warnings() { MeSetWarningHandler(previous_); }
  Warnings(const Warnings &) = delete;
  Warnings &operator=(const Warnings &) = delete;
  static std::vector<std::string> &log() {
    static std::vector<std::string> messages;
    return messages;
  }
  size_t count() const { return log().size(); }
  std::string last() const { return log().empty() ? std::string() : log().back(); }

 private:
  static void MEAPI handler(int, const char *message) { log().emplace_back(message); }
  MeMessageHandler previous_;
};

}  // namespace mcd_query_test
