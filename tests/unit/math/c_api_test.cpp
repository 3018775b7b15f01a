// c_api_test.cpp: runs the C11 caller in c_api_check.c.
#include <gtest/gtest.h>

extern "C" int karma_math_c_api_check(void);

TEST(MeMathCApi, CallsFromCWorkAndCompileCleanly) { EXPECT_EQ(karma_math_c_api_check(), 0); }
