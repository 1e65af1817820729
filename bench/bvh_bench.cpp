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
#include <filesystem>
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

// A scene of bare triangles (primitive i = triangle i), one grey material; its camera is the
// first view (it only matters to makeRays, which takes the views).
Scene meshScene(const std::string& name, std::vector<Triangle> tris) {
    Scene s;
    s.path = name;
    Material grey;
    grey.kind = BSDFKind::Diffuse;
    s.materials.push_back(grey);
    s.triangles = std::move(tris);
    for (uint32_t t = 0; t < s.triangles.size(); ++t) s.prims.push_back({ShapeKind::Triangle, t, 0, -1});
    s.camera = Camera(Vec3(0, 0, -1), Vec3(0), Vec3(0, 1, 0), 40.0f, 8, 8);
    s.finalize();
    return s;
}

// A pinhole camera looking at the mesh from direction `from` (from the bounds' centre towards the
// eye), at the distance where the bounding sphere fills a 40-degree view, that frames the mesh:
// it is turned towards the centre of the vertices' projections and its field of view and aspect
// are those of their bounding rectangle, about `rays` pixels. So most of its rays hit the mesh
// (bvh_bench prints how many), as most of a renderer's primary rays do; a camera that fits the
// bounding sphere sends most of its rays past a bunny (23 % hit) or a motorbike (12 %).
Camera framingView(const std::vector<Triangle>& tris, Vec3 from, Vec3 up, size_t rays) {
    AABB b;
    for (const Triangle& t : tris) b.expand(t.bounds());
    const float r = 0.5f * glm::length(b.extent());
    from = glm::normalize(from);
    const Vec3 eye = b.center() + from * (r / std::sin(20.0f * kPi / 180.0f));
    Vec3 forward = -from, right, camUp;
    float halfX = 0.0f, halfY = 0.0f;
    for (int pass = 0; pass < 3; ++pass) {                // aim at the projections' centre, then measure them
        right = glm::normalize(glm::cross(forward, up));  // as Camera builds its basis
        camUp = glm::cross(right, forward);
        float x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
        for (const Triangle& t : tris)
            for (const Vec3* p : {&t.p0, &t.p1, &t.p2}) {
                const Vec3 d = *p - eye;
                const float z = glm::dot(d, forward), x = glm::dot(d, right) / z, y = glm::dot(d, camUp) / z;
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        halfX = std::max(-x0, x1), halfY = std::max(-y0, y1);
        if (pass < 2) forward = glm::normalize(forward + 0.5f * (x0 + x1) * right + 0.5f * (y0 + y1) * camUp);
    }
    const float aspect = std::min(4.0f, std::max(0.25f, halfX / halfY));
    const int w = std::max(8, int(std::lround(std::sqrt(double(rays) * aspect))));
    const int h = std::max(8, int(std::lround(double(rays) / w)));
    const float fovY = 2.0f * std::atan(std::max(halfY, halfX / (float(w) / h))) * 180.0f / kPi;
    return Camera(eye, eye + forward, up, fovY, w, h);
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
    std::vector<size_t> viewEnd;  // primary rays: where each view's rays end
};

// Primary rays: each view's pixels in scan-line order, one jittered ray per pixel (as a renderer
// traces them, coherent); then the incoherent and shadow sets, n rays each.
std::vector<RaySet> makeRays(const Scene& s, const std::vector<Camera>& views, size_t n) {
    std::vector<RaySet> sets = {{"primary", false, {}, {}}, {"incoherent", false, {}, {}}, {"shadow", true, {}, {}}};
    for (size_t v = 0; v < views.size(); ++v) {
        const Camera& cam = views[v];
        const int w = cam.width(), h = cam.height();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                Rng rng = taskRng(kSeedPrimary, uint32_t(v), uint32_t(y * w + x));
                const Vec2 u = rng.uniform2();
                sets[0].rays.push_back(cam.generateRay(Vec2(x + u.x, y + u.y)));
            }
        sets[0].viewEnd.push_back(sets[0].rays.size());
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

// The goals of issue 30 (one thread, the two real meshes): our speed over Embree's at least this
// much per ray set, our build's CPU time at most kBuildGoal times Embree's.
double speedGoal(const std::string& set) { return set == "primary" ? 0.85 : 0.65; }
constexpr double kBuildGoal = 1.2;
bool hasGoal(const std::string& scene) { return scene == "bunny" || scene == "motorbike"; }

constexpr int kViews = 4;               // primary views per scene
constexpr double kMinPrimaryHit = 0.3;  // a view whose rays hit less is not a renderer's view

void usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: bvh_bench [--quick] [--processes N] [--passes N] [--clock wall|cpu] [--scenes DIR]\n"
                 "                 [--only NAME] [--threads L] [--sets L] [--res R] [--tracer T]\n"
                 "The framework BVH's build time and ray throughput (Mrays/s) on primary, incoherent and\n"
                 "shadow rays, 1 and 2 threads; with Embree (libembree-dev at configure time) its figures on\n"
                 "the same rays, interleaved, and the ratio ours / Embree. Every hit is checked.\n"
                 "  --quick         Cornell box and a small generated mesh, 2^14 rays, one pass (a smoke test)\n"
                 "  --processes N   run the benchmark in N processes one after the other and print, after\n"
                 "                  their tables, the median and range over the processes of each figure,\n"
                 "                  against the goals (the figures to publish: N >= 5)\n"
                 "  --passes N      timed passes per tracer, ray set and thread count (default 5)\n"
                 "  --clock C       wall (default): Mrays per wall-clock second; cpu: per CPU second of the\n"
                 "                  process, all threads added up (steadier on a loaded machine)\n"
                 "                  (--cpu-time: the same as --clock cpu)\n"
                 "  --scenes DIR    where cornell-box.scene is (default: %s)\n"
                 "  --only NAME     only that scene (cornell-box, noisy-sphere, bunny, motorbike)\n"
                 "  --threads L     thread counts, comma-separated (default 1,2)\n"
                 "  --sets L        ray sets, comma-separated (primary,incoherent,shadow; default all)\n"
                 "  --res R         about R^2 primary rays (%d views framing the mesh), R^2 rays in the\n"
                 "                  other sets (default 1024)\n"
                 "  --tracer T      ours, embree or both (default); one alone runs no checks: for profiling,\n"
                 "                  e.g. valgrind --tool=callgrind --toggle-collect='*traceOurs*'\n"
                 "Build times are CPU seconds of one thread each (median of 5 builds), whatever --clock says.\n"
                 "Exits 1 when a hit is wrong, when hits depend on the thread count, or when fewer than %.0f %%\n"
                 "of a view's primary rays hit the mesh.\n"
                 "Real meshes, when installed: %s (apt-get install glmark2-data),\n"
                 "  %s (apt-get install openfoam-examples)\n",
                 PATHSPACE_SOURCE_DIR "/scenes", kViews, 100.0 * kMinPrimaryHit, kBunny, kMotorbike);
}

