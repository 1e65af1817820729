// Lesson 12, graded: guided sampling (Eq. 12.3, 12.4). The mixture of a hand-made guide (its
// density from the test's own leaves) and the BSDF (the framework's pdfBSDF): every sampled
// direction's pdf and weight against that oracle, the sampler's directions against the oracle's
// counts (chi-square over the square of the cylindrical map, bins aligned with the guide's
// quadrants), and delta BSDFs never guided (the numbers replayed).
#include "lesson12.h"
#include "warps.h"

using namespace lesson12;

namespace {

// The hand-made guide's density per steradian from its leaves (the test's own oracle).
double guideDensity(const std::vector<Leaf>& leaves, double total, const Vec3& w) {
    double u, v;
    squareOf(w, u, v);
    const Leaf* l = leafAt(leaves, u, v);
    return l ? l->energy / total / (l->square.size * l->square.size) / (4.0 * kPiD) : 0.0;
}

ps::Material diffuse() {
    ps::Material m;
    m.kind = ps::BSDFKind::Diffuse;
    m.albedo = Color(0.8f, 0.6f, 0.4f);
    return m;
}
ps::Material phong(float exponent) {
    ps::Material m;
    m.kind = ps::BSDFKind::Phong;
    m.albedo = Color(0.7f);
    m.exponent = exponent;
    return m;
}

struct Replay : ps::UniformSource {
    std::vector<float> values;
    size_t read = 0;
    float next() override { return read < values.size() ? values[read++] : (++read, 0.5f); }
};

}  // namespace

TEST_CASE(
    "guided sampling: every direction's pdf is the mixture's, alpha guide + (1 - alpha) BSDF, and its weight f cos / pdf (Eq. 12.3, 12.4) [2 pts]") {
    const ps::DirectionalTree guide = handTree();
    const std::vector<Leaf> leaves = leavesOf(guide);
    const double total = totalOf(leaves);
    struct Case {
        ps::Material m;
        Vec3 n, wo;
        float alpha;
        const char* what;
    };
    const Vec3 up(0.0f, 0.0f, 1.0f);
    for (const Case& c :
         {Case{diffuse(), up, glm::normalize(Vec3(0.3f, 0.1f, 1.0f)), 0.5f, "diffuse, alpha 0.5"},
          Case{diffuse(), glm::normalize(Vec3(1.0f, -1.0f, 0.2f)), Vec3(0.0f, 0.0f, 1.0f), 0.3f,
               "diffuse, a tilted normal, alpha 0.3"},
          Case{phong(20.0f), up, glm::normalize(Vec3(-0.5f, 0.2f, 1.0f)), 0.5f, "Phong 20, alpha 0.5"},
          Case{diffuse(), up, glm::normalize(Vec3(0.3f, 0.1f, 1.0f)), 0.0f, "alpha 0: the BSDF alone"}}) {
        ps::Rng rng(ps::testseed::seed(1206), 9);
        int wrongPdf = 0, wrongWeight = 0, valid = 0;
        std::string firstPdf, firstWeight;
        for (int k = 0; k < 4000; ++k) {
            ps::BSDFSample s;
            if (!ps::sampleGuided(c.m, c.n, c.wo, guide, c.alpha, rng, s)) continue;
            ++valid;
            const double want =
                c.alpha * guideDensity(leaves, total, s.wi) + (1.0 - c.alpha) * ps::pdfBSDF(c.m, c.n, c.wo, s.wi);
            if (std::abs(s.pdf - want) > 1e-4 * want && wrongPdf++ == 0)
                firstPdf = "direction " + str(s.wi) + ": expected " + num(want) + ", got " + num(s.pdf) + " (guide " +
                           num(guideDensity(leaves, total, s.wi)) + ", BSDF " + num(ps::pdfBSDF(c.m, c.n, c.wo, s.wi)) +
                           ")";
            const Color w = ps::evalBSDF(c.m, c.n, c.wo, s.wi) * (std::abs(glm::dot(c.n, s.wi)) / float(want));
            if (glm::length(s.weight - w) > 1e-4f * glm::length(w) && wrongWeight++ == 0)
                firstWeight = "direction " + str(s.wi) + ": expected " + str(w) + ", got " + str(s.weight);
            if (s.delta) ++wrongWeight;
        }
        CHECK_MESSAGE(valid > 1000,
                      "sampleGuided (" << c.what << "): expected most of 4000 samples valid, got " << valid);
        CHECK_MESSAGE(wrongPdf == 0, "sampleGuided (" << c.what << "): " << wrongPdf << " of " << valid
                                                      << " samples with the wrong pdf (Eq. 12.3); the first, "
                                                      << firstPdf);
        CHECK_MESSAGE(wrongWeight == 0, "sampleGuided (" << c.what << "): " << wrongWeight << " of " << valid
                                                         << " samples with the wrong weight or marked delta (Eq. "
                                                            "12.4); the first, "
                                                         << firstWeight);
        const Vec3 probe = glm::normalize(Vec3(0.2f, -0.4f, 0.9f));
        const double want =
            c.alpha * guideDensity(leaves, total, probe) + (1.0 - c.alpha) * ps::pdfBSDF(c.m, c.n, c.wo, probe);
        const double got = ps::guidedPdf(c.m, c.n, c.wo, guide, c.alpha, probe);
        CHECK_MESSAGE(std::abs(got - want) <= 1e-4 * want, "guidedPdf (" << c.what << ") at " << str(probe)
                                                                         << ": expected " << num(want) << ", got "
                                                                         << num(got));
    }
}

