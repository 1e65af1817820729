// bvh_bench: figures for the framework's BVH (framework/bvh.h), through Scene::intersect and
// Scene::occluded as the renderers call them, on the Cornell box, a generated mesh and, when
// their Debian packages are installed, the Stanford bunny (glmark2-data) and the OpenFOAM
// motorbike (openfoam-examples). Three ray sets per scene, generated from fixed seeds before any
// clock starts: primary (a 1024 x 1024 pinhole camera), incoherent (origin uniform in the
// scene's bounds, direction uniform), shadow (segments between two uniform points, any hit).
// When Embree 3 was found at configure time (libembree-dev; a benchmark-only option, never a
// dependency of the course), Embree traces the same rays, pass by pass interleaved with ours so
// that machine load hits both alike, and the table shows the ratio of the two speeds.
// Every hit is checked: against Embree's (a disagreement is settled by brute force with the
// framework's own triangle test) and, for a sample of rays, against brute force.
// A benchmark, never a test: nothing is timed against a threshold. bench/README.md explains it.
#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>
#include "bench_common.h"
#include "rng.h"
#include "scene.h"
#include "scene_loader.h"
#ifdef PATHSPACE_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

#ifndef PATHSPACE_SOURCE_DIR
#define PATHSPACE_SOURCE_DIR "."
#endif

using namespace ps;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
using bench::loadAverage;
using bench::median;
using bench::processCpuSeconds;  // for --cpu-time

const char* const kBunny = "/usr/share/glmark2/models/bunny.obj";
const char* const kMotorbike = "/usr/share/doc/openfoam-examples/examples/resources/geometry/motorBike.obj.gz";

struct Options {
    bool quick = false;
    int passes = 5;    // timed passes per tracer, ray set and thread count
    std::string only;  // one scene by name (empty: all)
    std::vector<int> threads = {1, 2};
    std::string sets;             // ray sets to run, comma-separated (empty: all)
    std::string tracer = "both";  // ours | embree | both; one tracer alone: no checks (profiling)
    int res = 1024;               // primary rays res^2; the other sets as many
    bool cpuTime = false;         // time the tracing passes in process CPU seconds, not wall-clock
    std::string scenesDir = PATHSPACE_SOURCE_DIR "/scenes";
};

// ---- scenes -----------------------------------------------------------------------------------

// A scene of bare triangles (primitive i = triangle i), one grey material, a camera looking at
// the bounds' centre from direction `from` with the bounding sphere filling its 1024 x 1024 view.
Scene meshScene(const std::string& name, std::vector<Triangle> tris, Vec3 from, int res) {
    Scene s;
    s.path = name;
    Material grey;
    grey.kind = BSDFKind::Diffuse;
    s.materials.push_back(grey);
    s.triangles = std::move(tris);
    for (uint32_t t = 0; t < s.triangles.size(); ++t) s.prims.push_back({ShapeKind::Triangle, t, 0, -1});
    AABB b;
    for (const Triangle& t : s.triangles) b.expand(t.bounds());
    const float r = 0.5f * glm::length(b.extent()), fov = 40.0f;
    const Vec3 eye = b.center() + glm::normalize(from) * (r / std::sin(0.5f * fov * kPi / 180.0f));
    s.camera = Camera(eye, b.center(), Vec3(0, 1, 0), fov, res, res);
    s.finalize();
    return s;
}

// The triangles of an OBJ file (v and f lines; faces fanned; `gzip -dc` reads a .gz).
std::vector<Triangle> readObj(const std::string& path) {
    const bool gz = path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
    FILE* f = gz ? popen(("gzip -dc '" + path + "'").c_str(), "r") : std::fopen(path.c_str(), "r");
    if (!f) throw std::runtime_error("cannot read " + path);
    std::vector<Vec3> v;
    std::vector<Triangle> tris;
    char line[4096];
    while (std::fgets(line, sizeof line, f)) {
        if (line[0] == 'v' && line[1] == ' ') {
            Vec3 p;
            if (std::sscanf(line + 2, "%f %f %f", &p.x, &p.y, &p.z) == 3) v.push_back(p);
        } else if (line[0] == 'f' && line[1] == ' ') {
            std::vector<long> idx;
            for (char* c = line + 2; *c;) {
                char* end;
                const long i = std::strtol(c, &end, 10);
                if (end == c) break;
                idx.push_back(i < 0 ? long(v.size()) + i : i - 1);
                c = end;
                while (*c && *c != ' ' && *c != '\t') ++c;  // skip /vt/vn
            }
            for (size_t k = 2; k < idx.size(); ++k) {
                if (idx[0] < 0 || size_t(std::max({idx[0], idx[k - 1], idx[k]})) >= v.size()) continue;
                tris.push_back({v[size_t(idx[0])], v[size_t(idx[k - 1])], v[size_t(idx[k])]});
            }
        }
    }
    if (gz) pclose(f);
    else std::fclose(f);
    if (tris.empty()) throw std::runtime_error(path + ": no triangles");
    return tris;
}

