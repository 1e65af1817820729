// Lesson 2 — the direct-illumination integrators the render command knows (plumbing: read it,
// nothing to write here). Each estimates the light reaching the camera after at most one
// bounce: the emission seen directly (0 bounces) plus the direct illumination at the first
// hit (Eq. 2.1), by one of the estimators of direct.cpp:
//
//   direct-light      light sampling only (Eq. 2.4)
//   direct-bsdf       BSDF sampling only (Eq. 2.5)
//   direct-balance    one sample of each, balance heuristic (Eq. 2.6, 2.7)
//   direct-power      one sample of each, power heuristic (Eq. 2.6, 2.8)
//   direct-max        one sample of each, maximum heuristic (Eq. 2.6, 2.9)
//   direct-onesample  one sample of either, chosen at random, balance heuristic (Eq. 2.11)
//
// All draw the same random numbers in the same order (DirectRandom), so for a given pixel and
// iteration they see the same light sample. scene.settings.maxDepth = 0 leaves out the bounce.
#include "02-direct-mis/direct.h"
#include "integrator.h"

namespace ps {

namespace {

enum class DirectStrategy { Light, BSDF, MultiSample, OneSample };

class DirectIntegrator : public PixelIntegrator {
public:
    DirectIntegrator(DirectStrategy strategy, Heuristic heuristic) : strategy_(strategy), heuristic_(heuristic) {}

    Color Li(const Scene& scene, const Ray& cameraRay, Rng& rng) const override {
        Ray ray = cameraRay;
        SurfacePoint sp;
        if (!scene.intersect(ray, sp)) return scene.backgroundRadiance();
        const Vec3 wo = -cameraRay.d;
        Color L(0.0f);
        if (sp.light >= 0) L += emittedRadiance(scene.lights[sp.light], sp.n, wo);  // 0 bounces
        if (scene.settings.maxDepth < 1) return L;

        DirectRandom u;
        u.uLight = rng.uniform();
        u.uPoint = rng.uniform2();
        u.uBSDF = rng.uniform2();
        u.uLobe = rng.uniform();
        u.uChoice = rng.uniform();
        switch (strategy_) {
        case DirectStrategy::Light: return L + sampleDirectLight(scene, sp, wo, u.uLight, u.uPoint).value;
        case DirectStrategy::BSDF: return L + sampleDirectBSDF(scene, sp, wo, u.uBSDF, u.uLobe).value;
        case DirectStrategy::MultiSample: return L + directMultiSample(scene, sp, wo, heuristic_, u);
        case DirectStrategy::OneSample: return L + directOneSample(scene, sp, wo, heuristic_, u);
        }
        return L;
    }

private:
    DirectStrategy strategy_;
    Heuristic heuristic_;
};

// One class per algorithm name, for PS_REGISTER_INTEGRATOR.
struct DirectLight : DirectIntegrator {
    DirectLight() : DirectIntegrator(DirectStrategy::Light, Heuristic::Balance) {}
};
struct DirectBSDF : DirectIntegrator {
    DirectBSDF() : DirectIntegrator(DirectStrategy::BSDF, Heuristic::Balance) {}
};
struct DirectBalance : DirectIntegrator {
    DirectBalance() : DirectIntegrator(DirectStrategy::MultiSample, Heuristic::Balance) {}
};
struct DirectPower : DirectIntegrator {
    DirectPower() : DirectIntegrator(DirectStrategy::MultiSample, Heuristic::Power) {}
};
struct DirectMax : DirectIntegrator {
    DirectMax() : DirectIntegrator(DirectStrategy::MultiSample, Heuristic::Maximum) {}
};
struct DirectOneSample : DirectIntegrator {
    DirectOneSample() : DirectIntegrator(DirectStrategy::OneSample, Heuristic::Balance) {}
};

}  // namespace

PS_REGISTER_INTEGRATOR(DirectLight, "direct-light", "direct illumination by light sampling only (lesson 2)");
PS_REGISTER_INTEGRATOR(DirectBSDF, "direct-bsdf", "direct illumination by BSDF sampling only (lesson 2)");
PS_REGISTER_INTEGRATOR(DirectBalance, "direct-balance",
                       "direct illumination, light + BSDF sample, balance heuristic (lesson 2)");
PS_REGISTER_INTEGRATOR(DirectPower, "direct-power",
                       "direct illumination, light + BSDF sample, power heuristic (lesson 2)");
PS_REGISTER_INTEGRATOR(DirectMax, "direct-max",
                       "direct illumination, light + BSDF sample, maximum heuristic (lesson 2)");
PS_REGISTER_INTEGRATOR(DirectOneSample, "direct-onesample",
                       "direct illumination, one-sample MIS, balance heuristic (lesson 2)");

}  // namespace ps
