// Lesson 11's Whitted ray tracer (Whitted 1980): from the eye, rays are followed through perfect
// mirrors and through both branches of glass (reflected and refracted, Fresnel-weighted) until
// they meet a surface that is not specular; there the point lights shine, each seen through one
// shadow ray, and an optional ambient term stands for all other light. Implemented in
// solutions/11-classics/{whitted_direct,glass_split,whitted}.cpp (reference) or
// assignments/11-classics/... (yours); lessons/11-classics/README.md, Eq. 11.7-11.9.
//
// In Heckbert's notation (Eq. 11.1) Whitted carries the paths L [DG] S* E whose light is a point
// light, and L S* E (a lamp or the background seen directly or in mirrors and glass). Area lights
// and the background light no surface: Whitted's lights are points. On a scene whose lights are
// all point lights, with ambient 0, its image is therefore the path tracer's filtered to
// `L[DG]S*E|LS*E` (`pathspace render --algo pt --paths ...`; the L S* E paths of a point light
// carry nothing), the graded test's oracle.
#pragma once
#include "scene.h"

namespace ps {

struct WhittedOptions {
    int maxDepth = 8;          // the most bounces a path may have, as lesson 3's maxDepth (Eq. 3.3)
    Color ambient = Color(0);  // Whitted's ambient radiance (default 0: none, Eq. 11.9)
};

// The light the scene's point lights send from sp towards wo (Eq. 11.7): the sum over every point
// light l (position p_l, intensity I_l) that sp sees, one shadow ray each
// (scene.occluded(scene.spawnRayTo(sp, p_l))), of
//   f(wo, w_l) I_l |cos theta_l| / d_l^2,   w_l = (p_l - sp.p) / d_l,
// f = evalBSDF(material of sp, sp.n, wo, w_l). Other lights add nothing here.
Color whittedDirect(const Scene& scene, const SurfacePoint& sp, const Vec3& wo);

// The two branches of a smooth dielectric m (index 1 on the side its normal n points to, m.ior
// on the other) for radiance arriving from the direction wo (unit, away from the surface)
// (Eq. 11.8), eta_o the index on wo's side and eta_t the other one:
struct GlassSplit {
    Vec3 reflected;             // wo mirrored about the normal on wo's side
    Vec3 refracted;             // Snell's direction on the other side (Vec3(0) under total internal reflection)
    float reflectance = 1.0f;   // F = fresnelDielectric(|cos theta_o|, eta_o, eta_t)
    float transmission = 0.0f;  // the refracted branch's factor (1 - F) (eta_o / eta_t)^2 (radiance
                                // is compressed into a narrower cone as it enters a denser medium);
                                // 0 under total internal reflection
};
GlassSplit glassSplit(const Material& m, const Vec3& n, const Vec3& wo);

// The radiance arriving at the ray's origin along `ray`, after `bounces` bounces before it (the
// camera ray: 0), Whitted's recursion (Eq. 11.9):
//   - no hit: the background's radiance (scene.backgroundRadiance());
//   - a hit x (wo = -ray.d): the radiance x emits towards wo (an area light's emittedRadiance),
//     plus, if bounces < opt.maxDepth:
//       mirror: albedo L(x -> reflected direction), with bounces + 1;
//       glass: F L(reflected) + (1 - F) (eta_o / eta_t)^2 L(refracted), both with bounces + 1;
//       other materials: whittedDirect plus opt.ambient times the material's albedo.
// Rays leave x through scene.spawnRay.
Color LiWhitted(const Scene& scene, const Ray& ray, int bounces, const WhittedOptions& opt);

// The ambient radiance a render asks for: the render parameter `ambient` this lesson registers
// (`render ambient R G B` in a scene file, `--ambient A` or `R,G,B` on the command line; each
// value finite, not negative, at most 1e30), black where none is set (whitted_integrator.cpp).
Color whittedAmbient(const RenderSettings& settings);

}  // namespace ps
