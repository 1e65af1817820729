// main() of every test program: doctest's, after choosing passive waiting for the render
// loop's threads (framework/passive_wait.h: tests run two at a time and must not spin each other out).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include "passive_wait.h"

int main(int argc, char** argv) {
    ps::preferPassiveWaiting(argv);
    return doctest::Context(argc, argv).run();
}
