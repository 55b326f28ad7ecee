// The doctest runner of vibook. The test cases live beside the code (src/vibook/**/*_test.cpp).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
