// Lesson 11 — progressive refinement: the shooting (Southwell) iteration (Eq. 11.27, 11.28).
// Interface: lessons/11-classics/radiosity.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

RadiositySolution startRadiosity(const ElementMesh& mesh) {
    //! TODO(11) The solution before the first shot (Eq. 11.27; radiosity.h). Pitfall: both B and unshot start at E.
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
    //! TODO(11) The shooter of Eq. 11.28 (radiosity.h). Pitfall (README 6): the most unshot power, not radiosity.
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
    //! TODO(11) One shooting step from element i (Eq. 11.28; radiosity.h). Pitfalls (README 6): reciprocity's A_i /
    //!          A_j; unshot_i is taken before the loop, or i shoots its power again.
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
