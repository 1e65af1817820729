// bvh_bench: figures for the framework's BVH. For each scene: build time, node count and
// depth; then the throughput (Mrays/s) of primary, incoherent and shadow rays with 1 and 2
// threads. A benchmark, never a test: nothing is timed against a threshold. bench/README.md
// explains the columns and lists the figures measured on the course machine.
//
// Every ray is generated from fixed seeds (ps::taskRng) before the clock starts, so the
// timed loops only trace, and the hit counts (checksums) are the same for every run and
// every thread count.
#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>
#include "rng.h"
#include "sampling.h"
#include "scene.h"
#include "scene_loader.h"

#ifndef PATHSPACE_SOURCE_DIR
#define PATHSPACE_SOURCE_DIR "."
#endif

using namespace ps;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Fixed seeds, one per kind of ray.
constexpr uint64_t kSeedPrimary = 0x5eed0001, kSeedIncoherent = 0x5eed0002, kSeedShadow = 0x5eed0003;
constexpr int kThreadCounts[] = {1, 2};

struct Options {
    bool quick = false;
    std::string scenesDir = PATHSPACE_SOURCE_DIR "/scenes";
};

// How much work one scene gets. A figure is the best of `runs` runs; a run traces the primary
// pool primaryRepeat times and the incoherent and shadow pools once each.
struct Workload {
    int primaryPasses = 1;      // jittered passes over all pixels in the primary pool
    size_t poolSize = 1 << 20;  // incoherent and shadow pools
    int primaryRepeat = 1;      // passes over the primary pool per run (the others: one)
    int runs = 3;
    int buildRuns = 5;
};

struct Checksum {
    uint64_t hits = 0;
    uint64_t primSum = 0;  // sum of (hit primitive + 1): catches a different closest hit
    bool operator==(const Checksum& o) const { return hits == o.hits && primSum == o.primSum; }
    bool operator!=(const Checksum& o) const { return !(*this == o); }
};

struct Result {
    double mrays = 0.0;  // best run
    uint64_t raysPerRun = 0;
    Checksum sum;  // of one run
};

// One pass over rays[0, n) with the threads omp_set_num_threads chose.
template <bool AnyHit>
Checksum traceOnce(const Scene& scene, const std::vector<Ray>& rays, size_t n) {
    uint64_t hits = 0, primSum = 0;
    const int64_t count = static_cast<int64_t>(n);
#pragma omp parallel for schedule(dynamic, 1024) reduction(+ : hits, primSum)
    for (int64_t i = 0; i < count; ++i) {
        if constexpr (AnyHit) {
            hits += scene.occluded(rays[i]) ? 1 : 0;
        } else {
            Ray r = rays[i];
            SurfacePoint sp;
            if (scene.intersect(r, sp)) {
                ++hits;
                primSum += sp.prim + 1u;
            }
        }
    }
    return {hits, primSum};
}

template <bool AnyHit>
Result measure(const Scene& scene, const std::vector<Ray>& pool, int threads, int repeat, int runs, bool& consistent) {
    omp_set_num_threads(threads);
    traceOnce<AnyHit>(scene, pool, std::min<size_t>(pool.size(), 1 << 16));  // warm-up
    Result res;
    res.raysPerRun = static_cast<uint64_t>(pool.size()) * repeat;
    double best = 1e300;
    for (int run = 0; run < runs; ++run) {
        Checksum sum;
        const auto t0 = Clock::now();
        for (int p = 0; p < repeat; ++p) {
            const Checksum c = traceOnce<AnyHit>(scene, pool, pool.size());
            sum.hits += c.hits;
            sum.primSum += c.primSum;
        }
        best = std::min(best, secondsSince(t0));
        if (run == 0) res.sum = sum;
        else if (sum != res.sum) consistent = false;
    }
    res.mrays = static_cast<double>(res.raysPerRun) / best * 1e-6;
    return res;
}

// Camera rays through every pixel, jittered within the pixel, `passes` times.
std::vector<Ray> primaryRays(const Scene& scene, int passes) {
    const int w = scene.camera.width(), h = scene.camera.height();
    std::vector<Ray> rays;
    rays.reserve(static_cast<size_t>(passes) * w * h);
    for (int pass = 0; pass < passes; ++pass)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                Rng rng = taskRng(kSeedPrimary, static_cast<uint32_t>(pass), static_cast<uint32_t>(y * w + x));
                const Vec2 u = rng.uniform2();
                rays.push_back(scene.camera.generateRay(Vec2(x + u.x, y + u.y)));
            }
    return rays;
}