// A bumpy sphere (a latitude-longitude grid displaced by a few sines) above a floor: a mesh that
// needs no package. rings * segments * 2 triangles, minus the poles' degenerate ones.
std::vector<Triangle> noisySphere(int rings, int segments) {
    auto radius = [](const Vec3& d) {
        return 1.0f + 0.10f * std::sin(6.0f * d.x + 0.3f) * std::sin(7.0f * d.y + 1.1f) * std::sin(5.0f * d.z + 2.0f) +
               0.03f * std::sin(23.0f * d.x + 17.0f * d.y + 0.7f) +
               0.015f * std::sin(41.0f * d.z - 37.0f * d.x + 29.0f * d.y);
    };
    const Vec3 c(0.0f, 1.1f, 0.0f);
    std::vector<Vec3> v(size_t(rings + 1) * segments);
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const float theta = kPi * i / rings, phi = 2.0f * kPi * j / segments;
            const Vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            v[size_t(i) * segments + j] = c + radius(d) * d;
        }
    std::vector<Triangle> tris;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const int jn = (j + 1) % segments;
            const Vec3 &a = v[size_t(i) * segments + j], &b = v[size_t(i) * segments + jn];
            const Vec3 &cc = v[size_t(i + 1) * segments + j], &d = v[size_t(i + 1) * segments + jn];
            if (i > 0) tris.push_back({a, b, d});
            if (i < rings - 1) tris.push_back({a, d, cc});
        }
    const float f = 6.0f;
    tris.push_back({Vec3(-f, 0, -f), Vec3(-f, 0, f), Vec3(f, 0, f)});
    tris.push_back({Vec3(-f, 0, -f), Vec3(f, 0, f), Vec3(f, 0, -f)});
    return tris;
}

// ---- rays -------------------------------------------------------------------------------------

constexpr uint64_t kSeedPrimary = 0x5eed0001, kSeedIncoherent = 0x5eed0002, kSeedShadow = 0x5eed0003;

struct RaySet {
    const char* name;
    bool anyHit;
    std::vector<Ray> rays;
};

std::vector<RaySet> makeRays(const Scene& s, size_t n) {
    std::vector<RaySet> sets = {{"primary", false, {}}, {"incoherent", false, {}}, {"shadow", true, {}}};
    const int w = s.camera.width(), h = s.camera.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Rng rng = taskRng(kSeedPrimary, 0, uint32_t(y * w + x));
            const Vec2 u = rng.uniform2();
            sets[0].rays.push_back(s.camera.generateRay(Vec2(x + u.x, y + u.y)));
        }
    const Vec3 lo = s.bounds.lo, ext = s.bounds.extent();
    auto point = [&](Rng& rng) { return lo + ext * Vec3{rng.uniform(), rng.uniform(), rng.uniform()}; };
    for (size_t i = 0; i < n; ++i) {
        Rng rng = taskRng(kSeedIncoherent, 0, uint32_t(i));
        const Vec3 o = point(rng);
        const float z = 1.0f - 2.0f * rng.uniform(), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * rng.uniform();
        sets[1].rays.emplace_back(o, Vec3(r * std::cos(phi), r * std::sin(phi), z));
    }
    for (size_t i = 0; i < n;) {
        Rng rng = taskRng(kSeedShadow, 0, uint32_t(i));
        const Vec3 a = point(rng), b = point(rng);
        const float len = glm::length(b - a);
        if (len > 0.0f) sets[2].rays.emplace_back(a, (b - a) / len, len), ++i;
    }
    return sets;
}

// ---- tracers ----------------------------------------------------------------------------------

struct Hit {
    uint32_t prim = kNoPrimitive;  // for any-hit rays: 0 = occluded
    float t = kInf;
};

