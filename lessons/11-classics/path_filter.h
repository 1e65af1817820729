// Lesson 11 — plumbing (read it, nothing to write here): Heckbert's path expressions
// (framework/path_expression.h) applied by the algorithms that build paths. `pathspace render
// --algo A --paths EXPR` makes A's filtered form, registered here for A = pt, lt, bpt,
// bpt-balance, bpt-full and pm; every other algorithm refuses an expression
// (framework/integrator.h). A filtered form adds a path's contribution only if its string, typed
// by your vertex classification (heckbert.h), matches (Eq. 11.5), and stops a walk where no
// path through it can match any more (a dead state, Eq. 11.6), which leaves the image unchanged:
//
//   pt   (filtered_pt.cpp)   lesson 3's camera walk reads the backward automaton from E; lesson 3's
//                            addMISContribution is called twice per vertex, once for the emission
//                            the walk found (x_0 = this vertex) and once for the light sample (x_0
//                            a new vertex after this one), each added only if its path matches;
//   lt   (filtered_lt.cpp)   lesson 7's light subpath read forward from L, each vertex joined to
//                            the camera (lesson 7's connectCamera: lesson 5's estimate) if L ... E
//                            matches;
//   bpt  (filtered_bpt.cpp)  every technique (s, t) tests its path before it connects: the light
//                            prefix read forward, the camera prefix backward, joined (Eq. 11.5);
//                            the per-technique images (`pathspace pyramid --paths`) too;
//   pm   (filtered_pm.cpp)   every photon keeps the forward state of its light path (the string
//                            from L to its own vertex); the camera side joins each density
//                            estimate's photons with its own backward state.
//
// Without --paths nothing here runs: every algorithm renders exactly what it did before.
#pragma once
#include <functional>
#include <string>
#include <vector>
#include "07-bidirectional/bpt.h"
#include "11-classics/heckbert.h"
#include "path_expression.h"

namespace ps {

// The type of a surface point a walk hits, as a vertex in the middle of a path (Eq. 11.1):
// scatteringType of its material.
VertexType surfaceType(const Scene& scene, const SurfacePoint& sp);

// The interior vertex types the scene's materials have (D, G, S).
TypeSet sceneTypes(const Scene& scene);

// Whether some path of at most scene.settings.maxDepth bounces over the scene's vertex types can
// match (false: the whole image is black, and a filtered form renders nothing when pruning).
bool sceneCanMatch(const PathExpression& paths, const Scene& scene);

// The lines a filtered form prints through Integrator::leftOut (empty with --no-prune): what the
// expression leaves out on this scene. `walk` says how this algorithm leaves out what cannot match.
std::vector<std::string> pathFilterLeftOut(const PathExpression& paths, const Scene& scene, const std::string& walk);

// Whether bpt's technique (s, t) joins the light subpath's first s vertices and the camera
// subpath's first t into a path that matches (Eq. 11.5): y_0 (or, for s = 0, z_{t-1}) is L, the
// camera z_0 (or, for t = 0, y_{s-1} on a lens) is E, the vertices between are typed by
// surfaceType. Lesson 7's BptOptions::pathTest. For t = 0 (lens_technique.cpp) camera is not read:
// the path is y_0 .. y_{s-2} and the lens point, whose type is E.
bool bptPathMatches(const PathExpression& paths, const Scene& scene, const Subpath& light, const Subpath& camera, int s,
                    int t);

}  // namespace ps
