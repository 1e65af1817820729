// Hostile: the reference solution, included by a path relative to this file (the repository's
// solutions/ is six folders up). Built in place, this scored full marks; the grader builds a
// copy in a sandbox that holds no solution source, so it must not compile.
#include "../../../../../../solutions/00-rays/rays.cpp"