void traceOurs(const Scene& s, const RaySet& set, std::vector<Hit>& out) {
    const int64_t n = int64_t(set.rays.size());
#pragma omp parallel for schedule(dynamic, 1024)
    for (int64_t i = 0; i < n; ++i) {
        if (set.anyHit) {
            out[i].prim = s.occluded(set.rays[i]) ? 0 : kNoPrimitive;
        } else {
            Ray r = set.rays[i];
            SurfacePoint sp;
            out[i] = s.intersect(r, sp) ? Hit{sp.prim, r.tMax} : Hit{};
        }
    }
}

#ifdef PATHSPACE_HAVE_EMBREE
struct Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    explicit Embree(const char* config) : device(rtcNewDevice(config)) {}
    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    // Embree's default build (RTC_BUILD_QUALITY_MEDIUM) over one triangle geometry.
    void build(const std::vector<Triangle>& tris) {
        if (scene) rtcReleaseScene(scene);
        scene = rtcNewScene(device);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), 3 * tris.size() + 1));
        unsigned* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris.size()));
        for (size_t i = 0; i < tris.size(); ++i) {
            const Vec3* p[3] = {&tris[i].p0, &tris[i].p1, &tris[i].p2};
            for (int k = 0; k < 3; ++k) {
                for (int a = 0; a < 3; ++a) v[9 * i + 3 * k + a] = (*p[k])[a];
                idx[3 * i + k] = unsigned(3 * i + k);
            }
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
    }
    void trace(const RaySet& set, std::vector<Hit>& out) const {
        const int64_t n = int64_t(set.rays.size());
#pragma omp parallel for schedule(dynamic, 1024)
        for (int64_t i = 0; i < n; ++i) {
            const Ray& r = set.rays[i];
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            RTCRayHit rh;
            rh.ray.org_x = r.o.x, rh.ray.org_y = r.o.y, rh.ray.org_z = r.o.z;
            rh.ray.dir_x = r.d.x, rh.ray.dir_y = r.d.y, rh.ray.dir_z = r.d.z;
            rh.ray.tnear = 0.0f, rh.ray.tfar = r.tMax, rh.ray.time = 0.0f;
            rh.ray.mask = ~0u, rh.ray.id = 0, rh.ray.flags = 0;
            if (set.anyHit) {
                rtcOccluded1(scene, &ctx, &rh.ray);
                out[i].prim = rh.ray.tfar < 0.0f ? 0 : kNoPrimitive;
            } else {
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene, &ctx, &rh);
                out[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? Hit{} : Hit{rh.hit.primID, rh.ray.tfar};
            }
        }
    }
};
#endif

// ---- checks -----------------------------------------------------------------------------------

// Closest (or any) hit by testing every triangle with the framework's triangle test.
Hit bruteForce(const Scene& s, const Ray& ray) {
    const WatertightRay wr(ray);
    Hit best;
    for (uint32_t i = 0; i < s.triangles.size(); ++i) {
        float t, b1, b2;
        if (intersectTriangle(ray, wr, s.triangles[i], t, b1, b2) && t < best.t) best = {i, t};
    }
    return best;
}

// Ours equals brute force: the same t to the bit, and the same primitive or one at that same t.
bool agreesWithBruteForce(const Scene& s, const Ray& ray, bool anyHit, const Hit& ours) {
    const Hit ref = bruteForce(s, ray);
    if (anyHit) return (ours.prim != kNoPrimitive) == (ref.prim != kNoPrimitive);
    if (ours.prim == kNoPrimitive || ref.prim == kNoPrimitive) return ours.prim == ref.prim;
    if (ours.t != ref.t) return false;
    float t, b1, b2;
    return ours.prim == ref.prim ||
           (intersectTriangle(ray, WatertightRay(ray), s.triangles[ours.prim], t, b1, b2) && t == ref.t);
}

// Two tracers agree: both miss, or both hit the same triangle, or two at a distance equal to
// float precision (coincident or adjacent triangles; the two triangle tests round differently).
[[maybe_unused]] bool sameHit(const Hit& a, const Hit& b, bool anyHit) {
    if ((a.prim == kNoPrimitive) != (b.prim == kNoPrimitive)) return false;
    if (anyHit || a.prim == kNoPrimitive || a.prim == b.prim) return true;
    return std::abs(a.t - b.t) <= 1e-5f * std::max(a.t, b.t);
}