// A surface point seen through a pixel centre, with the normal turned towards the camera.
struct HitPoint {
    SurfacePoint sp;
    Vec3 facing;
};

std::vector<HitPoint> visiblePoints(const Scene& scene) {
    const int w = scene.camera.width(), h = scene.camera.height();
    std::vector<HitPoint> pts;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Ray r = scene.camera.generateRay(Vec2(x + 0.5f, y + 0.5f));
            HitPoint hp;
            if (!scene.intersect(r, hp.sp)) continue;
            hp.facing = glm::dot(hp.sp.n, r.d) < 0.0f ? hp.sp.n : -hp.sp.n;
            pts.push_back(hp);
        }
    return pts;
}

uint32_t pick(Rng& rng, size_t n) { return static_cast<uint32_t>(rng.nextU32() % n); }

// Diffuse bounces: a random visible point, a cosine-weighted direction on its camera side.
std::vector<Ray> incoherentRays(const Scene& scene, const std::vector<HitPoint>& pts, size_t n) {
    std::vector<Ray> rays(n);
    for (size_t i = 0; i < n; ++i) {
        Rng rng = taskRng(kSeedIncoherent, 0, static_cast<uint32_t>(i));
        const HitPoint& hp = pts[pick(rng, pts.size())];
        const Vec3 dir = Frame(hp.facing).toWorld(sampleCosineHemisphere(rng.uniform2()));
        rays[i] = scene.spawnRay(hp.sp, dir);
    }
    return rays;
}

// Visibility between two different random visible points.
std::vector<Ray> shadowRays(const Scene& scene, const std::vector<HitPoint>& pts, size_t n) {
    std::vector<Ray> rays(n);
    for (size_t i = 0; i < n; ++i) {
        Rng rng = taskRng(kSeedShadow, 0, static_cast<uint32_t>(i));
        for (;;) {
            const uint32_t a = pick(rng, pts.size());
            const uint32_t b = static_cast<uint32_t>((a + 1 + pick(rng, pts.size() - 1)) % pts.size());
            if (glm::length(pts[b].sp.p - pts[a].sp.p) > 0.0f) {
                rays[i] = scene.spawnRayTo(pts[a].sp, pts[b].sp);
                break;
            }
        }
    }
    return rays;
}

// A bumpy sphere (a latitude-longitude grid displaced by a few sines) above a floor, seen by
// a 512 x 512 camera. rings * segments * 2 triangles, minus the poles' degenerate ones.
Scene makeNoisySphere(int rings, int segments) {
    Scene s;
    s.path = "(generated noisy sphere)";
    Material grey;
    grey.name = "grey";
    grey.kind = BSDFKind::Diffuse;
    grey.albedo = Color(0.7f);
    s.materials.push_back(grey);

    const Vec3 c(0.0f, 1.1f, 0.0f);
    auto radius = [](const Vec3& d) {
        return 1.0f + 0.10f * std::sin(6.0f * d.x + 0.3f) * std::sin(7.0f * d.y + 1.1f) * std::sin(5.0f * d.z + 2.0f) +
               0.03f * std::sin(23.0f * d.x + 17.0f * d.y + 0.7f) +
               0.015f * std::sin(41.0f * d.z - 37.0f * d.x + 29.0f * d.y);
    };
    std::vector<Vec3> v(static_cast<size_t>(rings + 1) * segments);
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const float theta = kPi * i / rings, phi = 2.0f * kPi * j / segments;
            const Vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            v[static_cast<size_t>(i) * segments + j] = c + radius(d) * d;
        }
    auto addTriangle = [&](Vec3 p0, Vec3 p1, Vec3 p2) {
        if (glm::dot(glm::cross(p1 - p0, p2 - p0), p0 + p1 + p2 - 3.0f * c) < 0.0f) std::swap(p1, p2);  // outward
        s.triangles.push_back(Triangle{p0, p1, p2});
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const int jn = (j + 1) % segments;
            const Vec3& a = v[static_cast<size_t>(i) * segments + j];
            const Vec3& b = v[static_cast<size_t>(i) * segments + jn];
            const Vec3& cc = v[static_cast<size_t>(i + 1) * segments + j];
            const Vec3& d = v[static_cast<size_t>(i + 1) * segments + jn];
            if (i > 0) addTriangle(a, b, d);           // the top ring's first triangle is degenerate
            if (i < rings - 1) addTriangle(a, d, cc);  // the bottom ring's second one is
        }
    const float f = 6.0f;  // the floor, facing up
    s.triangles.push_back(Triangle{Vec3(-f, 0, -f), Vec3(-f, 0, f), Vec3(f, 0, f)});
    s.triangles.push_back(Triangle{Vec3(-f, 0, -f), Vec3(f, 0, f), Vec3(f, 0, -f)});

    for (uint32_t t = 0; t < s.triangles.size(); ++t) {
        Primitive p;
        p.shape = ShapeKind::Triangle;
        p.index = t;
        p.material = 0;
        s.prims.push_back(p);
    }
    s.camera = Camera(Vec3(0.0f, 1.8f, -4.2f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), 40.0f, 512, 512);
    s.finalize();
    return s;
}

