// Stale handles: a destroyed body's handle is refused with a warning, and a
// collision model whose body was destroyed does not drive the body that
// takes the freed slot next.
#include "scene_support.h"
#include "support/warning_capture.h"

using namespace hard;
using karma_test::WarningCapture;

TEST(HardCases, DestroyedBodyHandleIsRefused) {
  World w;
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodyEnable(b);
  MdtBodyDestroy(b);
  ASSERT_EQ(MdtWorldGetBodyCount(w), 0u);
  WarningCapture warnings;
  MdtBodyEnable(b);  // stale
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(w), 0u);
  EXPECT_FALSE(MdtBodyIsEnabled(b));
  MdtBodyDestroy(b);  // destroyed twice
  EXPECT_EQ(MdtWorldGetBodyCount(w), 0u);
  EXPECT_GE(warnings.count(), 3u);
  EXPECT_TRUE(warnings.saw("destroyed"));
}

TEST(HardCases, ModelOfADestroyedBodyDoesNotDriveTheNextBody) {
  Universe U;
  McdModelID m = addBox(U, 1, 1, 1, 1, 0, 5, 0);
  MdtBodyID old = bodyOf(m);
  WarningCapture warnings;
  MdtBodyDestroy(old);  // the model still refers to it
  EXPECT_TRUE(warnings.saw("model"));
  EXPECT_EQ(McdModelGetBody(m), nullptr);
  // The next body takes the freed slot; it must stay the model-less body it is.
  MdtBodyID next = MdtBodyCreate(U.world());
  MdtBodySetPosition(next, 100, 0.5, 0);
  MdtBodyEnable(next);
  for (int i = 0; i < 60; ++i) U.step(1.0 / 60);
  EXPECT_EQ(McdModelGetBody(m), nullptr);
  double p[3];
  position(next, p);
  // Model-less, it falls freely through where the ground is: 1 s of fall.
  EXPECT_NEAR(p[1], 0.5 - kG / 2, kG / 60 + 1e-3);
}
