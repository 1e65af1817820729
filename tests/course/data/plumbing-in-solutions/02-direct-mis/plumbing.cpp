// A solution file with no //! marker: nothing for the student to write. The skeleton tool must
// refuse it (its place is lessons/02-direct-mis/); see tests/course/CMakeLists.txt.
int plumbing() { return 0; }