// Best of `runs` builds over the scene's primitive boxes (the same boxes Scene::finalize uses).
double buildMs(const Scene& scene, int runs) {
    std::vector<AABB> boxes(scene.prims.size());
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Primitive& pr = scene.prims[i];
        boxes[i] =
            pr.shape == ShapeKind::Triangle ? scene.triangles[pr.index].bounds() : scene.spheres[pr.index].bounds();
    }
    double best = 1e300;
    for (int r = 0; r < runs; ++r) {
        BVH bvh;
        const auto t0 = Clock::now();
        bvh.build(boxes);
        best = std::min(best, secondsSince(t0));
    }
    return best * 1e3;
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            size_t k = line.find(':');
            if (k != std::string::npos) return line.substr(line.find_first_not_of(" \t", k + 1));
        }
    return "unknown CPU";
}

std::string compiler() {
#if defined(__clang__)
    return "clang " __clang_version__;
#elif defined(__GNUC__)
    return "g++ " __VERSION__;
#else
    return "unknown compiler";
#endif
}

std::string millions(uint64_t n) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2fM", static_cast<double>(n) * 1e-6);
    return buf;
}

struct Bench {
    std::string name;
    Scene scene;
    Workload work;
};

void usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: bvh_bench [--quick] [--scenes DIR]\n"
                 "Prints the framework BVH's build time, size and ray throughput (Mrays/s) for\n"
                 "primary, incoherent (diffuse bounce) and shadow rays, with 1 and 2 threads, on the\n"
                 "Cornell box and a generated mesh of 159k triangles. Fixed seeds and ray counts.\n"
                 "  --quick       few rays, one run each (a smoke test; the figures mean little)\n"
                 "  --scenes DIR  where cornell-box.scene is (default: %s)\n"
                 "  --help        this text\n",
                 PATHSPACE_SOURCE_DIR "/scenes");
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            usage(stdout);
            return 0;
        }
        if (a == "--quick") {
            opt.quick = true;
            continue;
        }
        if (a == "--scenes" && i + 1 < argc) {
            opt.scenesDir = argv[++i];
            continue;
        }
        if (a.rfind("--scenes=", 0) == 0) {
            opt.scenesDir = a.substr(9);
            continue;
        }
        std::fprintf(stderr, "bvh_bench: unknown or incomplete option '%s'\n", a.c_str());
        usage(stderr);
        return 2;
    }

    std::vector<Bench> benches;
    try {
        // Rays per run: about 0.15-0.5 s with one thread on the course machine.
        Bench cornell{"cornell-box", loadScene(opt.scenesDir + "/cornell-box.scene"), {}};
        cornell.work.primaryPasses = 16;  // 256 x 256 pixels: a pool of 1M camera rays
        cornell.work.primaryRepeat = 3;
        cornell.work.poolSize = 1 << 20;
        cornell.work.buildRuns = 200;
        benches.push_back(std::move(cornell));

        Bench mesh{"noisy-sphere", makeNoisySphere(200, 400), {}};
        mesh.work.primaryPasses = 4;  // 512 x 512 pixels: a pool of 1M camera rays
        mesh.work.primaryRepeat = 1;
        mesh.work.poolSize = 1 << 19;
        mesh.work.buildRuns = 5;
        benches.push_back(std::move(mesh));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bvh_bench: %s\n", e.what());
        return 1;
    }
    if (opt.quick)
        for (Bench& b : benches) {
            b.work = Workload{};
            b.work.primaryPasses = 1;
            b.work.poolSize = 1 << 14;
            b.work.runs = 1;
            b.work.buildRuns = 1;
        }

    std::printf("bvh_bench%s: %d logical CPUs (nproc), %s; %s, OpenMP %d%s\n", opt.quick ? " --quick" : "",
                omp_get_num_procs(), cpuModel().c_str(), compiler().c_str(), _OPENMP,
#ifdef NDEBUG
                ""
#else
                ", assertions ON (not a Release build: figures are not representative)"
#endif
    );
    std::printf("Mrays/s: best of %d runs with the same rays; rays are generated before timing (fixed seeds)\n\n",
                opt.quick ? 1 : Workload{}.runs);
    std::printf("%-14s %8s %9s %8s %6s %8s %16s %19s %15s\n", "scene", "tris", "build ms", "nodes", "depth", "threads",
                "primary Mrays/s", "incoherent Mrays/s", "shadow Mrays/s");
    std::fflush(stdout);

    struct Summary {
        std::string name;
        uint64_t rays[3];
        Checksum sums[3];
        size_t visible;
        int passes, width, height;
    };
    std::vector<Summary> summaries;
    bool consistent = true;
    const auto tStart = Clock::now();
    for (Bench& b : benches) {
        const Scene& s = b.scene;
        const double ms = buildMs(s, b.work.buildRuns);

        const std::vector<Ray> primary = primaryRays(s, b.work.primaryPasses);
        const std::vector<HitPoint> pts = visiblePoints(s);
        if (pts.size() < 2) {
            std::fprintf(stderr, "bvh_bench: %s: the camera sees fewer than 2 surface points\n", b.name.c_str());
            return 1;
        }
        const std::vector<Ray> incoherent = incoherentRays(s, pts, b.work.poolSize);
        const std::vector<Ray> shadow = shadowRays(s, pts, b.work.poolSize);

        Summary sum{b.name,           {}, {}, pts.size(), b.work.primaryPasses * b.work.primaryRepeat, s.camera.width(),
                    s.camera.height()};
        for (int threads : kThreadCounts) {
            const Result p = measure<false>(s, primary, threads, b.work.primaryRepeat, b.work.runs, consistent);
            const Result in = measure<false>(s, incoherent, threads, 1, b.work.runs, consistent);
            const Result sh = measure<true>(s, shadow, threads, 1, b.work.runs, consistent);
            std::printf("%-14s %8zu %9.3f %8zu %6d %8d %16.2f %19.2f %15.2f\n", b.name.c_str(), s.triangles.size(), ms,
                        s.bvh.nodes().size(), s.bvh.depth(), threads, p.mrays, in.mrays, sh.mrays);
            std::fflush(stdout);
            const Result* rs[3] = {&p, &in, &sh};
            for (int k = 0; k < 3; ++k) {
                if (threads == kThreadCounts[0]) {
                    sum.rays[k] = rs[k]->raysPerRun;
                    sum.sums[k] = rs[k]->sum;
                } else if (rs[k]->sum != sum.sums[k]) {
                    consistent = false;
                }
            }
        }
        summaries.push_back(sum);
    }

    std::printf("\nrays per run and checksums (hits per run, the same for every run and thread count):\n");
    for (const Summary& s : summaries) {
        const char* kinds[3] = {"primary", "incoherent", "shadow"};
        char what[3][96];
        std::snprintf(what[0], sizeof what[0], "%d jittered pass%s over %d x %d pixels", s.passes,
                      s.passes == 1 ? "" : "es", s.width, s.height);
        std::snprintf(what[1], sizeof what[1], "cosine-weighted bounces from %zu visible points", s.visible);
        std::snprintf(what[2], sizeof what[2], "between random pairs of those points");
        for (int k = 0; k < 3; ++k)
            std::printf("  %-14s %-10s %8s rays %10llu hits  (%s)\n", k == 0 ? s.name.c_str() : "", kinds[k],
                        millions(s.rays[k]).c_str(), static_cast<unsigned long long>(s.sums[k].hits), what[k]);
    }
    std::printf("total time %.1f s\n", secondsSince(tStart));
    if (!consistent) {
        std::fprintf(stderr,
                     "bvh_bench: checksums differ between runs or thread counts: traversal is not deterministic\n");
        return 1;
    }
    return 0;
}
