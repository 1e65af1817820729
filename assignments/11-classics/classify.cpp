// Lesson 11 — Heckbert's classification of a path's vertices. Interface:
// lessons/11-classics/heckbert.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/heckbert.h"
#include "todo.h"

namespace ps {

VertexType scatteringType(const Material& m) {
    // TODO(11) Eq. 11.1: S for a delta material (m.isDelta(): mirror, glass); D for a Lambertian
    //          one: BSDFKind::Diffuse, or BSDFKind::Phong with exponent 0 (its BRDF is albedo / pi);
    //          G for the other Phong materials.
    (void)m;
    return PS_TODO("lesson 11: scatteringType", VertexType::E);
}

VertexType vertexType(const Scene& scene, const Path& x, size_t i) {
    // TODO(11) Eq. 11.1: L for i = 0 and E for i = x.size() - 1 (by their place in the path, not
    //          by a material: a point light, the background and the pinhole have none, and an
    //          area light's surface has one); between them scatteringType of
    //          scene.materials[x[i].sp.material].
    //          Pitfall: a vertex on an emitting surface in the middle of a path (x[i].onLight)
    //          scatters light there; only x[0] is the path's light.
    (void)scene; (void)x; (void)i;
    return PS_TODO("lesson 11: vertexType", VertexType::E);
}

std::string pathString(const Scene& scene, const Path& x) {
    // TODO(11) Eq. 11.1: one letter per vertex (typeLetter(vertexType(scene, x, i))), from x[0]
    //          (the light) to x[k] (the eye): Heckbert's expressions read paths that way.
    (void)scene; (void)x;
    return PS_TODO("lesson 11: pathString", std::string());
}

}  // namespace ps
