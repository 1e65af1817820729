// Lesson 11 — progressive refinement: the shooting (Southwell) iteration (Eq. 11.27, 11.28).
// Interface: lessons/11-classics/radiosity.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

RadiositySolution startRadiosity(const ElementMesh& mesh) {
    // TODO(11) The solution before the first shot (Eq. 11.27; radiosity.h). Pitfall: both B and unshot start at E.
    (void)mesh;
    return PS_TODO("lesson 11: startRadiosity", RadiositySolution());
}

int chooseShooter(const ElementMesh& mesh, const RadiositySolution& s) {
    // TODO(11) The shooter of Eq. 11.28 (radiosity.h). Pitfall (README 6): the most unshot power, not radiosity.
    (void)mesh; (void)s;
    return PS_TODO("lesson 11: chooseShooter", -1);
}

void shoot(const ElementMesh& mesh, RadiositySolution& s, int i, const std::vector<float>& F) {
    // TODO(11) One shooting step from element i (Eq. 11.28; radiosity.h). Pitfalls (README 6): reciprocity's A_i /
    //          A_j; unshot_i is taken before the loop, or i shoots its power again.
    (void)mesh; (void)s; (void)i; (void)F;
    (void)PS_TODO("lesson 11: shoot", 0);
}

}  // namespace ps
