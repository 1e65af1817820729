// Lesson 11 — progressive refinement: the shooting (Southwell) iteration (Eq. 11.27, 11.28).
// Interface: lessons/11-classics/radiosity.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

RadiositySolution startRadiosity(const ElementMesh& mesh) {
    // TODO(11) Eq. 11.27: B_i = E_i and unshot_i = E_i for every element i (mesh[i].E); shots = 0.
    //          Pitfall: B without E leaves the lamps black, unshot without E shoots nothing.
    (void)mesh;
    return PS_TODO("lesson 11: startRadiosity", RadiositySolution());
}

int chooseShooter(const ElementMesh& mesh, const RadiositySolution& s) {
    // TODO(11) Eq. 11.28: the index i with the largest unshot power (unshot_i.r + unshot_i.g +
    //          unshot_i.b) * mesh[i].area, the first of equal ones; -1 if every one is 0.
    //          Pitfall: the largest unshot radiosity (without the area) shoots small bright
    //          elements first, and the iteration converges more slowly.
    (void)mesh; (void)s;
    return PS_TODO("lesson 11: chooseShooter", -1);
}

void shoot(const ElementMesh& mesh, RadiositySolution& s, int i, const std::vector<float>& F) {
    // TODO(11) Eq. 11.28: dB = s.unshot[i]; s.unshot[i] = 0 (before the loop); then for every
    //          element j: add = rho_j * dB * F[j] * A_i / A_j, added to s.B[j] and s.unshot[j];
    //          finally ++s.shots.
    //          Pitfall: A_i / A_j, not A_j / A_i (reciprocity, Eq. 11.22: F_ji = F_ij A_i / A_j);
    //          rho once; and unshot_i must be reset, or element i shoots the same power again.
    (void)mesh; (void)s; (void)i; (void)F;
    (void)PS_TODO("lesson 11: shoot", 0);
}

}  // namespace ps
