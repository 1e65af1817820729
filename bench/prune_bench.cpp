// prune_bench: what lesson 7's pruning (Eq. 7.12 in lessons/07-bidirectional/README.md) saves.
// For a few scenes it renders the same number of iterations of `bpt` with the scene's
// capabilities used to leave out techniques that cannot contribute (the default) and with
// `--no-prune` (every technique tried), and prints the wall time and pixel samples per second
// of both, the rays each traced (deterministic: the same in every run) and what pruning saved of
// each. A benchmark, never a test: nothing is timed against a threshold (pruning's
// exactness is tested in tests/07-bidirectional/test_robust.cpp). bench/README.md lists the
// figures measured on the course machine.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>
#include "integrator.h"
#include "render.h"
#include "bench_common.h"

#ifndef PATHSPACE_SOURCE_DIR
#define PATHSPACE_SOURCE_DIR "."
#endif

namespace {

// Best wall time of `repeats` renders; rays: the rays traced (the same in every run).
double timeBpt(const ps::Scene& scene, int spp, int threads, int repeats, uint64_t& rays) {
    double best = 1e30;
    for (int run = 0; run < repeats; ++run) {
        std::unique_ptr<ps::Integrator> bpt = ps::makeIntegrator("bpt");
        ps::RenderOptions opt;
        opt.spp = spp;
        opt.seed = 1;
        opt.threads = threads;
        const ps::RenderResult r = ps::render(scene, *bpt, opt);
        best = std::min(best, r.seconds);
        rays = r.stats.rays;
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    std::string dir = std::string(PATHSPACE_SOURCE_DIR) + "/scenes";
    int res = 64, spp = 16, threads = 1, repeats = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") {
            res = 16;
            spp = 2;
            repeats = 1;
        } else if (a == "--scenes" && i + 1 < argc) dir = argv[++i];
        else if (a == "--threads" && i + 1 < argc) threads = std::stoi(argv[++i]);
        else if (a == "--spp" && i + 1 < argc) spp = std::stoi(argv[++i]);
        else {
            std::printf(
                "usage: prune_bench [--quick] [--scenes DIR] [--threads T] [--spp N]\n"
                "  bpt with and without pruning on a few scenes at %d x %d, %d spp, best of %d runs\n",
                res, res, spp, repeats);
            return a == "--help" ? 0 : 2;
        }
    }
    try {
        std::printf("bpt, %d x %d pixels, %d spp, %d thread(s), best of %d runs\n", res, res, spp, threads, repeats);
        std::printf("%-20s %9s %11s %10s %9s %11s %10s %7s %7s  %s\n", "scene", "pruned s", "samples/s", "Mrays",
                    "full s", "samples/s", "Mrays", "time", "rays", "left out");
        for (const std::string name : {"cornell-box", "cornell-point-light", "cornell-spheres", "glass-lamp"}) {
            ps::Scene pruned = bench::loadSceneAt(dir + "/" + name + ".scene", res);
            ps::Scene full = pruned;
            full.settings.prune = false;
            uint64_t rp = 0, rf = 0;
            const double tp = timeBpt(pruned, spp, threads, repeats, rp), tf = timeBpt(full, spp, threads, repeats, rf);
            const double samples = double(res) * res * spp;
            const std::vector<std::string> left = ps::makeIntegrator("bpt")->leftOut(pruned);
            std::printf("%-20s %9.3f %11.0f %10.3f %9.3f %11.0f %10.3f %6.1f%% %6.1f%%  %zu item(s)\n", name.c_str(),
                        tp, samples / tp, rp * 1e-6, tf, samples / tf, rf * 1e-6, 100.0 * (tf - tp) / tf,
                        100.0 * (double(rf) - double(rp)) / double(rf), left.size());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "prune_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
