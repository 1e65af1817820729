// Lesson 11 — Heckbert's classification of a path's vertices. Interface:
// lessons/11-classics/heckbert.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/heckbert.h"
#include "todo.h"

namespace ps {

VertexType scatteringType(const Material& m) {
    // TODO(11) The Heckbert type of a scattering material (Eq. 11.1; heckbert.h). Pitfall (README 6): Phong of
    //          exponent 0 is Lambertian.
    (void)m;
    return PS_TODO("lesson 11: scatteringType", VertexType::E);
}

VertexType vertexType(const Scene& scene, const Path& x, size_t i) {
    // TODO(11) The type of vertex i of x (Eq. 11.1; heckbert.h). Pitfalls (README 6): x_0 is L by its place, not its
    //          material; a lamp in the middle of a path scatters.
    (void)scene; (void)x; (void)i;
    return PS_TODO("lesson 11: vertexType", VertexType::E);
}

std::string pathString(const Scene& scene, const Path& x) {
    // TODO(11) x's string in Heckbert's notation (Eq. 11.1; heckbert.h). Pitfall: it reads from the light to the eye.
    (void)scene; (void)x;
    return PS_TODO("lesson 11: pathString", std::string());
}

}  // namespace ps
