// query_test_support.h: a framework with models placed by the test.
#pragma once

#include "support/warning_capture.h"

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
  McdModelID place(McdGeometryID g, MeReal x, MeReal y, MeReal z, const MeMatrix3 *R = nullptr) {
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

using Warnings = karma_test::WarningCapture;  // warnings recorded while alive

}  // namespace mcd_query_test
