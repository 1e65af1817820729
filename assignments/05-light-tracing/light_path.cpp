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
        // TODO(05) What vertex v adds to the image (Eq. 5.3, 5.4): connect it to the camera
        //          point z (connectToCamera(..., z)) and, if the connection is valid,
        //          out.add(c.raster, value).
        //          y0 (bounces 0): value = Le / pdfA * importance, Le towards the camera (a point
        //          light: its intensity); no connection from the background. Later vertices:
        //          value = beta * f* * importance with f*(wLight -> wCam) = evalBSDF(m, n, wCam,
        //          wLight), wLight = v.wo (Eq. 5.6); none from a delta material (Eq. 5.9). Return true.
        //          Pitfall: a point light is not on a surface (connectToCamera's onSurface).
        (void)v; (void)start; (void)out; (void)z;
        return PS_TODO("lesson 05: traceLightPath", false);
    });
}

}  // namespace ps
