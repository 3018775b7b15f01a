// MeMessage: redirection of the four channels, formatting, debug filtering,
// the default handlers and MeFatalError's end of the program.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "MeMessage.h"
#include "runtime_test_support.h"

using karma_test::MessageCapture;

namespace {

void MEAPI otherHandler(int, const char *) {}

void MEAPI returningFatal(int, const char *text) { std::fprintf(stderr, "returning handler saw: %s\n", text); }

void MEAPI throwingFatal(int, const char *text) { throw std::runtime_error(text); }

TEST(MessageTest, InfoWarningAndDebugReachTheirHandlersFormatted) {
  MessageCapture capture;
  MeSetDebugLevel(5);
  MeInfo(1, "world has %d bodies", 12);
  MeWarning(2, "mass %.1f is not positive", -1.5);
  MeDebug(3, "step %s", "done");
  MeSetDebugLevel(0);

  ASSERT_EQ(capture.infos().size(), 1u);
  EXPECT_EQ(capture.infos()[0].level, 1);
  EXPECT_EQ(capture.infos()[0].text, "world has 12 bodies");
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_EQ(capture.warnings()[0].level, 2);
  EXPECT_EQ(capture.warnings()[0].text, "mass -1.5 is not positive");
  ASSERT_EQ(capture.debugs().size(), 1u);
  EXPECT_EQ(capture.debugs()[0].level, 3);
  EXPECT_EQ(capture.debugs()[0].text, "step done");
}

TEST(MessageTest, FatalErrorReachesItsHandlerFormatted) {
  MeMessageHandler previous = MeSetFatalErrorHandler(&throwingFatal);
  try {
    MeFatalError(4, "pool %s is broken (%d)", "bodies", 9);
    ADD_FAILURE() << "MeFatalError returned";
  } catch (const std::runtime_error &error) {
    EXPECT_STREQ(error.what(), "pool bodies is broken (9)");
  }
  EXPECT_THROW(MeFatalError(0, "again"), std::runtime_error);
  MeSetFatalErrorHandler(previous);
}

TEST(MessageTest, SettersReturnThePreviousHandlerAndNullRestoresTheDefault) {
  MessageCapture capture;  // installs its own, restores the old ones after
  MeMessageHandler capturing = MeSetWarningHandler(nullptr);
  ASSERT_NE(capturing, nullptr);
  MeMessageHandler defaultHandler = MeSetWarningHandler(capturing);
  ASSERT_NE(defaultHandler, nullptr);
  EXPECT_NE(defaultHandler, capturing);
  EXPECT_EQ(MeSetWarningHandler(capturing), capturing);

  testing::internal::CaptureStderr();
  MeSetWarningHandler(nullptr);
  MeWarning(0, "restored %d", 1);
  MeSetWarningHandler(capturing);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "Karma warning: restored 1\n");
  EXPECT_TRUE(capture.warnings().empty());

  for (auto set : {&MeSetInfoHandler, &MeSetFatalErrorHandler, &MeSetDebugHandler}) {
    MeMessageHandler before = set(&otherHandler);
    EXPECT_NE(before, nullptr);
    EXPECT_EQ(set(before), &otherHandler);
  }
}

TEST(MessageTest, DefaultHandlersPrintOneLinePerMessageWithPrefixes) {
  testing::internal::CaptureStderr();
  MeInfo(0, "hello %s", "there");
  MeWarning(0, "careful\n");
  MeSetDebugLevel(1);
  MeDebug(1, "trace");
  MeSetDebugLevel(0);
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "Karma info: hello there\nKarma warning: careful\nKarma debug: trace\n");
}

TEST(MessageTest, DebugOutputIsFilteredByTheDebugLevel) {
  MessageCapture capture;
  EXPECT_EQ(MeGetDebugLevel(), 0);
  MeDebug(0, "level zero counts as one");
  MeDebug(1, "off by default");
  EXPECT_TRUE(capture.debugs().empty());

  MeSetDebugLevel(2);
  EXPECT_EQ(MeGetDebugLevel(), 2);
  MeDebug(0, "a");
  MeDebug(1, "b");
  MeDebug(2, "c");
  MeDebug(3, "d");
  MeSetDebugLevel(0);
  ASSERT_EQ(capture.debugs().size(), 3u);
  EXPECT_EQ(capture.debugs()[0].text, "a");
  EXPECT_EQ(capture.debugs()[2].text, "c");
}

TEST(MessageTest, TrailingNewlinesAreRemoved) {
  MessageCapture capture;
  MeWarning(0, "one line\n");
  MeWarning(0, "two\r\n\n");
  MeWarning(0, "%s", "inner\nkept");
  ASSERT_EQ(capture.warnings().size(), 3u);
  EXPECT_EQ(capture.warnings()[0].text, "one line");
  EXPECT_EQ(capture.warnings()[1].text, "two");
  EXPECT_EQ(capture.warnings()[2].text, "inner\nkept");
}

TEST(MessageTest, LongMessagesAreCutNotOverflowed) {
  MessageCapture capture;
  const std::string longText(5000, 'x');
  MeWarning(0, "%s", longText.c_str());
  ASSERT_EQ(capture.warnings().size(), 1u);
  const std::string &text = capture.warnings()[0].text;
  EXPECT_EQ(text.size(), std::size_t(ME_MESSAGE_MAX_LENGTH - 1));
  EXPECT_EQ(text.substr(text.size() - 3), "...");
  EXPECT_EQ(text.substr(0, 10), std::string(10, 'x'));
}

TEST(MessageTest, ArgumentWarningNamesTheFunction) {
  MessageCapture capture;
  MeArgumentWarning("MdtBodySetMass", "mass must be positive, got %g", -2.0);
  MeArgumentWarning(nullptr, "no name");
  ASSERT_EQ(capture.warnings().size(), 2u);
  EXPECT_EQ(capture.warnings()[0].text, "MdtBodySetMass: mass must be positive, got -2");
  EXPECT_EQ(capture.warnings()[0].level, 0);
  EXPECT_EQ(capture.warnings()[1].text, "(unknown function): no name");
}

TEST(MessageDeathTest, FatalErrorWithTheDefaultHandlerAborts) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(MeFatalError(0, "cannot continue: %d", 42), "Karma fatal error: cannot continue: 42");
}

TEST(MessageDeathTest, FatalErrorAbortsWhenTheHandlerReturns) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        MeSetFatalErrorHandler(&returningFatal);
        MeFatalError(0, "oops %s", "here");
      },
      "returning handler saw: oops here");
}

}  // namespace
