// diagnostics_test.cpp: MeDiagnostics.h, the list of diagnostic sources:
// registration order, no duplicates, removal, reading by index, bad input.
#include <gtest/gtest.h>

#include "MeDiagnostics.h"
#include "runtime_test_support.h"

namespace {

// A source whose figures name it: jointError = its tag.
struct Tagged {
  MeReal tag;
};

void MEAPI ReadTagged(void *owner, MeDiagnosticFigures *f) {
  f->jointError = static_cast<Tagged *>(owner)->tag;
  f->energyDrift = -static_cast<Tagged *>(owner)->tag;
}

TEST(MeDiagnostics, SourcesAreListedOnceInRegistrationOrderUntilRemoved) {
  const int before = MeDiagnosticSourceCount();
  Tagged a{1}, b{2};
  MeDiagnosticSourceRegister(&a, ReadTagged);
  MeDiagnosticSourceRegister(&b, ReadTagged);
  MeDiagnosticSourceRegister(&a, ReadTagged);  // already listed
  ASSERT_EQ(MeDiagnosticSourceCount(), before + 2);
  MeDiagnosticFigures f;
  ASSERT_TRUE(MeDiagnosticSourceRead(before, &f));
  EXPECT_EQ(f.jointError, 1);
  EXPECT_EQ(f.energyDrift, -1);
  EXPECT_EQ(f.penetration, 0);  // zeroed before the reader runs
  ASSERT_TRUE(MeDiagnosticSourceRead(before + 1, &f));
  EXPECT_EQ(f.jointError, 2);
  MeDiagnosticSourceUnregister(&a);
  ASSERT_EQ(MeDiagnosticSourceCount(), before + 1);
  ASSERT_TRUE(MeDiagnosticSourceRead(before, &f));
  EXPECT_EQ(f.jointError, 2);
  MeDiagnosticSourceUnregister(&b);
  MeDiagnosticSourceUnregister(&b);  // not listed: ignored
  EXPECT_EQ(MeDiagnosticSourceCount(), before);
}

TEST(MeDiagnostics, BadInputWarnsOrReadsNothing) {
  karma_test::MessageCapture capture;
  const int before = MeDiagnosticSourceCount();
  Tagged a{1};
  MeDiagnosticSourceRegister(nullptr, ReadTagged);
  MeDiagnosticSourceRegister(&a, nullptr);
  EXPECT_EQ(MeDiagnosticSourceCount(), before);
  EXPECT_EQ(capture.warnings().size(), 2u);
  MeDiagnosticFigures f;
  f.jointError = 5;
  EXPECT_FALSE(MeDiagnosticSourceRead(before, &f));
  EXPECT_EQ(f.jointError, 0);
  EXPECT_FALSE(MeDiagnosticSourceRead(-1, &f));
  EXPECT_FALSE(MeDiagnosticSourceRead(0, nullptr));
  EXPECT_EQ(capture.warnings().size(), 3u);
}

}  // namespace
