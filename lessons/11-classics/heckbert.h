// Lesson 11's path classification (Heckbert 1990): the type of every vertex of a path in the
// alphabet of Heckbert's path expressions (framework/path_expression.h, Eq. 11.1) and a path's
// string, read from the light to the eye. `pathspace render --paths EXPR` renders only the paths
// whose string the expression matches, in pt, lt, bpt and pm (plumbing: path_filter.h), with
// these types. Implemented in solutions/11-classics/classify.cpp (reference) or
// assignments/11-classics/classify.cpp (yours); lessons/11-classics/README.md, Eq. 11.1-11.9.
#pragma once
#include <string>
#include "06-path-space/paths.h"
#include "11-classics/path_expression.h"

namespace ps {

// The type of a vertex that scatters light, from its material (Eq. 11.1): S for a delta BSDF
// (mirror, glass: Material::isDelta), D for a Lambertian one (BSDFKind::Diffuse, and a Phong
// material of exponent 0, whose BRDF is albedo / pi: framework/bsdf.cpp), G for every other
// non-delta BSDF (Phong).
VertexType scatteringType(const Material& m);

// The type of vertex i of lesson 6's path x (x[0] on a light, x[k] the camera, k = x.size() - 1):
// L for x[0], whatever the light (an area light, a point light, the background) and whatever the
// material of the surface it lies on; E for x[k]; every vertex between them scatters light:
// scatteringType of its material (scene.materials[x[i].sp.material]), also where that surface
// emits (x[i].onLight: a lamp the path passes over is not its light).
VertexType vertexType(const Scene& scene, const Path& x, size_t i);

// x's string from the light to the eye, one letter per vertex (typeLetter), e.g. "LDSE".
std::string pathString(const Scene& scene, const Path& x);

}  // namespace ps
