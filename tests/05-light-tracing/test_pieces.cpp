// Lesson 5, graded: the pieces of the light tracer, exactly: the particle leaving a light
// (Eq. 5.2), the connection to the camera (Eq. 5.5), the adjoint BSDF (Eq. 5.6-5.8), and an
// image that does not depend on the number of threads.
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool close(double a, double b, double rel) {
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + 1e-30;
}

// Two lights of different power (an area light facing down, a point light) and a floor.
const char* const kTwoLights =
    "camera eye 0 1 -3  target 0 0.5 0  fov 60  resolution 8 8\n"
    "material floor diffuse albedo 0.5 0.5 0.5\n"
    "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material floor\n"
    "quad -0.5 2 -0.5  0.5 2 -0.5  0.5 2 0.5  -0.5 2 0.5  emission 4 3 2\n"
    "pointlight position 1 1 1  intensity 2 2 2\n";

}  // namespace

TEST_CASE("light tracing: the particle leaving a light carries Le |cos| / (P p_A p_omega) (Eq. 5.2) [1 pt]") {
    const ps::Scene scene = ps::parseScene(kTwoLights, "two lights (test_pieces.cpp)");
    int checked[2] = {0, 0};
    for (int i = 0; i < 64; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(5501), 0, uint32_t(i));
        const float uLight = rng.uniform();
        const Vec2 uPos = rng.uniform2(), uDir = rng.uniform2();
        const ps::LightPathStart s = ps::startLightPath(scene, uLight, uPos, uDir);
        float P = 0.0f;
        const int l = scene.selectLight(uLight, P);
        const ps::EmissionSample e = ps::sampleEmission(scene, l, uPos, uDir);
        const bool point = scene.lights[l].isDelta();
        const Color expected =
            e.Le * float((point ? 1.0 : std::abs(double(glm::dot(e.n, e.dir)))) / (double(P) * e.pdfA * e.pdfW));
        ++checked[point];
        INFO(std::string(point ? "point light" : "area light")
             << ", sample " << i << ": emission point " << str(e.p) << ", direction " << str(e.dir)
             << ", light chosen with probability " << P);
        REQUIRE_MESSAGE(s.valid, "expected a valid start");
        CHECK_MESSAGE(s.light == l, "expected light " << l << ", got " << s.light);
        CHECK_MESSAGE(close(s.pdfA, double(P) * e.pdfA, 1e-5),
                      "expected pdfA = P p_A = " << double(P) * e.pdfA << ", got " << s.pdfA);
        CHECK_MESSAGE((close(s.beta.r, expected.r, 1e-4) && close(s.beta.g, expected.g, 1e-4) &&
                       close(s.beta.b, expected.b, 1e-4)),
                      "expected the particle's power " << str(expected) << ", got " << str(s.beta));
        CHECK_MESSAGE(glm::length(s.y0.p - e.p) < 1e-6f, "expected y0 at " << str(e.p) << ", got " << str(s.y0.p));
        CHECK_MESSAGE((glm::length(s.ray.d - e.dir) < 1e-6f && glm::length(s.ray.o - e.p) < 1e-4f),
                      "expected the ray to leave " << str(e.p) << " along " << str(e.dir) << ", got origin "
                                                   << str(s.ray.o) << ", direction " << str(s.ray.d));
    }
    CHECK_MESSAGE((checked[0] > 5 && checked[1] > 5), "test setup: both lights should have been chosen");
}

