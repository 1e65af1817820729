// photon_figures: lesson 8's pictures of what a photon mapper has inside it, as PNGs (scripts/
// figures.sh runs it; lessons/08-photon-mapping/README.md shows them):
//   pm-photons.png      the global and the caustic map of the Cornell spheres, each photon a dot
//                       where the camera sees it, in the colour of its power
//   pm-filters.png      one global map seen directly (its radiance estimate at the first diffuse
//                       surface, k = 50) with the box, cone and Gaussian filters
//   pm-caustic-map.png  the caustic map alone, seen directly (cone filter; exposure +1)
//   pm-final-gather.png final gathering off (the global map seen directly) and on (pm)
//   pm-ic-records.png   pm with the irradiance cache, and where the cache's records are (a dot each)
// Every panel uses maps traced once (fixed seeds), the pixels averaged over several jittered
// samples. The pieces are lesson 8's (the reference, or yours with -DPATHSPACE_STUDENT=8).
//
//   photon_figures OUTDIR [--quick] [--scenes DIR]
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>
#include "08-photon-mapping/photonmap.h"
#include "image.h"
#include "render.h"
#include "scene_loader.h"
#include "tasks.h"

#ifndef PATHSPACE_SOURCE_DIR
#define PATHSPACE_SOURCE_DIR "."
#endif

using namespace ps;

namespace {

struct Settings {
    std::string out, scenes = PATHSPACE_SOURCE_DIR "/scenes";
    int resolution = 256, spp = 16, photons = 50000;
};

// scenes/NAME.scene at res x res pixels (the "resolution 256 256" of the shipped file replaced).
Scene sceneAt(const Settings& s, const std::string& name) {
    const std::string path = s.scenes + "/" + name + ".scene";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::stringstream buf;
    buf << in.rdbuf();
    std::string text = buf.str();
    const std::string from = "resolution 256 256";
    const size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error(path + ": no '" + from + "' to replace");
    text.replace(at, from.size(), "resolution " + std::to_string(s.resolution) + " " + std::to_string(s.resolution));
    return parseScene(text, path);
}

// An integrator for one figure: a radiance function of a camera ray, the maps traced once.
struct Figure : Integrator {
    std::function<Color(const Ray&, Rng&)> Li;
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
            return Li(scene.camera.generateRay(jitteredRaster(pixel, out.width, rng)), rng);
        });
    }
};

Image renderFigure(const Scene& scene, const Settings& s, const std::function<Color(const Ray&, Rng&)>& Li) {
    Figure fig;
    fig.Li = Li;
    RenderOptions opt;
    opt.spp = s.spp;
    opt.seed = 8;
    return render(scene, fig, opt).film.mean();
}

// A map's radiance estimate at the first non-specular surface the ray reaches (through mirrors
// and glass), plus the emission seen directly or through them: the map "seen directly".
Color mapSeenDirectly(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMap& map, const EstimateOptions& est,
                      bool emission) {
    Color L(0.0f);
    cameraWalk(scene, ray, rng, {scene.settings.maxDepth}, [&](const WalkVertex& v) {
        if (!v.hit) return false;
        if (emission && v.specular && v.sp.light >= 0)
            L += v.beta * emittedRadiance(scene.lights[size_t(v.sp.light)], v.sp.n, v.wo);
        const Material& m = scene.materials[size_t(v.sp.material)];
        if (m.isDelta()) return true;
        L += v.beta * radianceEstimate(map, v.sp, m, v.wo, est);
        return false;
    });
    return L;
}

// Panels side by side, 4 black pixels between them.
Image sideBySide(const std::vector<Image>& panels) {
    const int gap = 4, h = panels[0].height;
    int w = -gap;
    for (const Image& p : panels) w += p.width + gap;
    Image out(w, h);
    int x0 = 0;
    for (const Image& p : panels) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < p.width; ++x) out.at(x0 + x, y) = p.at(x, y);
        x0 += p.width + gap;
    }
    return out;
}

void plot(Image& img, const Vec2& r, const Color& c, int radius = 0) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = int(r.x) + dx, y = int(r.y) + dy;
            if (x >= 0 && y >= 0 && x < img.width && y < img.height) img.at(x, y) = c;
        }
}

// Is p (on a surface) seen by the pinhole? Its raster position if so.
bool seen(const Scene& scene, const Vec3& p, Vec2& raster) {
    if (!scene.camera.rasterPosition(p, raster)) return false;
    const Vec3 d = p - scene.camera.position();
    const float dist = glm::length(d);
    return !scene.occluded(Ray(scene.camera.position(), d / dist, dist * (1.0f - 1e-4f)));
}

