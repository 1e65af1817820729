// Lesson 11 — plumbing: what the filtered forms of pt, lt, bpt and pm share (path_filter.h), and
// the algorithm option `--paths` that reaches them (framework/integrator.h).
#include "11-classics/path_filter.h"
#include "errors.h"

namespace ps {

namespace {

const char* const kPathsHelp =
    R"(  --paths EXPR       render only the paths Heckbert's expression EXPR matches (lesson 11): the
                     types of a path's vertices from the light to the eye: L light, D diffuse,
                     G glossy (Phong), S specular (mirror, glass), E eye; . any type, [DS] one
                     of, [^S] any but, ( ), | or, postfix * + ? (zero or more, one or more, zero
                     or one). Every path is L.*E = L(D|G|S)*E. The algorithms marked * below
                     honour it, the others refuse it. Examples (quote them in the shell):
                       LE        lights seen directly        LDE      direct light on diffuse
                       LD+E      diffuse interreflection      LS+DE    caustics
                       L.*S.*E   paths with a specular vertex L[DG]S*E what Whitted carries
)";

std::vector<std::string> filteredAlgorithms() {
    std::vector<std::string> names;
    for (const auto& e : Registry<PathFilteredForm>::sorted()) names.push_back(e.name);
    return names;
}

void checkExpression(const std::string& text) {
    try {
        PathExpression e(text);
    } catch (const PathExpressionError& e) { throw OptionError("option --paths: " + e.pointed("  ")); }
}

std::unique_ptr<Integrator> makeFiltered(const std::string& algo, const std::string& text) {
    const PathFilteredForm* form = Registry<PathFilteredForm>::find(algo);
    if (!form) return nullptr;
    checkExpression(text);
    return (*form)(PathExpression(text));
}

[[maybe_unused]] const bool registered = Registry<AlgorithmOption>::add(
    "paths", AlgorithmOption{"EXPR", kPathsHelp, filteredAlgorithms, checkExpression, makeFiltered});

}  // namespace

std::string carriedPaths(const std::string& algo, const Scene& scene, const AlgorithmOptions& options) {
    for (const auto& [name, value] : options)
        if (name == "paths") return value;
    const CarriedPaths* carried = Registry<CarriedPaths>::find(algo);
    return carried ? (*carried)(scene) : kAllPaths;
}

VertexType surfaceType(const Scene& scene, const SurfacePoint& sp) {
    return scatteringType(scene.materials[size_t(sp.material)]);
}

TypeSet sceneTypes(const Scene& scene) {
    TypeSet types = 0;
    for (const Material& m : scene.materials) types = TypeSet(types | typeBit(scatteringType(m)));
    return TypeSet(types & kInteriorTypes);
}

bool sceneCanMatch(const PathExpression& paths, const Scene& scene) {
    return paths.matchesSome(sceneTypes(scene), scene.settings.maxDepth);
}

std::vector<std::string> pathFilterLeftOut(const PathExpression& paths, const Scene& scene, const std::string& walk) {
    if (!scene.settings.prune) return {};
    const std::string expr = "'" + paths.text() + "'";
    if (!sceneCanMatch(paths, scene)) {
        std::string types;
        for (VertexType t : {VertexType::D, VertexType::G, VertexType::S})
            if (sceneTypes(scene) & typeBit(t)) types += std::string(types.empty() ? "" : ", ") + typeLetter(t);
        return {"every path: none of at most " + std::to_string(scene.settings.maxDepth) +
                " bounces over this scene's vertex types (" + (types.empty() ? std::string("none") : types) +
                ") matches " + expr + " (lesson 11, Eq. 11.6): the image is black"};
    }
    return {"paths that do not match " + expr + " (--paths: Heckbert's expression, lesson 11, Eq. 11.5); " + walk};
}

bool bptPathMatches(const PathExpression& paths, const Scene& scene, const Subpath& light, const Subpath& camera, int s,
                    int t) {
    // The light prefix, forward from L: y_0 .. y_{s-1}, or for s = 0 the emitter z_{t-1} alone. A
    // technique t = 0 (a light subpath that reaches a camera with a lens) ends on the eye: y_{s-1} is E.
    PathExpression::State q = paths.step(paths.start(), VertexType::L);
    const int lightEnd = t == 0 ? s - 1 : s;
    for (int i = 1; i < lightEnd; ++i) q = paths.step(q, surfaceType(scene, light[size_t(i)].sp));
    if (t == 0) return paths.accepting(paths.step(q, VertexType::E));
    if (!paths.live(q)) return false;
    // The camera prefix, backward from E: z_1 .. z_{t-1} (z_{t-2} when z_{t-1} is the light).
    PathExpression::State b = paths.backStep(paths.backStart(), VertexType::E);
    const int end = s == 0 ? t - 1 : t;
    for (int j = 1; j < end; ++j) {
        const PathVertex& z = camera[size_t(j)];
        if (!z.onSurface() || z.sp.material < 0) return false;  // the background: nothing joins it
        b = paths.backStep(b, surfaceType(scene, z.sp));
    }
    return paths.joins(q, b);
}

}  // namespace ps