TEST_CASE("light tracing: the connection to the camera: raster position, W_e G and visibility (Eq. 5.5) [2 pts]") {
    // A camera at the origin looking down +z with up +y (fov 60, 40 x 30; so the image's right
    // is -x), an occluding square at z = 5 covering x in [1, 3]. Expected values computed here from scratch, in double:
    // importance = w h / (A cos^4 theta_e) * cos(theta_e) |cos(theta_y)| / d^2.
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 0 0  target 0 0 1  up 0 1 0  fov 60  resolution 40 30\n"
        "material m diffuse albedo 0.5 0.5 0.5\n"
        "quad 1 -1 5  3 -1 5  3 1 5  1 1 5  material m\n",
        "connection (test_pieces.cpp)");
    const double ty = std::tan(30.0 * kPi / 180.0), tx = ty * 40.0 / 30.0, A = 4.0 * tx * ty;
    struct Case {
        Vec3 p, n;
        bool onSurface, visible;
    };
    const Case cases[] = {
        {Vec3(0.2f, -0.3f, 4.0f), glm::normalize(Vec3(0.3f, 1.0f, -0.5f)), true, true},
        {Vec3(-3.0f, 2.0f, 7.0f), glm::normalize(Vec3(0.0f, 0.0f, -1.0f)), true, true},  // near the top right corner
        {Vec3(1.0f, 0.5f, 2.0f), glm::normalize(Vec3(1.0f, -1.0f, 0.2f)), false, true},  // a point light: no cos at y
        {Vec3(4.0f, 0.0f, 10.0f), Vec3(0.0f, 0.0f, -1.0f), true, false},                 // behind the occluder
        {Vec3(0.0f, 0.0f, -2.0f), Vec3(0.0f, 0.0f, 1.0f), true, false},                  // behind the camera
        {Vec3(9.0f, 0.0f, 4.0f), Vec3(0.0f, 0.0f, -1.0f), true, false},                  // outside the image
    };
    for (const Case& c : cases) {
        ps::SurfacePoint y;
        y.p = c.p;
        y.n = c.n;
        y.errScale = c.onSurface ? ps::maxAbsComponent(c.p) : 0.0f;
        const ps::CameraConnection got = ps::connectToCamera(scene, y, c.onSurface);
        INFO("point " << str(c.p) << (c.onSurface ? ", normal " + str(c.n) : std::string(", not on a surface")));
        CHECK_MESSAGE(got.valid == c.visible, "expected the connection to be "
                                                  << std::string(c.visible ? "valid" : "invalid") << ", got "
                                                  << std::string(got.valid ? "valid" : "invalid"));
        if (!c.visible || !got.valid) continue;
        const glm::dvec3 toEye = -glm::dvec3(c.p);
        const double d = glm::length(toEye), cosE = double(c.p.z) / d;
        const double cosY = c.onSurface ? std::abs(glm::dot(glm::dvec3(c.n), toEye / d)) : 1.0;
        const double expected = 40.0 * 30.0 / (A * std::pow(cosE, 4)) * cosE * cosY / (d * d);
        const Vec2 raster(float((-c.p.x / c.p.z / tx + 1.0) * 20.0), float((1.0 - c.p.y / c.p.z / ty) * 15.0));
        CHECK_MESSAGE(close(got.importance, expected, 1e-4),
                      "expected importance W_e^(j) G = " << num(expected) << ", got " << num(got.importance));
        CHECK_MESSAGE(glm::length(got.raster - raster) < 1e-3f,
                      "expected raster " << str(raster) << ", got " << str(got.raster));
        CHECK_MESSAGE(glm::length(got.wCam - Vec3(toEye / d)) < 1e-5f,
                      "expected wCam " << str(Vec3(toEye / d)) << ", got " << str(got.wCam));
    }
}