// One line of figures of one process (also what --processes reads back from each child).
struct Figure {
    std::string scene, set;  // set "build": the build times (ours, embree in ms; ratio ours / Embree)
    int threads = 1;
    double hit = 0.0, ours = 0.0, embree = 0.0, ratio = 0.0;  // 0: not measured
};

// --processes N: runs this program N times with the same options (but --processes) and prints
// the median and range over the processes of each figure against the goals.
int runProcesses(int n, int argc, char** argv) {
    auto quote = [](const std::string& a) {
        std::string q = "'";
        for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q + "'";
    };
    std::error_code ec;
    const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();  // Linux
    std::string cmd = quote(ec || self.empty() ? argv[0] : self);
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--processes") ++i;
        else cmd += " " + quote(argv[i]);
    }
    cmd += " --figures";
    std::vector<std::vector<Figure>> runs;
    std::string clockName = "wall";
    std::string loadBefore = loadAverage();
    for (int p = 0; p < n; ++p) {
        std::printf("==== process %d of %d (load average %s)\n", p + 1, n, loadAverage().c_str());
        std::fflush(stdout);
        FILE* f = popen(cmd.c_str(), "r");
        if (!f) {
            std::fprintf(stderr, "bvh_bench: cannot start %s\n", cmd.c_str());
            return 1;
        }
        std::vector<Figure> figs;
        char line[1024];
        while (std::fgets(line, sizeof line, f)) {
            if (line[0] != '@') {
                std::fputs(line, stdout);
                std::fflush(stdout);
                continue;
            }
            char scene[64], set[64], clk[16];
            Figure fig;
            if (std::sscanf(line, "@ %63s %d %63s %lf %lf %lf %lf %15s", scene, &fig.threads, set, &fig.hit, &fig.ours,
                            &fig.embree, &fig.ratio, clk) == 8) {
                fig.scene = scene, fig.set = set, clockName = clk;
                figs.push_back(fig);
            }
        }
        const int status = pclose(f);
        if (status != 0) {
            std::fprintf(stderr, "bvh_bench: process %d of %d failed (status %d): no summary\n", p + 1, n, status);
            return 1;
        }
        runs.push_back(figs);
    }
    auto stat = [](std::vector<double> v, const char* fmt) {
        v.erase(std::remove(v.begin(), v.end(), 0.0), v.end());
        if (v.empty()) return std::string("-");
        char buf[96], a[24], b[24], c[24];
        std::snprintf(a, sizeof a, fmt, median(v));
        std::snprintf(b, sizeof b, fmt, *std::min_element(v.begin(), v.end()));
        std::snprintf(c, sizeof c, fmt, *std::max_element(v.begin(), v.end()));
        std::snprintf(buf, sizeof buf, "%s (%s-%s)", a, b, c);
        return std::string(buf);
    };
    std::printf(
        "\n==== %d processes, load average %s before and %s after: median (range) over the processes\n"
        "of each process's figure (speeds and ratios: the median of its passes; build: of its 5 builds)\n"
        "speeds in Mrays per %s second; build in ms of CPU time, one thread each\n\n",
        n, loadBefore.c_str(), loadAverage().c_str(), clockName == "cpu" ? "CPU" : "wall-clock");
    std::printf("%-13s %3s %-10s %6s %22s %22s %20s %8s %s\n", "scene", "thr", "rays", "hit %", "ours", "Embree",
                "ratio", "goal", "");
    for (size_t i = 0; i < runs[0].size(); ++i) {
        const Figure& f0 = runs[0][i];
        std::vector<double> hit, ours, embree, ratio;
        for (const auto& r : runs)
            if (i < r.size() && r[i].scene == f0.scene && r[i].set == f0.set && r[i].threads == f0.threads) {
                hit.push_back(r[i].hit), ours.push_back(r[i].ours), embree.push_back(r[i].embree);
                ratio.push_back(r[i].ratio);
            }
        const bool build = f0.set == "build";
        std::string goal = "", verdict = "";
        std::vector<double> rs = ratio;
        rs.erase(std::remove(rs.begin(), rs.end(), 0.0), rs.end());
        if (hasGoal(f0.scene) && f0.threads == 1 && !rs.empty()) {
            const double g = build ? kBuildGoal : speedGoal(f0.set), m = median(rs);
            char buf[16];
            std::snprintf(buf, sizeof buf, "%s %.2f", build ? "<=" : ">=", g);
            goal = buf;
            verdict = (build ? m <= g : m >= g) ? "met" : "NOT MET";
        }
        char hitText[16] = "";
        if (!build) std::snprintf(hitText, sizeof hitText, "%.1f", 100.0 * median(hit));  // the same in every process
        std::printf("%-13s %3d %-10s %6s %22s %22s %20s %8s %s\n", f0.scene.c_str(), f0.threads, f0.set.c_str(),
                    hitText, stat(ours, build ? "%.1f" : "%.2f").c_str(), stat(embree, build ? "%.1f" : "%.2f").c_str(),
                    stat(ratio, "%.2f").c_str(), goal.c_str(), verdict.c_str());
    }
    std::printf(
        "\nratio: our speed over Embree's (build: our time over Embree's); goal: issue 30, one thread, "
        "median over the processes\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    int processes = 0;
    bool figures = false;  // print the machine-readable '@' lines (for --processes)
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            usage(stdout);
            return 0;
        }
        if (a == "--quick") opt.quick = true;
        else if (a == "--passes" && i + 1 < argc) opt.passes = std::max(1, std::atoi(argv[++i]));
        else if (a == "--processes" && i + 1 < argc) processes = std::max(1, std::atoi(argv[++i]));
        else if (a == "--figures") figures = true;
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
        else if (a == "--clock" && i + 1 < argc &&
                 (std::string(argv[i + 1]) == "cpu" || std::string(argv[i + 1]) == "wall"))
            opt.cpuTime = std::string(argv[++i]) == "cpu";
        else if (a == "--res" && i + 1 < argc) opt.res = std::max(16, std::atoi(argv[++i]));
        else if (a == "--tracer" && i + 1 < argc &&
                 (std::string(argv[i + 1]) == "ours" || std::string(argv[i + 1]) == "embree" ||
                  std::string(argv[i + 1]) == "both" || std::string(argv[i + 1]) == "avx2"))
            opt.tracer = argv[++i];
        else {
            std::fprintf(stderr, "bvh_bench: unknown or incomplete option '%s'\n", a.c_str());
            usage(stderr);
            return 2;
        }
    }
    if (processes > 0) return runProcesses(processes, argc, argv);
    if (opt.quick) opt.passes = 1;
    const int res = opt.quick ? 128 : opt.res;  // about res^2 primary rays; the other sets res^2
    const size_t n = size_t(res) * res;

    struct Bench {
        std::string name;
        Scene scene;
        std::vector<Camera> views;
    };
    std::vector<Bench> benches;
    std::vector<std::string> missing;
    // Each scene with kViews views that frame it (from the bounds' centre towards the eye) and
    // the world's up for them; the motorbike stands on z = 0.
    auto add = [&](const std::string& name, std::vector<Triangle> tris, Vec3 up, std::vector<Vec3> from) {
        Bench b{name, meshScene(name, tris), {}};
        for (const Vec3& f : from) b.views.push_back(framingView(tris, f, up, n / from.size()));
        benches.push_back(std::move(b));
    };
    const Vec3 yUp(0, 1, 0), zUp(0, 0, 1);
    try {
        auto wanted = [&](const char* name) { return opt.only.empty() || opt.only == name; };
        if (wanted("cornell-box"))
            add("cornell-box", loadScene(opt.scenesDir + "/cornell-box.scene").triangles, yUp,
                {Vec3(0, 0, -1), Vec3(0.4f, 0.3f, -1), Vec3(-0.5f, 0.2f, -1), Vec3(0.2f, 1, -0.6f)});
        if (wanted("noisy-sphere"))
            add("noisy-sphere", opt.quick ? noisySphere(40, 80) : noisySphere(200, 400), yUp,
                {Vec3(0, 0.3f, -1), Vec3(1, 0.5f, 0.2f), Vec3(-0.6f, 0.2f, 0.8f), Vec3(0.2f, 1.5f, 0.3f)});
        if (!opt.quick) {
            if (wanted("bunny") && !std::ifstream(kBunny)) missing.push_back(kBunny);
            else if (wanted("bunny"))
                add("bunny", readObj(kBunny), yUp,
                    {Vec3(0, 0.2f, 1), Vec3(1, 0.3f, 0.1f), Vec3(-0.6f, 0.4f, -0.8f), Vec3(-0.9f, 0.1f, 0.5f)});
            if (wanted("motorbike") && !std::ifstream(kMotorbike)) missing.push_back(kMotorbike);
            else if (wanted("motorbike"))
                add("motorbike", readObj(kMotorbike), zUp,
                    {Vec3(0.2f, -1, 0.3f), Vec3(-1, -0.6f, 0.3f), Vec3(1, 0.7f, 0.4f), Vec3(-0.3f, 1, 0.15f)});
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bvh_bench: %s\n", e.what());
        return 1;
    }

    const char* clockName = opt.cpuTime ? "cpu" : "wall";
    std::printf("bvh_bench%s: %d logical CPUs, %s; g++/clang %s; load average %s at the start\n",
                opt.quick ? " --quick" : "", omp_get_num_procs(), cpuModel().c_str(), __VERSION__,
                loadAverage().c_str());
#ifdef PATHSPACE_HAVE_EMBREE
    std::printf("Embree %d.%d.%d on the same rays, interleaved pass by pass; ratio = our speed / Embree's\n",
                RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
#else
    std::printf("without Embree (configure with libembree-dev installed to compare)\n");
#endif
    std::printf("our traversal: %s\n", useAvx2Tracing(!std::getenv("PATHSPACE_NO_AVX2"))
                                           ? "its AVX2 copy (PATHSPACE_NO_AVX2=1: the baseline)"
                                           : "the baseline copy (SSE2 on x86-64)");
    for (const std::string& m : missing)
        std::printf("not found: %s (apt-get install %s)\n", m.c_str(),
                    m == kBunny ? "glmark2-data" : "openfoam-examples");
    std::printf(
        "primary rays: %d views per scene, each framing the mesh; incoherent and shadow: %d rays each\n"
        "Mrays/s: per %s second, median of %d passes (ratio: median and range of the per-pass ratios);\n"
        "hit %%: rays that hit (shadow: occluded); build: CPU ms of one thread, median of 5 builds\n\n",
        kViews, int(n), opt.cpuTime ? "CPU" : "wall-clock", opt.passes);
    std::printf("%-13s %8s %18s %3s %-10s %6s %9s %9s %18s\n", "scene", "tris", "build ms ours/Emb", "thr", "rays",
                "hit %", "ours", opt.tracer == "avx2" ? "baseline" : "Embree", "ratio");
    std::fflush(stdout);

    bool ok = true;
    std::vector<std::string> emptyViews;
    std::vector<Figure> out;
    const auto tStart = Clock::now();
    for (Bench& b : benches) {
        const Scene& s = b.scene;
        const bool runOurs = opt.tracer != "embree", checks = opt.tracer == "both";
        const bool versusBaseline = opt.tracer == "avx2";  // the second column: our baseline copy
#ifdef PATHSPACE_HAVE_EMBREE
        const bool runEmbree = opt.tracer == "embree" || opt.tracer == "both";
#endif
        // Builds: CPU time of the process (each build runs on one thread), median of the runs.
        // Each from the triangles to what its traversal reads. Embree's: its buffers filled, then
        // rtcCommitScene (its triangles' boxes, its BVH, its leaves of four triangles). Ours: what
        // Scene::finalize does for them: the triangles' boxes, BVH::build, the triangles copied
        // in the BVH's leaf order (Scene's items also keep a material and a light: 52 bytes, here
        // the 36-byte triangles). Both free the build before theirs inside the timed region.
        const int buildRuns = opt.quick || !checks ? 1 : 5;
        std::vector<double> oursBuilds, embreeBuilds;
        BVH keptBvh;  // kept, so that no build's work can be left out as unused
        std::vector<Triangle, LargePageAllocator<Triangle>> keptTriangles;
        for (int r = 0; r < buildRuns && runOurs; ++r) {
            const double c0 = processCpuSeconds();
            {
                std::vector<AABB> boxes(s.triangles.size());
                for (size_t i = 0; i < boxes.size(); ++i) boxes[i] = s.triangles[i].bounds();
                BVH bvh;
                bvh.build(boxes);
                std::vector<Triangle, LargePageAllocator<Triangle>> leafOrder(boxes.size());
                for (size_t i = 0; i < leafOrder.size(); ++i) leafOrder[i] = s.triangles[bvh.order()[i]];
                keptBvh = std::move(bvh);  // the build before this one freed, as Embree's is
                keptTriangles = std::move(leafOrder);
            }
            oursBuilds.push_back(processCpuSeconds() - c0);
        }
        // Freed before anything is traced: the last build's 20-40 MB left in place moved where
        // Embree's nodes landed and made its incoherent rays 7 % faster (motorbike).
        keptBvh = BVH();
        decltype(keptTriangles)().swap(keptTriangles);
#ifdef PATHSPACE_HAVE_EMBREE
        Embree embree(getenv("PS_EMBREE_CONFIG")
                          ? getenv("PS_EMBREE_CONFIG")
                          : "threads=1");  // build on one thread, like ours; tracing runs on our threads
        for (int r = 0; r < buildRuns && runEmbree; ++r) {
            const double c0 = processCpuSeconds();
            embree.build(s.triangles);
            embreeBuilds.push_back(processCpuSeconds() - c0);
        }
#endif
        const double oursBuild = oursBuilds.empty() ? 0.0 : median(oursBuilds),
                     embreeBuild = embreeBuilds.empty() ? 0.0 : median(embreeBuilds);
        char oursB[16] = "-", embreeB[16] = "-", build[40];
        if (oursBuild > 0) std::snprintf(oursB, sizeof oursB, "%.1f", oursBuild * 1e3);
        if (embreeBuild > 0) std::snprintf(embreeB, sizeof embreeB, "%.1f", embreeBuild * 1e3);
        std::snprintf(build, sizeof build, "%s / %s", oursB, embreeB);
        out.push_back({b.name, "build", 1, 0.0, oursBuild * 1e3, embreeBuild * 1e3,
                       oursBuild > 0 && embreeBuild > 0 ? oursBuild / embreeBuild : 0.0});

        std::vector<RaySet> sets = makeRays(s, b.views, n);
        if (!opt.sets.empty())
            sets.erase(std::remove_if(sets.begin(), sets.end(),
                                      [&](const RaySet& r) {
                                          return ("," + opt.sets + ",").find("," + std::string(r.name) + ",") ==
                                                 std::string::npos;
                                      }),
                       sets.end());
        CheckCount check;
        std::vector<std::vector<Hit>> firstRun(sets.size());
        std::string viewHits;
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
                        if (versusBaseline) {
                            useAvx2Tracing(oursNow);
                            traceOurs(s, set, oursNow ? ours : theirs);
                        } else if (oursNow && runOurs) traceOurs(s, set, ours);
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
                if (versusBaseline) useAvx2Tracing(!std::getenv("PATHSPACE_NO_AVX2"));
                // What the rays hit (whichever tracer ran; the checks below hold them equal).
                const std::vector<Hit>& hits = runOurs ? ours : theirs;
                auto hitFraction = [&](size_t begin, size_t end) {
                    size_t k = 0;
                    for (size_t i = begin; i < end; ++i) k += hits[i].prim != kNoPrimitive;
                    return end > begin ? double(k) / double(end - begin) : 0.0;
                };
                const double hit = hitFraction(0, hits.size());
                if (ti == 0 && !set.viewEnd.empty()) {
                    for (size_t v = 0, begin = 0; v < set.viewEnd.size(); begin = set.viewEnd[v++]) {
                        const double h = hitFraction(begin, set.viewEnd[v]);
                        char buf[160];
                        std::snprintf(buf, sizeof buf, "%s %.0f %%", v ? "," : "", 100.0 * h);
                        viewHits += buf;
                        if (h < kMinPrimaryHit) {
                            std::snprintf(buf, sizeof buf, "%s view %zu: %.1f %% of its primary rays hit",
                                          b.name.c_str(), v + 1, 100.0 * h);
                            emptyViews.push_back(buf);
                        }
                    }
                }
                const double mOurs = tOurs.empty() ? 0.0 : set.rays.size() / median(tOurs) * 1e-6;
                const double mTheirs = tTheirs.empty() ? 0.0 : set.rays.size() / median(tTheirs) * 1e-6;
                char oursText[16] = "-", theirsText[16] = "-", ratioText[32] = "-";
                if (mOurs > 0) std::snprintf(oursText, sizeof oursText, "%.2f", mOurs);
                if (mTheirs > 0) std::snprintf(theirsText, sizeof theirsText, "%.2f", mTheirs);
                if (!ratio.empty())
                    std::snprintf(ratioText, sizeof ratioText, "%.2f (%.2f-%.2f)", median(ratio),
                                  *std::min_element(ratio.begin(), ratio.end()),
                                  *std::max_element(ratio.begin(), ratio.end()));
                std::printf("%-13s %8zu %18s %3d %-10s %6.1f %9s %9s %18s\n", b.name.c_str(), s.triangles.size(), build,
                            threads, set.name, 100.0 * hit, oursText, theirsText, ratioText);
                std::fflush(stdout);
                out.push_back({b.name, set.name, threads, hit, mOurs, mTheirs, ratio.empty() ? 0.0 : median(ratio)});
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
        if (!viewHits.empty()) std::printf("%-13s primary rays that hit, view by view:%s\n", "", viewHits.c_str());
        if (!checks) {
            std::printf("%-13s checks: none (--tracer %s)\n", "", opt.tracer.c_str());
            continue;
        }
        std::printf(
            "%-13s checks: %llu rays against Embree (%llu differ), %llu against brute force (%llu wrong), "
            "%llu differ between thread counts\n",
            "", (unsigned long long)check.vsEmbree, (unsigned long long)check.embreeDiffers,
            (unsigned long long)check.vsBrute, (unsigned long long)check.wrong,
            (unsigned long long)check.threadsDiffer);
        ok = ok && check.wrong == 0 && check.threadsDiffer == 0;
    }
    std::printf("total time %.1f s; load average %s at the end\n", secondsSince(tStart), loadAverage().c_str());
    if (figures)
        for (const Figure& f : out)
            std::printf("@ %s %d %s %.6f %.6f %.6f %.6f %s\n", f.scene.c_str(), f.threads, f.set.c_str(), f.hit, f.ours,
                        f.embree, f.ratio, clockName);
    if (!emptyViews.empty()) {
        for (const std::string& e : emptyViews)
            std::fprintf(stderr,
                         "bvh_bench: %s, fewer than %.0f %%: such a view measures empty space, not the BVH "
                         "(bvh_bench.cpp, framingView)\n",
                         e.c_str(), 100.0 * kMinPrimaryHit);
        return 1;
    }
    if (!ok) {
        std::fprintf(stderr,
                     "bvh_bench: the BVH returned hits that brute force does not, or that depend on the threads\n");
        return 1;
    }
    return 0;
}
