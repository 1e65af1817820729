// photon_bench: figures for lesson 8's photon map (lessons/08-photon-mapping/photonmap.h): the
// build time of the left-balanced kd-tree, k = 50 nearest-neighbour queries per second with 1 and
// 2 threads, and the bytes per stored photon, for 1e5 and 1e6 photons traced in the Cornell box.
// When nanoflann's header is installed (Debian: libnanoflann-dev; a benchmark's comparison, never
// a dependency of the course) it runs the same queries through nanoflann and prints the ratio. A
// benchmark, never a test: nothing is timed against a threshold. bench/README.md explains the
// columns and lists the figures measured on the course machine.
//
// The photons come from tracePhotonMap (fixed seed); the queries are the positions of photons
// drawn at random (fixed seed), as a final gather or a camera ray looks the map up where photons
// are. Both trees must find the same neighbours: the sum of every query's k-th squared distance
// is printed for each and the program exits 1 if they differ.
#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>
#include <vector>
#include "08-photon-mapping/photonmap.h"
#include "rng.h"
#include "scene_loader.h"

// -DPATHSPACE_NO_NANOFLANN builds the program as it is without nanoflann (to check that branch).
#if __has_include(<nanoflann.hpp>) && !defined(PATHSPACE_NO_NANOFLANN)
#include <nanoflann.hpp>
#define PATHSPACE_HAVE_NANOFLANN 1
#else
#define PATHSPACE_HAVE_NANOFLANN 0
#endif

#ifndef PATHSPACE_SOURCE_DIR
#define PATHSPACE_SOURCE_DIR "."
#endif

using namespace ps;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

constexpr int kK = 50;
constexpr int kThreadCounts[] = {1, 2};
constexpr uint64_t kPhotonSeed = 0x9407000000000001ull, kQuerySeed = 0x9407000000000002ull;

// What a run of queries found: the sum of every query's k-th squared distance (a checksum that
// both trees must reproduce) and the number of queries that found k photons.
struct Found {
    double sumKth = 0.0;
    long full = 0;
};

// Our tree: nearestPhotons (kdtree_query.cpp) for every query, in parallel.
Found queryOurs(const PhotonMap& map, const std::vector<Vec3>& queries) {
    double sum = 0.0;
    long full = 0;
    const float inf = std::numeric_limits<float>::infinity();
#pragma omp parallel reduction(+ : sum, full)
    {
        std::vector<NearPhoton> found;
        found.reserve(kK);
#pragma omp for schedule(dynamic, 256)
        for (long i = 0; i < long(queries.size()); ++i) {
            nearestPhotons(map, queries[size_t(i)], kK, inf, found);
            if (found.size() == size_t(kK)) {
                sum += found[0].d2;
                ++full;
            }
        }
    }
    return {sum, full};
}

