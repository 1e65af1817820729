// Lesson 11 — plumbing (read it, nothing to write here): Heckbert's path expressions
// (path_expression.h) applied by the algorithms that build paths. `--paths` is an algorithm option
// (framework/integrator.h) that this lesson registers: `pathspace render --algo A --paths EXPR`
// makes A's filtered form, registered (Registry<PathFilteredForm>) for A = pt, lt, bpt,
// bpt-balance, bpt-full and pm; every other algorithm refuses an expression. A filtered form adds a path's contribution only if its string, typed
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
//   bpt  (filtered_bpt.cpp)  lesson 7's technique filter: every technique (s, t) tests its path
//                            before it connects, the light prefix read forward, the camera prefix
//                            backward, joined (Eq. 11.5); the per-technique images (`pathspace
//                            pyramid --paths`) too;
//   pm   (filtered_pm.cpp)   lesson 8's photon visitor keeps each photon's forward state (the
//                            string from L to its own vertex) as its population; lesson 8's
//                            gather visitor joins each density estimate's populations with the
//                            camera side's backward state.
//
// Without --paths nothing here runs: every algorithm renders exactly what it did before.
#pragma once
#include <functional>
#include <string>
#include <vector>
#include "07-bidirectional/bpt.h"
#include "11-classics/heckbert.h"
#include "11-classics/path_expression.h"
#include "integrator.h"

namespace ps {

// An algorithm's filtered form (Registry<PathFilteredForm>, keyed by the algorithm's name): its
// integrator restricted to the paths `paths` matches.
using PathFilteredForm = std::unique_ptr<Integrator> (*)(const PathExpression& paths);
// In a .cpp at namespace scope: Type has a constructor Type(const PathExpression&).
#define PS_REGISTER_PATH_FILTER(Type, name)                                                \
    static const bool psPathFilter_##Type = ::ps::Registry<::ps::PathFilteredForm>::add(   \
        name, [](const ::ps::PathExpression& paths) -> std::unique_ptr<::ps::Integrator> { \
            return std::make_unique<Type>(paths);                                          \
        })

// The paths an algorithm carries on a scene, as a Heckbert expression: every path (kAllPaths),
// unless the algorithm registered fewer (Registry<CarriedPaths>: a classic, whitted's
// "L[DG]S*E|LS*E" where every light is a point light) or "" where no expression over the alphabet
// says which. With the option `--paths EXPR` (options): EXPR. The extreme tests compare an
// integrator with pt filtered to its expression.
using CarriedPaths = std::string (*)(const Scene& scene);
constexpr const char* kAllPaths = "L.*E";
std::string carriedPaths(const std::string& algo, const Scene& scene, const AlgorithmOptions& options = {});

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
