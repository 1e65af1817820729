// Lesson 3, graded: a lamp seen only in a mirror. Light sampling cannot reach it through a delta
// BSDF, so every estimator must count the emission its BSDF sample finds after the mirror in
// full (next-event estimation: the `specular` flag, Eq. 3.6; MIS: weight 1, Eq. 3.7). Found
// missing by scripts/mutants.sh (the Cornell box and the furnaces have no specular surface).
#include <cmath>
#include "lesson03.h"
#include "seed.h"

using namespace lesson03;

namespace {

// A mirror floor (y = 0) and a square lamp of radiance 1 at y = 3 facing down, where the mirror
// reflects the camera ray aimed at the origin: (0, 6, 6) -> (0, 0, 0) -> the lamp at (0, 3, -3).
const char* kMirrorScene = R"(
camera eye 0 6 6  target 0 0 0  fov 40  resolution 1 1
material chrome mirror albedo 1 1 1
quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  material chrome
quad -2 3 -5  2 3 -5  2 3 -1  -2 3 -1  emission 1 1 1
)";

}  // namespace

TEST_CASE(
    "path tracing: a lamp seen only in a mirror has its full radiance with every estimator (Eq. 3.6, 3.7) [1 pt]") {
    const ps::Scene scene = ps::parseScene(kMirrorScene, "mirror floor (test_mirror.cpp)");
    const ps::Ray ray(scene.camera.position(), glm::normalize(Vec3(0.0f) - scene.camera.position()));
    for (const Estimator& e : estimators())
        for (int maxDepth : {1, 4}) {
            int wrong = 0;
            Color worst(0.0f);
            for (int i = 0; i < 16; ++i) {
                ps::Rng rng = ps::taskRng(ps::testseed::seed(371), 0, uint32_t(i));
                const Color L = e.Li(scene, ray, rng, maxDepth);
                if (!(std::abs(sum(L) - 3.0) <= 1e-4)) {
                    if (wrong == 0) worst = L;
                    ++wrong;
                }
            }
            CHECK_MESSAGE(wrong == 0, e.name << ", maxdepth " << maxDepth
                                             << ": the camera ray sees the lamp (radiance 1) "
                                             << "in the mirror floor: expected (1, 1, 1) in every sample, got "
                                             << str(worst) << " in " << wrong << " of 16 (ratio " << sum(worst) / 3.0
                                             << "; 0: the emission after a delta bounce was not counted, the specular "
                                             << "flag not set from s.delta?)");
        }
}
