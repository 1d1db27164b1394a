// main of cutaway_gl_tests: one EGL context for every test (gl_test_support.h).
#include <gtest/gtest.h>

#include "gl_test_support.h"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new cutaway::test::GlEnvironment);
    return RUN_ALL_TESTS();
}