struct CheckCount {
    uint64_t vsEmbree = 0, embreeDiffers = 0, vsBrute = 0, wrong = 0, threadsDiffer = 0;
};

// ---- measuring --------------------------------------------------------------------------------

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
    return "unknown CPU";
}

void usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: bvh_bench [--quick] [--passes N] [--scenes DIR] [--only NAME]\n"
                 "The framework BVH's build time and ray throughput (Mrays/s) on primary, incoherent and\n"
                 "shadow rays, 1 and 2 threads; with Embree (libembree-dev at configure time) its figures on\n"
                 "the same rays, interleaved, and the ratio ours / Embree. Every hit is checked.\n"
                 "  --quick       Cornell box and a small generated mesh, 2^14 rays, one pass (a smoke test)\n"
                 "  --passes N    timed passes per tracer, ray set and thread count (default 5)\n"
                 "  --scenes DIR  where cornell-box.scene is (default: %s)\n"
                 "  --only NAME   only that scene (cornell-box, noisy-sphere, bunny, motorbike)\n"
                 "  --threads L   thread counts, comma-separated (default 1,2)\n"
                 "  --sets L      ray sets, comma-separated (primary,incoherent,shadow; default all)\n"
                 "  --res R       R x R primary rays, R^2 rays in the other sets (default 1024)\n"
                 "  --cpu-time    Mrays per CPU second of the process instead of per wall-clock second\n"
                 "                (steadier on a loaded machine; with 2 threads, their CPU time added up)\n"
                 "  --tracer T    ours, embree or both (default); one alone runs no checks: for profiling,\n"
                 "                e.g. valgrind --tool=callgrind --toggle-collect='*traceOurs*'\n"
                 "Real meshes, when installed: %s (apt-get install glmark2-data),\n"
                 "  %s (apt-get install openfoam-examples)\n",
                 PATHSPACE_SOURCE_DIR "/scenes", kBunny, kMotorbike);
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
        if (a == "--quick") opt.quick = true;
        else if (a == "--passes" && i + 1 < argc) opt.passes = std::max(1, std::atoi(argv[++i]));
        else if (a == "--scenes" && i + 1 < argc) opt.scenesDir = argv[++i];
        else if (a == "--only" && i + 1 < argc) opt.only = argv[++i];
        else if (a == "--threads" && i + 1 < argc) {
            opt.threads.clear();
            for (const char* c = argv[++i]; *c;) {
                char* end;
                opt.threads.push_back(std::max(1, int(std::strtol(c, &end, 10))));
                c = *end ? end + 1 : end;
            }
        } else if (a == "--sets" && i + 1 < argc) opt.sets = argv[++i];
        else if (a == "--cpu-time") opt.cpuTime = true;
        else if (a == "--res" && i + 1 < argc) opt.res = std::max(8, std::atoi(argv[++i]));
        else if (a == "--tracer" && i + 1 < argc &&
                 (std::string(argv[i + 1]) == "ours" || std::string(argv[i + 1]) == "embree" ||
                  std::string(argv[i + 1]) == "both"))
            opt.tracer = argv[++i];
        else {
            std::fprintf(stderr, "bvh_bench: unknown or incomplete option '%s'\n", a.c_str());
            usage(stderr);
            return 2;
        }
    }
    if (opt.quick) opt.passes = 1;
    const int res = opt.quick ? 128 : opt.res;  // primary rays: res^2; the other sets as many
    const size_t n = size_t(res) * res;

    struct Bench {
        std::string name;
        Scene scene;
    };
    std::vector<Bench> benches;
    std::vector<std::string> missing;
    try {
        auto wanted = [&](const char* name) { return opt.only.empty() || opt.only == name; };
        if (wanted("cornell-box")) {
            const Scene cornell = loadScene(opt.scenesDir + "/cornell-box.scene");
            benches.push_back({"cornell-box", meshScene("cornell-box", cornell.triangles, Vec3(0, 0, -1), res)});
        }
        if (wanted("noisy-sphere"))
            benches.push_back(
                {"noisy-sphere", meshScene("noisy-sphere", opt.quick ? noisySphere(40, 80) : noisySphere(200, 400),
                                           Vec3(0.0f, 0.3f, -1.0f), res)});
        if (!opt.quick) {
            for (const auto& [name, path, from] : {std::tuple{"bunny", kBunny, Vec3(0, 0, 1)},
                                                   std::tuple{"motorbike", kMotorbike, Vec3(-1, 0.3f, -0.6f)}}) {
                if (!wanted(name)) continue;
                if (!std::ifstream(path)) {
                    missing.push_back(path);
                    continue;
                }
                benches.push_back({name, meshScene(name, readObj(path), from, res)});
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bvh_bench: %s\n", e.what());
        return 1;
    }

    std::printf("bvh_bench%s: %d logical CPUs, %s; g++/clang %s; load average %s at the start\n",
                opt.quick ? " --quick" : "", omp_get_num_procs(), cpuModel().c_str(), __VERSION__,
                loadAverage().c_str());
#ifdef PATHSPACE_HAVE_EMBREE
    std::printf("Embree %d.%d.%d on the same rays, interleaved pass by pass; ratio = our speed / Embree's\n",
                RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
#else
    std::printf("without Embree (configure with libembree-dev installed to compare)\n");
#endif
    for (const std::string& m : missing)
        std::printf("not found: %s (apt-get install %s)\n", m.c_str(),
                    m == kBunny ? "glmark2-data" : "openfoam-examples");
    std::printf(
        "%d ray(s) per set; Mrays/s%s: median of %d passes (ratio: median and range of the per-pass ratios)\n\n",
        int(n), opt.cpuTime ? " (per CPU second)" : "", opt.passes);
    std::printf("%-13s %8s %18s %3s %-10s %9s %9s %18s\n", "scene", "tris", "build ms ours/Emb", "thr", "rays", "ours",
                "Embree", "ratio");
    std::fflush(stdout);

    bool ok = true;
    const auto tStart = Clock::now();
    for (Bench& b : benches) {
        if (!opt.only.empty() && b.name != opt.only) continue;
        const Scene& s = b.scene;
        std::vector<AABB> boxes(s.triangles.size());
        for (size_t i = 0; i < boxes.size(); ++i) boxes[i] = s.triangles[i].bounds();
        const bool runOurs = opt.tracer != "embree", checks = opt.tracer == "both";
#ifdef PATHSPACE_HAVE_EMBREE
        const bool runEmbree = opt.tracer != "ours";
#endif
        const int buildRuns = opt.quick || !checks ? 1 : 5;
        double oursBuild = 1e300, embreeBuild = 0.0;
        for (int r = 0; r < buildRuns && runOurs; ++r) {
            BVH bvh;
            const auto t0 = Clock::now();
            bvh.build(boxes);
            oursBuild = std::min(oursBuild, secondsSince(t0));
        }
#ifdef PATHSPACE_HAVE_EMBREE
        Embree embree(getenv("PS_EMBREE_CONFIG")
                          ? getenv("PS_EMBREE_CONFIG")
                          : "threads=1");  // build on one thread, like ours; tracing runs on our threads
        if (runEmbree) embreeBuild = 1e300;
        for (int r = 0; r < buildRuns && runEmbree; ++r) {
            const auto t0 = Clock::now();
            embree.build(s.triangles);
            embreeBuild = std::min(embreeBuild, secondsSince(t0));
        }
#endif
        char oursB[16] = "-", embreeB[16] = "-", build[40];
        if (runOurs) std::snprintf(oursB, sizeof oursB, "%.1f", oursBuild * 1e3);
        if (embreeBuild > 0) std::snprintf(embreeB, sizeof embreeB, "%.1f", embreeBuild * 1e3);
        std::snprintf(build, sizeof build, "%s / %s", oursB, embreeB);

        std::vector<RaySet> sets = makeRays(s, n);
        if (!opt.sets.empty())
            sets.erase(std::remove_if(sets.begin(), sets.end(),
                                      [&](const RaySet& r) {
                                          return ("," + opt.sets + ",").find("," + std::string(r.name) + ",") ==
                                                 std::string::npos;
                                      }),
                       sets.end());
        CheckCount check;
        std::vector<std::vector<Hit>> firstRun(sets.size());
        for (size_t ti = 0; ti < opt.threads.size(); ++ti) {
            const int threads = opt.threads[ti];
            omp_set_num_threads(threads);
            for (size_t si = 0; si < sets.size(); ++si) {
                const RaySet& set = sets[si];
                std::vector<Hit> ours(set.rays.size()), theirs(set.rays.size());
                std::vector<double> tOurs, tTheirs, ratio;
                // Warm-up, then the timed passes. Alternate which tracer goes first, so that
                // neither always gets the warmer machine.
                for (int p = -1; p < opt.passes; ++p) {
                    for (int k = 0; k < 2; ++k) {
                        const bool oursNow = (k == 0) == (p % 2 == 0);
                        const auto t0 = Clock::now();
                        const double c0 = processCpuSeconds();
                        if (oursNow && runOurs) traceOurs(s, set, ours);
#ifdef PATHSPACE_HAVE_EMBREE
                        else if (!oursNow && runEmbree) embree.trace(set, theirs);
#endif
                        else continue;
                        if (p >= 0)
                            (oursNow ? tOurs : tTheirs)
                                .push_back(opt.cpuTime ? processCpuSeconds() - c0 : secondsSince(t0));
                    }
                    if (p >= 0 && !tTheirs.empty() && !tOurs.empty()) ratio.push_back(tTheirs.back() / tOurs.back());
                }
                char oursText[16] = "-", theirsText[16] = "-", ratioText[32] = "-";
                if (!tOurs.empty())
                    std::snprintf(oursText, sizeof oursText, "%.2f", set.rays.size() / median(tOurs) * 1e-6);
                if (!tTheirs.empty())
                    std::snprintf(theirsText, sizeof theirsText, "%.2f", set.rays.size() / median(tTheirs) * 1e-6);
                if (!ratio.empty())
                    std::snprintf(ratioText, sizeof ratioText, "%.2f (%.2f-%.2f)", median(ratio),
                                  *std::min_element(ratio.begin(), ratio.end()),
                                  *std::max_element(ratio.begin(), ratio.end()));
                std::printf("%-13s %8zu %18s %3d %-10s %9s %9s %18s\n", b.name.c_str(), s.triangles.size(), build,
                            threads, set.name, oursText, theirsText, ratioText);
                std::fflush(stdout);
                if (!checks) continue;
                if (ti > 0) {
                    for (size_t i = 0; i < ours.size(); ++i)
                        if (ours[i].prim != firstRun[si][i].prim || ours[i].t != firstRun[si][i].t)
                            ++check.threadsDiffer;
                    continue;
                }
                firstRun[si] = ours;
                // Checks, once per set: every ray against Embree, a sample against brute force.
                const size_t sample = std::min(
                    set.rays.size(), std::max<size_t>(64, (size_t(1) << (opt.quick ? 20 : 27)) / s.triangles.size()));
                for (size_t i = 0; i < set.rays.size(); ++i) {
                    bool brute = i % std::max<size_t>(1, set.rays.size() / sample) == 0;
#ifdef PATHSPACE_HAVE_EMBREE
                    ++check.vsEmbree;
                    if (!sameHit(ours[i], theirs[i], set.anyHit)) {
                        ++check.embreeDiffers;
                        brute = true;
                    }
#endif
                    if (!brute) continue;
                    ++check.vsBrute;
                    if (!agreesWithBruteForce(s, set.rays[i], set.anyHit, ours[i])) {
                        if (check.wrong++ < 5)
                            std::fprintf(stderr, "bvh_bench: %s %s ray %zu: the BVH's hit differs from brute force\n",
                                         b.name.c_str(), set.name, i);
                    }
                }
            }
        }
        if (!checks) {
            std::printf("%-13s checks: none (--tracer %s)\n", "", opt.tracer.c_str());
            continue;
        }
        std::printf(
            "%-13s checks: %llu rays against Embree (%llu differ), %llu against brute force (%llu wrong), "
            "%llu differ between 1 and 2 threads\n",
            "", (unsigned long long)check.vsEmbree, (unsigned long long)check.embreeDiffers,
            (unsigned long long)check.vsBrute, (unsigned long long)check.wrong,
            (unsigned long long)check.threadsDiffer);
        ok = ok && check.wrong == 0 && check.threadsDiffer == 0;
    }
    std::printf("total time %.1f s; load average %s at the end\n", secondsSince(tStart), loadAverage().c_str());
    if (!ok) {
        std::fprintf(stderr,
                     "bvh_bench: the BVH returned hits that brute force does not, or that depend on the threads\n");
        return 1;
    }
    return 0;
}
