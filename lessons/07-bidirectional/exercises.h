// Lesson 7's pen-and-paper exercise (lessons/07-bidirectional/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/07-bidirectional/exercises.cpp (reference) or assignments/07-bidirectional/exercises.cpp (yours).
#pragma once

namespace ps {

// The MIS weight w_{s,3-s} of technique s (0, 1 or 2) for a path of length k = 2 seen by a
// pinhole, given the area-measure pdfs pdf[0], pdf[1], pdf[2] with which the three techniques
// s = 0, 1, 2 sample it (>= 0, not all 0), with the heuristic's exponent b (1 balance, 2 power)
// (Eq. 7.E1).
double techniqueWeightK2(const double pdf[3], int s, double b);

}  // namespace ps
