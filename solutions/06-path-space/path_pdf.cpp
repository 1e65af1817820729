// Lesson 6 — the area-measure pdf p_{s,t}(x) of a path under technique (s, t). Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

double pdfTechnique(const Scene& scene, const Path& x, int s) {
    // Given: a technique of this path at all (s from 0 to k + 1, k >= 1). Not the student's: a
    // missing check would read before the path (x[-1]), which no test can observe reliably.
    if (x.size() < 2 || s < 0 || s > int(x.size())) return 0.0;
    //! TODO(06) p_{s,t}(x) per unit area (Eq. 6.7-6.10), in double, 0 for what technique s cannot sample (Eq. 6.12), as
    //!          pdfTechnique in paths.h states it; x0 and x1 as startLightPath samples them, specular vertices as in
    //!          contribution. Pitfalls (README 6): the BSDF's argument order in each subpath; P(l) p_A(x0) counts even
    //!          for s = 1; no Russian roulette.
    //! STUB (void)scene; (void)x; (void)s;
    //! STUB return PS_TODO("lesson 06: pdfTechnique", 0.0);
    //! BEGIN
    const int k = int(x.size()) - 1, t = k + 1 - s;
    if (t == 0 && !x[size_t(k)].onCamera) return 0.0;
    if (s == 0 && (!x[0].onLight || x[0].pointLight)) return 0.0;
    if (s >= 1 && t >= 1 && (x[size_t(s) - 1].specular || x[size_t(s)].specular)) return 0.0;
    if (t == 1 && x[size_t(k) - 1].infinite) return 0.0;  // the background joined straight to the pinhole
    double p = 1.0;
    // The light subpath x0 ... x_{s-1} (Eq. 6.8).
    if (s >= 1) {
        const int l = x[0].sp.light;
        if (l < 0) return 0.0;
        const EmissionPdf e = pdfEmission(scene, l, x[0].sp.n, direction(x[0], x[1]));
        p *= scene.lightSelectionProb(l);
        p *= x[0].infinite ? e.pdfW : e.pdfA;  // the background's x0 is a direction
        if (s >= 2) {
            if (x[0].infinite) p *= double(e.pdfA) * std::abs(double(glm::dot(x[1].sp.n, x[0].sp.n)));
            else p *= pdfSolidAngleToArea(e.pdfW, x[0], x[1]);
        }
        for (int i = 1; i <= s - 2; ++i) {
            const PathVertex& v = x[size_t(i)];
            const Material& m = scene.materials[size_t(v.sp.material)];
            const Vec3 wLight = direction(v, x[size_t(i) - 1]), wNext = direction(v, x[size_t(i) + 1]);
            float pdfW;
            if (v.specular) {
                const DeltaLobe lobe =
                    deltaLobe(m, v.sp.n, wLight, wNext, deltaTolerance(x[size_t(i) - 1], v, x[size_t(i) + 1]));
                pdfW = lobe.valid ? lobe.pdfLight : 0.0f;
            } else {
                pdfW = pdfBSDF(m, v.sp.n, wLight, wNext);
            }
            p *= pdfSolidAngleToArea(pdfW, v, x[size_t(i) + 1]);
        }
    }
    // The camera subpath x_k ... x_s (Eq. 6.9): the pinhole is a delta position (pdfPoint 1).
    const Camera& camera = scene.camera;
    if (t >= 1) p *= camera.pdfPoint();
    if (t >= 2) {
        p *= pdfSolidAngleToArea(camera.pdfDirection(x[size_t(k)].p(), direction(x[size_t(k)], x[size_t(k) - 1])),
                                 x[size_t(k)], x[size_t(k) - 1]);
        for (int j = k - 1; j >= s + 1; --j) {
            const PathVertex& v = x[size_t(j)];
            const Material& m = scene.materials[size_t(v.sp.material)];
            const Vec3 wCamera = direction(v, x[size_t(j) + 1]), wPrev = direction(v, x[size_t(j) - 1]);
            float pdfW;
            if (v.specular) {
                const DeltaLobe lobe =
                    deltaLobe(m, v.sp.n, wPrev, wCamera, deltaTolerance(x[size_t(j) - 1], v, x[size_t(j) + 1]));
                pdfW = lobe.valid ? lobe.pdfCamera : 0.0f;
            } else {
                pdfW = pdfBSDF(m, v.sp.n, wCamera, wPrev);
            }
            p *= pdfSolidAngleToArea(pdfW, v, x[size_t(j) - 1]);
        }
    }
    return p;
    //! END
}

}  // namespace ps
