// Lesson 5 — the start of a light path: emission sampling. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

LightPathStart startLightPath(const Scene& scene, float uLight, const Vec2& uPos, const Vec2& uDir) {
    // TODO(05) The first vertex y0 and the particle leaving it (Eq. 5.2), as lesson 4's
    //          fluxParticle started its particles (Eq. 4.13):
    //          1. l = scene.selectLight(uLight, P); invalid (return the default) if l < 0.
    //          2. e = sampleEmission(scene, l, uPos, uDir); invalid if e.pdfA or e.pdfW is 0.
    //          3. light = l, y0 = emissionPoint(scene, l, e), pdfA = P * e.pdfA,
    //             ray = scene.spawnRay(y0, e.dir),
    //             beta = e.Le |cos theta| / (P pdfA pdfW) (cos between e.n and e.dir for an
    //             area light; none for a point light or the background), valid = true.
    (void)scene; (void)uLight; (void)uPos; (void)uDir;
    return PS_TODO("lesson 05: startLightPath", LightPathStart());
}

}  // namespace ps
