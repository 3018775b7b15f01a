// c_api_test.cpp: runs the C translation unit c_api_check.c.
#include <gtest/gtest.h>

extern "C" int mcd_c_api_check(void);

TEST(McdCApi, CompilesAndRunsFromC) { EXPECT_EQ(mcd_c_api_check(), 1); }

extern "C" int mcd_c_api_order(void);

TEST(McdCApi, MdtHeadersFirstAlsoCompile) { EXPECT_EQ(mcd_c_api_order(), 1); }
