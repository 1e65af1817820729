// Lesson 12's plumbing, ungraded: the learned field's memory budget (GuideField::endPass, the
// algorithm option --guide-budget MB that lesson 12 registers for pt-guided and pt-guided-adrrs),
// and the schedule's last pass, which learns nothing (GuidedPathTracer::renderIteration).
#include <doctest/doctest.h>
#include <string>
#include <vector>
#include "12-path-guiding/guiding.h"
#include "errors.h"
#include "film.h"
#include "integrator.h"
#include "render.h"
#include "rng.h"
#include "scene_loader.h"
#include "seed.h"
#include "warps.h"

namespace {

using ps::Vec3;

// A point of the unit cube, drawn x, y, z in this order.
Vec3 uniform3(ps::Rng& rng) {
    const float x = rng.uniform(), y = rng.uniform();
    return Vec3(x, y, rng.uniform());
}

// Passes of records spread over a box and over the sphere (many cells, deep directional trees),
// into a field of the given budget; the field's bytes after every pass, and its cells at the end.
struct Filled {
    std::vector<size_t> bytes;
    size_t cells = 0;
};
Filled fill(size_t budget, uint64_t seed) {
    ps::AABB box;
    box.lo = Vec3(0.0f);
    box.hi = Vec3(4.0f, 2.0f, 3.0f);
    ps::GuideSettings settings;
    settings.spatialThreshold = 16;
    settings.budget = budget;
    ps::GuideField field(box, settings);
    ps::Rng rng(seed, 7);
    Filled out;
    for (int pass = 0; pass < 5; ++pass) {
        std::vector<ps::RadianceRecord> recs;
        for (int k = 0; k < 4000; ++k) {
            const Vec3 p = box.lo + box.extent() * uniform3(rng);
            // Directions bunched around a few poles (trees that refine deep), values > 0.
            const Vec3 w = ps::sampleUniformSphere(rng.uniform2());
            const Vec3 bunched = glm::normalize(Vec3(float(k % 3) - 1.0f, 0.3f, 1.0f) + 0.2f * w);
            recs.push_back({int(field.cellOf(p)), k % 6, bunched, 0.5f + rng.uniform()});
        }
        field.add(recs);
        field.endPass(pass);
        out.bytes.push_back(field.bytes());
    }
    out.cells = field.cells();
    return out;
}

}  // namespace

TEST_CASE("learned field: its memory stays within the budget at the end of every pass (--guide-budget)") {
    // Budgets from where a few cells fit to half of what the field takes without one. The field once
    // took 60 % more than 20000 bytes here (the spatial tree's nodes were not counted per cell, and
    // the learning trees were never made coarser than rho = 0.64).
    const Filled free = fill(size_t(64) << 20, ps::testseed::seed(1290));
    for (size_t budget : {size_t(20000), size_t(50000), size_t(120000), free.bytes.back() / 2}) {
        const Filled f = fill(budget, ps::testseed::seed(1290));
        for (size_t pass = 0; pass < f.bytes.size(); ++pass)
            CHECK_MESSAGE(f.bytes[pass] <= budget, "GuideField with a budget of "
                                                       << budget << " bytes: " << f.bytes[pass] << " bytes after pass "
                                                       << pass << " (" << f.cells << " cells at the end)");
        CHECK_MESSAGE(f.cells > 1, "GuideField with a budget of "
                                       << budget << " bytes: expected the spatial tree cut, got " << f.cells
                                       << " cell");
    }
    CHECK_MESSAGE(free.bytes.back() > 240000,
                  "the field without a binding budget: expected it larger than the budgets "
                  "tested, got "
                      << free.bytes.back() << " bytes");
}

TEST_CASE("--guide-budget: taken by pt-guided and pt-guided-adrrs, refused by others and for a bad value") {
    for (const char* algo : {"pt-guided", "pt-guided-adrrs"}) {
        const std::unique_ptr<ps::Integrator> made = ps::makeIntegrator(algo, {{"guide-budget", "0.5"}});
        REQUIRE(made);
        CHECK(made->name == algo);
        CHECK(made->caps.cameraModels);
    }
    CHECK_THROWS_AS(ps::makeIntegrator("pt", {{"guide-budget", "1"}}), ps::OptionError);
    for (const char* bad : {"abc", "0", "0.001", "1e9", "-3", ""})
        CHECK_THROWS_AS(ps::makeIntegrator("pt-guided", {{"guide-budget", bad}}), ps::OptionError);
}

TEST_CASE("pt-guided's schedule: the pass a render of N spp ends in learns nothing, and the image is as if it learnt") {
    // A floor and a wall under a small lamp, 16 x 16 pixels; 7 spp: passes 0, 1 (iterations 1-2)
    // and 2 (iterations 3-6), the last. Against the same integrator driven iteration by iteration
    // without a budget (iterationsLeft() = -1: it learns in every pass), through lesson 3's Film.
    const ps::Scene scene = ps::parseScene(
        "camera eye 0.5 1 -2  target 0.5 0.3 1  up 0 1 0  fov 50  resolution 16 16\n"
        "material white diffuse albedo 0.6 0.6 0.6\n"
        "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material white\n"
        "quad -2 0 1  2 0 1  2 2 1  -2 2 1  material white\n"
        "quad -0.2 1.5 -0.2  0.2 1.5 -0.2  0.2 1.5 0.2  -0.2 1.5 0.2  emission 10 10 10\n"
        "render maxdepth 4\n",
        "schedule.scene (test_guide_budget.cpp)");
    const uint64_t seed = ps::testseed::seed(1291);
    for (bool adrrs : {false, true}) {
        ps::GuidedPathTracer budgeted(adrrs);
        ps::RenderOptions opt;
        opt.spp = 7;
        opt.seed = seed;
        opt.threads = 0;
        const ps::RenderResult r = ps::render(scene, budgeted, opt);

        ps::GuidedPathTracer free(adrrs), first(adrrs);  // every pass learning; iterations 0-2 alone
        ps::Film film(16, 16);
        ps::SampleStats stats;
        for (uint32_t it = 0; it < 7; ++it) {
            ps::Image image(16, 16);
            free.renderIteration(scene, it, seed, image, stats);
            film.addIteration(image);
            if (it < 3) {
                ps::Image other(16, 16);
                first.renderIteration(scene, it, seed, other, stats);
            }
        }
        const char* name = adrrs ? "pt-guided-adrrs" : "pt-guided";
        CHECK_MESSAGE(budgeted.field().records() == first.field().records(),
                      name << " at 7 spp: expected the records of iterations 0-2 alone (" << first.field().records()
                           << "; the last pass learns nothing), got " << budgeted.field().records());
        CHECK_MESSAGE(free.field().records() > first.field().records(),
                      name << " without a budget: expected pass 2 to record too, got " << free.field().records());
        const ps::Image a = r.film.mean(), b = film.mean();
        size_t differ = 0;
        for (size_t i = 0; i < a.pixels.size(); ++i)
            for (int k = 0; k < 3; ++k) differ += a.pixels[i][k] != b.pixels[i][k] ? 1 : 0;
        CHECK_MESSAGE(differ == 0, name << " at 7 spp: the image of a last pass that learns nothing must be the one "
                                           "of a pass that learns; "
                                        << differ << " pixel channels differ");
    }
}
