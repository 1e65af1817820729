// Lesson 11 — the ambient term of progressive radiosity's display (Eq. 11.29; Cohen, Chen,
// Wallace and Greenberg 1988). Interface: lessons/11-classics/radiosity.h. Equation numbers refer
// to lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

Color ambientRadiosity(const ElementMesh& mesh, const RadiositySolution& s) {
    //! TODO(11) The ambient radiosity of Eq. 11.29 per channel (radiosity.h), sums in double; a channel whose rho_avg
    //!          >= 1 gets 0 (no convergent series). Pitfall: the unshot power is reflected again and again, not once.
    //! STUB (void)mesh; (void)s;
    //! STUB return PS_TODO("lesson 11: ambientRadiosity", Color(0.0f));
    //! BEGIN
    DColor rhoA(0.0), unshotA(0.0);
    double area = 0.0;
    for (int j = 0; j < mesh.size(); ++j) {
        const double A = mesh[j].area;
        rhoA += DColor(mesh[j].rho) * A;
        unshotA += DColor(s.unshot[size_t(j)]) * A;
        area += A;
    }
    if (!(area > 0.0)) return Color(0.0f);
    DColor ambient(0.0);
    for (int c = 0; c < 3; ++c) {
        const double rhoAvg = rhoA[c] / area;
        if (rhoAvg < 1.0) ambient[c] = unshotA[c] / area / (1.0 - rhoAvg);
    }
    return Color(ambient);
    //! END
}

}  // namespace ps
