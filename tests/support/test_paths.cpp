// Where the graded tests find the source tree and the build tree. The two paths are compiled
// into this one file only (tests/support/CMakeLists.txt), not into every test source, so that a
// second tree with the same sources (the handout that CI builds) compiles the tests to the same
// objects and ccache can reuse them.
#include "lesson_files.h"

namespace ps::testfiles {

const char* sourceDir() { return PATHSPACE_SOURCE_DIR; }
const char* binaryDir() { return PATHSPACE_BINARY_DIR; }

}  // namespace ps::testfiles
