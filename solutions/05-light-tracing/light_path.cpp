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
        //! TODO(05) What vertex v adds to the image (Eq. 5.3, 5.4), through out.add; return true. y0 sends its Le
        //!          towards the camera (C_0), a later vertex scatters by the adjoint BSDF (Eq. 5.6); no connection from
        //!          the background or a delta material (Eq. 5.9). Pitfalls (README 6): the k = 0 connection left out; a
        //!          point light is on no surface.
        //! STUB (void)v; (void)start; (void)out; (void)z;
        //! STUB return PS_TODO("lesson 05: traceLightPath", false);
        //! BEGIN
        if (v.bounces == 0) {
            // The point on the light seen directly (not the background: no point to connect).
            const Light& light = scene.lights[start.light];
            if (light.isInfinite()) return true;
            const CameraConnection c = connectToCamera(scene, v.sp, !light.isDelta(), z);
            if (c.valid) {
                const Color Le = light.isDelta() ? light.Le : emittedRadiance(light, v.sp.n, c.wCam);
                out.add(c.raster, Le * (c.importance / start.pdfA));
            }
            return true;
        }
        const Material& m = scene.materials[v.sp.material];
        if (m.isDelta()) return true;
        const CameraConnection c = connectToCamera(scene, v.sp, true, z);
        if (c.valid) out.add(c.raster, v.beta * evalBSDF(m, v.sp.n, c.wCam, v.wo) * c.importance);
        return true;
        //! END
    });
}

}  // namespace ps
