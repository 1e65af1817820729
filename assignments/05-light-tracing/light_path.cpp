// Lesson 5 — one light path, connected to the camera at every vertex. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

void traceLightPath(const Scene& scene, Rng& rng, const WalkOptions& opt, const SplatTarget& out) {
    // The camera point every connection of this path goes to: the pinhole camera.position()
    // (no number drawn), or a point of the camera's model.
    const Vec3 z = scene.camera.samplePoint(rng);
    lightWalk(scene, rng, opt, [&](const WalkVertex& v, const LightPathStart& start) {
        // TODO(05) What vertex v adds to the image (Eq. 5.3, 5.4), through out.add; return true. y0 sends its Le
        //          towards the camera (C_0), a later vertex scatters by the adjoint BSDF (Eq. 5.6); no connection from
        //          the background or a delta material (Eq. 5.9). Pitfalls (README 6): the k = 0 connection left out; a
        //          point light is on no surface.
        (void)v; (void)start; (void)out; (void)z;
        return PS_TODO("lesson 05: traceLightPath", false);
    });
}

}  // namespace ps