TEST_CASE("guided sampling: the directions follow the mixture (chi-square, Eq. 12.3) [1 pt]") {
    const ps::DirectionalTree guide = handTree();
    const std::vector<Leaf> leaves = leavesOf(guide);
    const double total = totalOf(leaves);
    const ps::Material m = phong(4.0f);
    const Vec3 n = glm::normalize(Vec3(0.2f, 0.1f, 1.0f)), wo = glm::normalize(Vec3(0.6f, -0.3f, 0.8f));
    const float mix = 0.4f;
    // 32 x 32 bins of the square (aligned with every leaf of the guide but the deepest, whose
    // energy is spread evenly within its bin by energyIn); the BSDF's share by a 16 x 16 midpoint
    // rule per bin; invalid samples (a Phong direction below the surface) in a bin of their own.
    constexpr int B = 32, Q = 16, samples = 100000;
    std::vector<double> expected(B * B + 1, 0.0), observed(B * B + 1, 0.0);
    double valid = 0.0;
    for (int i = 0; i < B; ++i)
        for (int j = 0; j < B; ++j) {
            const Square sq{double(i) / B, double(j) / B, 1.0 / B};
            double bsdf = 0.0;
            for (int a = 0; a < Q; ++a)
                for (int b = 0; b < Q; ++b)
                    bsdf += ps::pdfBSDF(m, n, wo,
                                        directionOf(sq.x + (a + 0.5) * sq.size / Q, sq.y + (b + 0.5) * sq.size / Q));
            bsdf *= 4.0 * kPiD * sq.size * sq.size / (Q * Q);
            // The guide's directions where f is 0 (below the surface) come out invalid too.
            double below = 0.0;
            for (int a = 0; a < Q; ++a)
                for (int b = 0; b < Q; ++b) {
                    const Vec3 w = directionOf(sq.x + (a + 0.5) * sq.size / Q, sq.y + (b + 0.5) * sq.size / Q);
                    if (ps::pdfBSDF(m, n, wo, w) == 0.0f) below += 1.0;
                }
            const double g = energyIn(leaves, sq) / total;
            const double e = mix * g * (1.0 - below / (Q * Q)) + (1.0 - mix) * bsdf;
            expected[size_t(i) * B + j] = e * samples;
            valid += e;
        }
    expected[B * B] = (1.0 - valid) * samples;
    ps::Rng rng(ps::testseed::seed(1207), 4);
    for (int k = 0; k < samples; ++k) {
        ps::BSDFSample s;
        if (!ps::sampleGuided(m, n, wo, guide, mix, rng, s)) {
            observed[B * B] += 1.0;
            continue;
        }
        double u, v;
        squareOf(s.wi, u, v);
        observed[size_t(std::min(B - 1, int(u * B))) * B + size_t(std::min(B - 1, int(v * B)))] += 1.0;
    }
    const ps::stats::ChiSquareResult r = ps::stats::chiSquare(observed, expected, alpha());
    CHECK_MESSAGE(r.passed, "sampleGuided (Phong 4, alpha 0.4, the hand-made guide): "
                                << samples
                                << " directions binned in the square (32 x 32, and the invalid ones) "
                                   "against the mixture's probabilities: "
                                << r.report);
}

TEST_CASE("guided sampling: a delta BSDF is never guided (Eq. 12.3) [1 pt]") {
    const ps::DirectionalTree guide = handTree();
    ps::Material mirror, glass;
    mirror.kind = ps::BSDFKind::Mirror;
    mirror.albedo = Color(0.9f);
    glass.kind = ps::BSDFKind::Dielectric;
    glass.ior = 1.5f;
    const Vec3 n(0.0f, 0.0f, 1.0f), wo = glm::normalize(Vec3(0.4f, 0.2f, 1.0f));
    for (const ps::Material* m : {&mirror, &glass})
        for (const float u : {0.02f, 0.5f, 0.97f}) {
            Replay replay;
            replay.values = {u, 0.3f, u, 0.8f, 0.1f};
            ps::Rng rng;
            rng.replayFrom(&replay);
            ps::BSDFSample s, want;
            const bool ok = ps::sampleGuided(*m, n, wo, guide, 0.5f, rng, s);
            ps::sampleBSDF(*m, n, wo, Vec2(u, 0.3f), u, ps::Transport::Radiance, want);
            const std::string what = std::string(m == &mirror ? "a mirror" : "glass") + ", numbers (" + num(u) +
                                     ", 0.3, " + num(u) + ", ...)";
            CHECK_MESSAGE((ok && s.delta && glm::length(s.wi - want.wi) < 1e-6f && s.pdf == want.pdf &&
                           glm::length(s.weight - want.weight) < 1e-6f),
                          "sampleGuided on " << what << ": expected lesson 3's delta sample (direction " << str(want.wi)
                                             << ", weight " << str(want.weight) << ", pdf " << num(want.pdf)
                                             << "), got " << (ok ? "" : "no sample, ") << "direction " << str(s.wi)
                                             << ", weight " << str(s.weight) << ", pdf " << num(s.pdf)
                                             << (s.delta ? "" : ", not delta"));
            CHECK_MESSAGE(replay.read == 3, "sampleGuided on " << what
                                                               << ": expected the three numbers of sampleBSDF "
                                                                  "and no choice between guide and BSDF, got "
                                                               << replay.read << " numbers");
        }
}
