// Lesson 11 — the ambient term of progressive radiosity's display (Eq. 11.29; Cohen, Chen,
// Wallace and Greenberg 1988). Interface: lessons/11-classics/radiosity.h. Equation numbers refer
// to lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

Color ambientRadiosity(const ElementMesh& mesh, const RadiositySolution& s) {
    // TODO(11) Eq. 11.29, per channel, with sums over every element j (in double):
    //          rho_avg = sum rho_j A_j / sum A_j, R = 1 / (1 - rho_avg),
    //          ambient = R sum unshot_j A_j / sum A_j. Black without elements; a channel with
    //          rho_avg >= 1 gets 0 (the series 1 + rho_avg + rho_avg^2 + ... does not converge).
    //          Pitfall: R is the geometric series 1 + rho_avg + rho_avg^2 + ...: the unshot power
    //          is reflected again and again, not once.
    (void)mesh; (void)s;
    return PS_TODO("lesson 11: ambientRadiosity", Color(0.0f));
}

}  // namespace ps