TEST_CASE(
    "light tracing: the adjoint BSDF keeps a particle's power through glass and weighs diffuse and glossy bounces (Eq. 5.6-5.8) [2 pts]") {
    const Vec3 n(0.0f, 0.0f, 1.0f);
    ps::Material glass;
    glass.kind = ps::BSDFKind::Dielectric;
    glass.ior = 1.5f;
    // Glass: from outside and from inside, at several angles; both lobes.
    for (float sign : {1.0f, -1.0f})
        for (float deg : {0.0f, 20.0f, 40.0f, 60.0f, 85.0f}) {
            const float th = deg * float(kPi) / 180.0f;
            const Vec3 wLight(std::sin(th), 0.0f, sign * std::cos(th));
            const float etaFrom = sign > 0 ? 1.0f : 1.5f, etaTo = sign > 0 ? 1.5f : 1.0f;
            const float F = ps::fresnelDielectric(std::cos(th), etaFrom, etaTo);
            for (float uLobe : {0.999f * F, F + 0.001f * (1.0f - F)}) {
                if (uLobe >= 1.0f) continue;  // total internal reflection: no refraction lobe
                ps::BSDFSample s;
                const bool ok = ps::sampleAdjointBSDF(glass, n, wLight, Vec2(0.3f, 0.6f), uLobe, s);
                const bool refract = uLobe >= F;
                INFO("glass (ior 1.5), particle from the "
                     << std::string(sign > 0 ? "outside" : "inside") << " at " << deg << " degrees, "
                     << std::string(refract ? "refraction" : "reflection") << " (F = " << F << ")");
                REQUIRE_MESSAGE(ok, "expected a valid sample");
                CHECK_MESSAGE(s.delta, "expected a delta (specular) sample");
                CHECK_MESSAGE(
                    (close(s.weight.r, 1.0, 1e-5) && close(s.weight.g, 1.0, 1e-5) && close(s.weight.b, 1.0, 1e-5)),
                    "expected weight 1: the particle keeps its power (the radiance factor (eta_i/eta_t)^2 = "
                        << (etaFrom / etaTo) * (etaFrom / etaTo) << " is not for particles), got " << str(s.weight));
                CHECK_MESSAGE(close(s.pdf, refract ? 1.0 - F : F, 1e-5),
                              "expected pdf " << (refract ? 1.0f - F : F) << ", got " << s.pdf);
                Vec3 expected;
                if (!refract) {
                    expected = Vec3(-wLight.x, -wLight.y, wLight.z);
                } else {
                    const float sinT = etaFrom / etaTo * std::sin(th);
                    expected = Vec3(-sinT, 0.0f, -sign * std::sqrt(1.0f - sinT * sinT));  // Snell, on the other side
                }
                CHECK_MESSAGE(glm::length(s.wi - expected) < 1e-5f,
                              "expected direction " << str(expected) << ", got " << str(s.wi));
            }
        }
    // Diffuse and glossy: the weight is f(wLight -> wi) |cos(theta_wi)| / pdf(wi), with the
    // cosine of the direction the particle leaves in. What an argument swap really changes here
    // (lessons/05-light-tracing/README.md, 1.4): not f (Lambert and normalised Phong are
    // reciprocal, so evalBSDF(m, n, wLight, wi) is the same number as evalBSDF(m, n, wi, wLight);
    // no test can or should tell them apart), nor Phong's pdf (symmetric: it depends on
    // dot(wi, reflect(wLight)) only), but the Lambertian's sampling pdf: cos of the SAMPLED
    // direction / pi, computed here from the direction itself, while the swapped
    // pdfBSDF(m, n, wi, wLight) is cos(theta_wLight) / pi. The cosine of the weight belongs to
    // the sampled direction too.
    ps::Material diffuse;
    diffuse.kind = ps::BSDFKind::Diffuse;
    diffuse.albedo = Color(0.8f, 0.5f, 0.2f);
    ps::Material phong;
    phong.kind = ps::BSDFKind::Phong;
    phong.albedo = Color(0.7f, 0.6f, 0.5f);
    phong.exponent = 20.0f;
    int bad = 0;
    for (const ps::Material* m : {&diffuse, &phong})
        for (int i = 0; i < 200; ++i) {
            ps::Rng rng = ps::taskRng(ps::testseed::seed(5601), 0, uint32_t(i));
            const Vec3 wLight = ps::sampleUniformSphere(rng.uniform2());
            const Vec2 u = rng.uniform2();
            ps::BSDFSample s;
            if (!ps::sampleAdjointBSDF(*m, n, wLight, u, 0.5f, s)) continue;
            const double cosOut = std::abs(double(glm::dot(n, s.wi))), cosIn = std::abs(double(glm::dot(n, wLight)));
            const bool sameSide = glm::dot(n, s.wi) * glm::dot(n, wLight) > 0.0f;
            const double pdf = m == &diffuse ? (sameSide ? cosOut / double(kPi) : 0.0)  // Eq. 1.11, of the sampled wi
                                             : double(ps::pdfBSDF(*m, n, wLight, s.wi));
            const Color f = ps::evalBSDF(*m, n, s.wi, wLight);
            const Color expected = pdf > 0.0 ? f * float(cosOut / pdf) : Color(0.0f);
            const bool ok = !s.delta && close(s.pdf, pdf, 1e-4) && close(s.weight.r, expected.r, 1e-4) &&
                            close(s.weight.g, expected.g, 1e-4) && close(s.weight.b, expected.b, 1e-4);
            if (!ok && ++bad <= 3) {
                std::string hint;
                if (m == &diffuse && close(s.pdf, cosIn / double(kPi), 1e-4) && !close(cosIn, cosOut, 1e-3))
                    hint =
                        " (that pdf is cos(theta of wLight) / pi: the pdf's arguments are swapped; the Lambertian's "
                        "sampling pdf is the cosine of the SAMPLED direction / pi, pdfBSDF(m, n, wLight, wi))";
                else if (pdf > 0.0 && close(s.weight.r, f.r * cosIn / pdf, 1e-4) && !close(cosIn, cosOut, 1e-3))
                    hint =
                        " (that is the cosine of the direction the particle came from: Eq. 5.6 takes |cos| of the sampled one)";
                else if (m == &diffuse && close(s.weight.r, diffuse.albedo.r * cosOut / cosIn, 1e-4) &&
                         !close(cosIn, cosOut, 1e-3))
                    hint =
                        " (albedo cos(out) / cos(in): the weight divides by the swapped pdf pdfBSDF(m, n, wi, wLight))";
                FAIL_CHECK(std::string(m == &diffuse ? "diffuse" : "Phong (n = 20)")
                           << ", particle from " << str(wLight) << ", sampled " << str(s.wi) << ": expected pdf " << pdf
                           << " and weight f |cos(theta_wi)| / pdf = " << str(expected) << ", got pdf " << s.pdf
                           << " and weight " << str(s.weight) << hint);
            }
        }
    CHECK_MESSAGE(bad == 0, bad << " of 400 diffuse and glossy samples have a wrong pdf or weight");
}

TEST_CASE("light tracing: the image does not depend on the number of threads [1 pt]") {
    // Light paths splat all over the image; through the SplatBuffer the sum is the same, in the
    // same order, whatever thread traced a path: 1 and 2 threads give identical bits.
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    const Render one = render(scene, "lt", 6, ps::testseed::seed(5701), 1),
                 two = render(scene, "lt", 6, ps::testseed::seed(5701), 2);
    size_t differ = 0;
    for (size_t i = 0; i < one.mean.pixels.size(); ++i) differ += one.mean.pixels[i] != two.mean.pixels[i];
    CHECK_MESSAGE(total(one.mean) > 0.0,
                  "lt on the Cornell box (16 x 16, 6 iterations): expected an image that is not black");
    CHECK_MESSAGE(differ == 0,
                  "lt on the Cornell box (16 x 16, 6 iterations, seed 5701): expected identical images with 1 and 2 "
                  "threads, got "
                      << differ << " different pixels");
}
