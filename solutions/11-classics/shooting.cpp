// Lesson 11 — progressive refinement: the shooting (Southwell) iteration (Eq. 11.27, 11.28).
// Interface: lessons/11-classics/radiosity.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

RadiositySolution startRadiosity(const ElementMesh& mesh) {
    //! TODO(11) Eq. 11.27: B_i = E_i and unshot_i = E_i for every element i (mesh[i].E); shots = 0.
    //!          Pitfall: B without E leaves the lamps black, unshot without E shoots nothing.
    //! STUB (void)mesh;
    //! STUB return PS_TODO("lesson 11: startRadiosity", RadiositySolution());
    //! BEGIN
    RadiositySolution s;
    for (const Element& e : mesh.elements()) {
        s.B.push_back(e.E);
        s.unshot.push_back(e.E);
    }
    return s;
    //! END
}

int chooseShooter(const ElementMesh& mesh, const RadiositySolution& s) {
    //! TODO(11) Eq. 11.28: the index i with the largest unshot power (unshot_i.r + unshot_i.g +
    //!          unshot_i.b) * mesh[i].area, the first of equal ones; -1 if every one is 0.
    //!          Pitfall: the largest unshot radiosity (without the area) shoots small bright
    //!          elements first, and the iteration converges more slowly.
    //! STUB (void)mesh; (void)s;
    //! STUB return PS_TODO("lesson 11: chooseShooter", -1);
    //! BEGIN
    int best = -1;
    double most = 0.0;
    for (int i = 0; i < mesh.size(); ++i) {
        const Color& u = s.unshot[size_t(i)];
        const double power = (double(u.r) + double(u.g) + double(u.b)) * double(mesh[i].area);
        if (power > most) {
            most = power;
            best = i;
        }
    }
    return best;
    //! END
}

void shoot(const ElementMesh& mesh, RadiositySolution& s, int i, const std::vector<float>& F) {
    //! TODO(11) Eq. 11.28: dB = s.unshot[i]; s.unshot[i] = 0 (before the loop); then for every
    //!          element j: add = rho_j * dB * F[j] * A_i / A_j, added to s.B[j] and s.unshot[j];
    //!          finally ++s.shots.
    //!          Pitfall: A_i / A_j, not A_j / A_i (reciprocity, Eq. 11.22: F_ji = F_ij A_i / A_j);
    //!          rho once; and unshot_i must be reset, or element i shoots the same power again.
    //! STUB (void)mesh; (void)s; (void)i; (void)F;
    //! STUB (void)PS_TODO("lesson 11: shoot", 0);
    //! BEGIN
    const Color dB = s.unshot[size_t(i)];
    s.unshot[size_t(i)] = Color(0.0f);
    const float areaI = mesh[i].area;
    for (int j = 0; j < mesh.size(); ++j) {
        if (F[size_t(j)] == 0.0f) continue;
        const Color add = mesh[j].rho * dB * (F[size_t(j)] * areaI / mesh[j].area);
        s.B[size_t(j)] += add;
        s.unshot[size_t(j)] += add;
    }
    ++s.shots;
    //! END
}

}  // namespace ps
