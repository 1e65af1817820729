// Lesson 2, graded: what MIS is for. On Veach's plates (scenes/veach-plates.scene at 64 x 64)
// light sampling fails on the shiny plates and BSDF sampling on the rough ones; the power
// heuristic must do at least as well as the better of the two on EVERY plate.
//
// Equal samples per technique: the MIS estimator takes one light sample and one BSDF sample per
// pixel and iteration, and it takes exactly the samples the single-technique estimators take
// (the integrators draw the same random numbers, direct_integrators.cpp). Light sampling alone
// is itself a weighting of those samples (w_light = 1, w_bsdf = 0), so Veach's theorem 9.2 says
// the balance heuristic can be worse than it by at most a term that vanishes with the sample
// count; the power heuristic does about as well in practice. Measured with the reference solution
// over seeds 1-5 at 256 spp, the power heuristic's per-plate relMSE is at most 0.79 of the better
// single technique's (most plates: below 0.3); but on the back plate (nearly a mirror, where BSDF
// sampling is nearly optimal) the two are close, and scripts/seeds.sh found a seed where power was
// 1.5 % worse than BSDF sampling there. So the test allows 10 %: power's relMSE must be at most
// 1.1 times the better single technique's on every plate.
// relMSE is against the stored reference data/veach-plates-64.pfm (65536 spp of direct-power;
// README section 4 has the command), whose own noise is under 1 % of the errors compared.
#include "lesson02.h"
#include "seed.h"

using namespace lesson02;

TEST_CASE("direct: on Veach's plates the power heuristic beats the better single technique on every plate [2 pts]") {
    const ps::Scene scene = loadSceneAt("scenes/veach-plates.scene", 64, 64);
    const ps::Image ref = readData("veach-plates-64.pfm");
    const std::vector<int> mask = plateMask(scene);
    constexpr int kSpp = 256;
    const Render light = render(scene, "direct-light", kSpp, ps::testseed::seed(41));
    const Render bsdf = render(scene, "direct-bsdf", kSpp, ps::testseed::seed(41));
    const Render power = render(scene, "direct-power", kSpp, ps::testseed::seed(41));
    for (const Render* r : {&light, &bsdf, &power}) LESSON02_CHECK_FINITE(*r);
    const ps::Image black(ref.width, ref.height);
    const std::string plates[] = {"back plate (exponent 10000)", "second plate (exponent 1000)",
                                  "third plate (exponent 100)", "front plate (exponent 10)"};
    for (int p = 0; p < 4; ++p) {
        const double eL = plateRelMse(light.mean, ref, mask, p), eB = plateRelMse(bsdf.mean, ref, mask, p);
        const double eP = plateRelMse(power.mean, ref, mask, p), eBlack = plateRelMse(black, ref, mask, p);
        // A black plate (nothing estimated) has relMSE eBlack; an estimate must do far better.
        CHECK_MESSAGE(
            (eP <= 1.1 * std::min(eL, eB) && eP < 0.25 * eBlack),
            plates[p]
                << ", " << kSpp << " spp (seed " << ps::testseed::seed(41)
                << "), relMSE against the reference: expected "
                << "the power heuristic's <= 1.1 min(light sampling, BSDF sampling) and < 1/4 of a black image's, got power "
                << eP << ", light " << eL << ", BSDF " << eB << ", black " << eBlack
                << "\n  (a = your power heuristic's image) "
                << ps::stats::writeFailedImages(power.mean, power.variance, ref, ps::Image()));
    }
}