// The photons of a map the camera sees, each a dot in the colour of its power (brightest
// channel 1), on black.
Image photonDots(const Scene& scene, const PhotonMap& map) {
    Image img(scene.camera.width(), scene.camera.height());
    for (size_t i = 1; i <= map.size(); ++i) {
        const Photon& ph = map.nodes[i];
        Vec2 r;
        if (!seen(scene, ph.p, r)) continue;
        const float peak = std::max(ph.power.r, std::max(ph.power.g, ph.power.b));
        if (peak > 0.0f) plot(img, r, ph.power / peak);
    }
    return img;
}

void write(const Settings& s, const std::string& name, const Image& img, float exposure = 0.0f) {
    const std::string path = s.out + "/" + name;
    writePNG(path, img, exposure);
    std::printf("photon_figures: wrote %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") {
            s.resolution = 64;
            s.spp = 2;
            s.photons = 5000;
        } else if (a == "--scenes" && i + 1 < argc) {
            s.scenes = argv[++i];
        } else if (a == "--help" || a == "-h" || a.rfind("-", 0) == 0 || !s.out.empty()) {
            std::fprintf(a == "--help" || a == "-h" ? stdout : stderr,
                         "usage: photon_figures OUTDIR [--quick] [--scenes DIR]\n"
                         "Writes lesson 8's figures pm-photons, pm-filters, pm-caustic-map, pm-final-gather and\n"
                         "pm-ic-records (.png) into OUTDIR. --quick: 64 x 64 pixels, few photons.\n");
            return a == "--help" || a == "-h" ? 0 : 2;
        } else {
            s.out = a;
        }
    }
    if (s.out.empty()) {
        std::fprintf(stderr, "usage: photon_figures OUTDIR [--quick] [--scenes DIR]\n");
        return 2;
    }
    try {
        const Scene scene = sceneAt(s, "cornell-spheres");
        const float R = scene.radius;
        SampleStats stats;
        PhotonMaps maps;
        maps.global = tracePhotonMap(scene, MapKind::Global, s.photons, scene.settings.maxDepth, 81, 0, stats);
        maps.caustic = tracePhotonMap(scene, MapKind::Caustic, 4 * s.photons, scene.settings.maxDepth, 82, 0, stats);

        write(s, "pm-photons.png", sideBySide({photonDots(scene, maps.global), photonDots(scene, maps.caustic)}));

        std::vector<Image> filters;
        for (Filter f : {Filter::Box, Filter::Cone, Filter::Gaussian}) {
            EstimateOptions est;
            est.filter = f;
            est.k = 50;
            est.maxRadius = 0.1f * R;
            filters.push_back(renderFigure(scene, s, [&](const Ray& ray, Rng& rng) {
                return mapSeenDirectly(scene, ray, rng, maps.global, est, true);
            }));
        }
        write(s, "pm-filters.png", sideBySide(filters));

        EstimateOptions caustic;
        caustic.filter = Filter::Cone;
        caustic.k = 50;
        caustic.maxRadius = 0.02f * R;
        write(s, "pm-caustic-map.png",
              renderFigure(scene, s,
                           [&](const Ray& ray, Rng& rng) {
                               return mapSeenDirectly(scene, ray, rng, maps.caustic, caustic, false);
                           }),
              1.0f);

        PmOptions opt;
        opt.maxDepth = scene.settings.maxDepth;
        opt.globalEstimate.k = 50;
        opt.globalEstimate.maxRadius = 0.1f * R;
        opt.causticEstimate = caustic;
        const Image gatherOn =
            renderFigure(scene, s, [&](const Ray& ray, Rng& rng) { return LiPhotonMap(scene, ray, rng, maps, opt); });
        write(s, "pm-final-gather.png", sideBySide({filters[0], gatherOn}));

        // The irradiance cache of pm-ic (its settings), filled once.
        opt.minR = kCacheMinR * R;
        opt.maxR = kCacheMaxR * R;
        const IrradianceCache cache = buildIrradianceCache(scene, maps.global, opt, kCacheErrorBound,
                                                           scene.camera.width(), scene.camera.height(), 83, 0, stats);
        opt.cache = &cache;
        const Image cached =
            renderFigure(scene, s, [&](const Ray& ray, Rng& rng) { return LiPhotonMap(scene, ray, rng, maps, opt); });
        Image records = cached;
        for (Color& c : records.pixels) c *= 0.3f;
        for (const IrradianceRecord& rec : cache.records) {
            Vec2 r;
            if (scene.camera.rasterPosition(rec.p, r)) plot(records, r, Color(1.0f, 0.3f, 0.1f));
        }
        write(s, "pm-ic-records.png", sideBySide({cached, records}));
        std::printf("photon_figures: %zu global and %zu caustic photons, %zu cache records (a = %.2f), %llu NaN/Inf\n",
                    maps.global.size(), maps.caustic.size(), cache.records.size(), double(cache.a),
                    (unsigned long long)stats.bad());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon_figures: %s\n", e.what());
        return 1;
    }
}