#if PATHSPACE_HAVE_NANOFLANN
// nanoflann's adaptor over the photons' positions (the same array our tree was built from).
struct PhotonCloud {
    const std::vector<Photon>& photons;
    size_t kdtree_get_point_count() const { return photons.size(); }
    float kdtree_get_pt(size_t i, size_t dim) const { return photons[i].p[int(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};
using NanoTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PhotonCloud>, PhotonCloud, 3, uint32_t>;

Found queryNano(const NanoTree& tree, const std::vector<Vec3>& queries) {
    double sum = 0.0;
    long full = 0;
#pragma omp parallel reduction(+ : sum, full)
    {
        std::vector<uint32_t> index(kK);
        std::vector<float> d2(kK);
#pragma omp for schedule(dynamic, 256)
        for (long i = 0; i < long(queries.size()); ++i) {
            const Vec3& q = queries[size_t(i)];
            const float point[3] = {q.x, q.y, q.z};
            if (tree.knnSearch(point, kK, index.data(), d2.data()) == size_t(kK)) {
                sum += d2[kK - 1];
                ++full;
            }
        }
    }
    return {sum, full};
}
#endif

// Best of `runs` wall times of f, after one untimed warm-up.
template <class F>
double bestSeconds(int runs, F&& f) {
    f();
    double best = 1e300;
    for (int r = 0; r < runs; ++r) {
        const auto t0 = Clock::now();
        f();
        best = std::min(best, secondsSince(t0));
    }
    return best;
}

// At least n photons traced in the Cornell box, in path order (global map: every diffuse hit).
std::vector<Photon> tracePhotons(const Scene& scene, size_t n) {
    std::vector<Photon> out;
    for (uint32_t batch = 0; out.size() < n; ++batch) {
        SampleStats stats;
        const PhotonMap map =
            tracePhotonMap(scene, MapKind::Global, int(n / 2), scene.settings.maxDepth, kPhotonSeed, batch, stats);
        out.insert(out.end(), map.nodes.begin() + 1, map.nodes.end());
    }
    out.resize(n);
    return out;
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

void usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: photon_bench [--quick] [--scenes DIR]\n"
                 "Prints lesson 8's photon map figures: kd-tree build time, k = %d nearest-neighbour\n"
                 "queries per second with 1 and 2 threads, bytes per photon, for 1e5 and 1e6 photons of\n"
                 "the Cornell box; with nanoflann installed (libnanoflann-dev) the same for nanoflann.\n"
                 "  --quick       1e4 and 1e5 photons, one run each (a smoke test)\n"
                 "  --scenes DIR  where cornell-box.scene is (default: %s)\n"
                 "  --help        this text\n",
                 kK, PATHSPACE_SOURCE_DIR "/scenes");
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    std::string scenes = PATHSPACE_SOURCE_DIR "/scenes";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            usage(stdout);
            return 0;
        } else if (a == "--quick") {
            quick = true;
        } else if (a == "--scenes" && i + 1 < argc) {
            scenes = argv[++i];
        } else {
            std::fprintf(stderr, "photon_bench: unknown or incomplete option '%s'\n", a.c_str());
            usage(stderr);
            return 2;
        }
    }
    try {
        const Scene scene = loadScene(scenes + "/cornell-box.scene");
        const std::vector<size_t> sizes =
            quick ? std::vector<size_t>{10000, 100000} : std::vector<size_t>{100000, 1000000};
        const size_t queryCount = quick ? 20000 : 200000;
        const int runs = quick ? 1 : 3;
        const auto t0 = Clock::now();
        const std::vector<Photon> all = tracePhotons(scene, sizes.back());
        std::printf(
            "photon_bench: %zu photons traced in the Cornell box in %.2f s; k = %d, %zu queries at photons' "
            "positions; %s, %d logical CPUs\n",
            all.size(), secondsSince(t0), kK, queryCount, compiler().c_str(), omp_get_num_procs());
#if PATHSPACE_HAVE_NANOFLANN
        std::printf(
            "nanoflann %d.%d.%d: KDTreeSingleIndexAdaptor, L2_Simple_Adaptor<float>, leaf_max_size 10 (its "
            "default), knnSearch\n",
            (NANOFLANN_VERSION >> 8) & 0xf, (NANOFLANN_VERSION >> 4) & 0xf, NANOFLANN_VERSION & 0xf);
#else
        std::printf(
            "nanoflann: not installed, so no comparison (Debian: apt-get install libnanoflann-dev, then "
            "rebuild photon_bench)\n");
#endif
        std::printf("\n%-10s %-9s %10s %8s %14s %14s %11s\n", "photons", "tree", "build ms", "bytes", "1 thread q/s",
                    "2 threads q/s", "ours/nano");
        int status = 0;
        for (const size_t n : sizes) {
            const std::vector<Photon> photons(all.begin(), all.begin() + long(n));
            std::vector<Vec3> queries(queryCount);
            Rng rng(kQuerySeed);
            for (Vec3& q : queries) q = photons[std::min(n - 1, size_t(rng.uniform() * float(n)))].p;

            PhotonMap map;
            const double buildOurs = bestSeconds(runs, [&] { buildPhotonMap(photons, map); });
            const double bytesOurs = double(map.nodes.size() * sizeof(Photon)) / double(n);
            double qpsOurs[2] = {0.0, 0.0};
            Found ours;
            for (int t = 0; t < 2; ++t) {
                omp_set_num_threads(kThreadCounts[t]);
                qpsOurs[t] = double(queryCount) / bestSeconds(runs, [&] { ours = queryOurs(map, queries); });
            }
            std::printf("%-10zu %-9s %10.1f %8.1f %14.0f %14.0f %11s\n", n, "ours", buildOurs * 1e3, bytesOurs,
                        qpsOurs[0], qpsOurs[1], "");
#if PATHSPACE_HAVE_NANOFLANN
            const PhotonCloud cloud{photons};
            std::unique_ptr<NanoTree> tree;
            const double buildNano = bestSeconds(runs, [&] {
                tree = std::make_unique<NanoTree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
            });
            // nanoflann keeps the index (4 bytes a photon), its nodes, and reads the points from the
            // photons themselves: counted here as the 12 bytes of a position.
            const double bytesNano = double(tree->usedMemory(*tree)) / double(n) + 12.0;
            double qpsNano[2] = {0.0, 0.0};
            Found nano;
            for (int t = 0; t < 2; ++t) {
                omp_set_num_threads(kThreadCounts[t]);
                qpsNano[t] = double(queryCount) / bestSeconds(runs, [&] { nano = queryNano(*tree, queries); });
            }
            std::printf("%-10zu %-9s %10.1f %8.1f %14.0f %14.0f %10.2fx\n", n, "nanoflann", buildNano * 1e3, bytesNano,
                        qpsNano[0], qpsNano[1], qpsNano[0] / qpsOurs[0]);
            const bool same = nano.full == ours.full && std::abs(nano.sumKth - ours.sumKth) <= 1e-6 * ours.sumKth;
            std::printf("%-10s checksum: sum of the k-th squared distances %.9g (ours) %.9g (nanoflann)%s\n", "",
                        ours.sumKth, nano.sumKth, same ? "" : "  DIFFERENT");
            if (!same) status = 1;
#else
            std::printf("%-10s checksum: sum of the k-th squared distances %.9g, %ld queries found k\n", "",
                        ours.sumKth, ours.full);
#endif
        }
        std::printf(
            "\nbytes: the tree's array per photon (ours: %zu-byte photons in heap order, node 0 unused); "
            "q/s: queries per second (best of %d); ours/nano: our query time over nanoflann's, 1 thread\n",
            sizeof(Photon), runs);
        return status;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon_bench: %s\n", e.what());
        return 1;
    }
}
