// Lesson 12's plumbing, ungraded: the learned field's memory budget (GuideField::endPass, the
// algorithm option --guide-budget MB that lesson 12 registers for pt-guided and pt-guided-adrrs).
#include <doctest/doctest.h>
#include <string>
#include <vector>
#include "12-path-guiding/guiding.h"
#include "errors.h"
#include "integrator.h"
#include "rng.h"
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
