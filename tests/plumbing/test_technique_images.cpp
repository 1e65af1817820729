// Per-technique images (`pathspace pyramid`, framework/integrator.h: Integrator::techniques), for
// EVERY integrator that registers them (lesson 7's bpt, lesson 13's vcm and its special cases, and
// any later one as soon as it registers): the MIS-weighted cells of all rows add up to the
// integrator's own image of the same seed and samples, pixel by pixel, when the rows cover every
// path length the render samples (maxLength = maxDepth + 1). A cell left out of the rows, a
// technique recorded in the wrong row or twice, or a pyramid whose iterations are not the render's
// (another radius, another light pass) breaks the sum. The layout's cells are the rendered ones.
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include "integrator.h"
#include "lesson_files.h"
#include "render.h"
#include "scene_loader.h"
#include "seed.h"

using namespace ps;

TEST_CASE("per-technique images: the weighted cells of every row add up to the integrator's image") {
    const int maxLength = 3, spp = 3;
    // Mirror and glass (merges through them), and a point light (no s = 0).
    for (const char* file : {"scenes/cornell-spheres.scene", "scenes/cornell-point-light.scene"}) {
        Scene scene = testfiles::loadSceneAt(file, 12, 12);
        scene.settings.maxDepth = maxLength - 1;
        int tested = 0;
        for (const IntegratorInfo& info : integratorList()) {
            if (!info.caps.techniqueImages) continue;
            CAPTURE(file);
            CAPTURE(info.name);
            const uint64_t seed = testseed::seed(5);
            std::unique_ptr<Integrator> integrator = makeIntegrator(info.name);
            TechniqueImagesOptions o;
            o.maxLength = maxLength;
            o.spp = spp;
            o.seed = seed;
            const TechniquePyramid p = integrator->techniques.render(scene, o);
            const std::vector<TechniqueRow> layout = integrator->techniques.layout(maxLength);
            REQUIRE(p.rows.size() == layout.size());
            Image sum(scene.camera.width(), scene.camera.height());
            for (size_t r = 0; r < p.rows.size(); ++r) {
                REQUIRE(p.rows[r].cells.size() == layout[r].cells.size());
                for (size_t c = 0; c < p.rows[r].cells.size(); ++c) {
                    CHECK(p.rows[r].cells[c].name == layout[r].cells[c].name);
                    const Image& w = p.rows[r].cells[c].weighted;
                    for (size_t q = 0; q < sum.pixels.size(); ++q) sum.pixels[q] += w.pixels[q];
                }
            }
            RenderOptions ro;
            ro.spp = spp;
            ro.seed = seed;
            const Image image = render(scene, *integrator, ro).film.mean();
            // The same samples, added in another order (float rounding: relative 1e-4 of the
            // image's brightest channel; measured 2e-5 at most).
            float peak = 0.0f, worst = 0.0f;
            int at = -1;
            for (const Color& c : image.pixels) peak = std::max({peak, c.r, c.g, c.b});
            for (size_t q = 0; q < sum.pixels.size(); ++q) {
                const Color d = sum.pixels[q] - image.pixels[q];
                const float e = std::max({std::fabs(d.r), std::fabs(d.g), std::fabs(d.b)});
                if (e > worst) worst = e, at = int(q);
            }
            CAPTURE(at);
            CHECK_MESSAGE(worst <= 1e-4f * peak,
                          "the weighted cells differ from the image by " << worst << " (peak " << peak << ")");
            ++tested;
        }
        CHECK(tested >= 2);
    }
}
