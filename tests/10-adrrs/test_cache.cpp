// Lesson 10, graded: the adjoint cache (Eq. 10.8): the cell and side of hand-placed points, and the
// pre-pass's samples of one hand-made path.
#include "lesson10.h"

using namespace lesson10;

TEST_CASE("adjoint cache: the cell and the side of hand-placed points (Eq. 10.8) [1 pt]") {
    ps::AABB box;
    box.lo = Vec3(0.0f);
    box.hi = Vec3(2.0f, 4.0f, 8.0f);
    const ps::AdjointCache cache(box, 4);
    struct CellCase {
        Vec3 p;
        int cell;
        const char* what;
    };
    for (const CellCase& c :
         {CellCase{Vec3(0.1f, 1.1f, 7.9f), 0 + 4 * (1 + 4 * 3), "inside: cell (0, 1, 3)"},
          CellCase{Vec3(1.0f, 2.0f, 4.0f), 2 + 4 * (2 + 4 * 2), "the box's centre: (2, 2, 2)"},
          CellCase{Vec3(2.0f, 4.0f, 8.0f), 63, "the far corner: the last cell (3, 3, 3)"},
          CellCase{Vec3(-1e-6f, 0.0f, 8.00001f), 0 + 4 * (0 + 4 * 3), "a rounding error outside: clamped to (0, 0, 3)"},
          CellCase{Vec3(1.9f, 0.5f, 0.1f), 3 + 4 * (0 + 4 * 0), "cell (3, 0, 0)"}}) {
        const int got = cache.cell(c.p);
        CHECK_MESSAGE(got == c.cell, "AdjointCache over [(0, 0, 0), (2, 4, 8)], 4^3 cells: cell"
                                         << str(c.p) << " expected " << c.cell << " (" << c.what
                                         << ": ix + 4 (iy + 4 iz)), got " << got);
    }
    ps::AABB shifted;
    shifted.lo = Vec3(-1.0f, -2.0f, -3.0f);
    shifted.hi = Vec3(1.0f, 2.0f, 5.0f);
    const int centre = ps::AdjointCache(shifted, 4).cell(Vec3(0.0f));
    CHECK_MESSAGE(centre == 2 + 4 * (2 + 4 * 1),
                  "AdjointCache over [(-1, -2, -3), (1, 2, 5)], 4^3 cells: cell(0, 0, 0) "
                  "expected 26 (cell (2, 2, 1): measured from the box's lower corner), "
                  "got "
                      << centre);
    ps::AABB flat;
    flat.lo = Vec3(0.0f);
    flat.hi = Vec3(1.0f, 0.0f, 1.0f);
    const ps::AdjointCache flatCache(flat, 2);
    const int got = flatCache.cell(Vec3(0.7f, 0.0f, 0.2f));
    CHECK_MESSAGE(got == 1,
                  "AdjointCache over a flat box [(0, 0, 0), (1, 0, 1)], 2^3 cells: cell(0.7, 0, 0.2) "
                  "expected 1 (iy = 0 along the flat axis), got "
                      << got);

    struct SideCase {
        Vec3 n, wo;
        int side;
        const char* what;
    };
    const float h = std::sqrt(0.5f);
    for (const SideCase& c :
         {SideCase{Vec3(0, 0, 1), Vec3(0, 0.1f, 1), 4, "+z seen from +z"},
          SideCase{Vec3(0, 0, 1), Vec3(0, 0.1f, -1), 5, "the back of a +z surface: -z"},
          SideCase{Vec3(0.6f, -0.8f, 0), Vec3(1, 0, 0), 3, "dominant axis y, negative"},
          SideCase{Vec3(0.6f, -0.8f, 0), Vec3(-1, 0, 0), 2, "turned towards wo: (-0.6, 0.8, 0), +y"},
          SideCase{Vec3(-1, 0, 0), Vec3(-0.2f, 0.9f, 0.1f), 1, "-x seen from its own side"},
          SideCase{Vec3(h, h, 0), Vec3(h, h, 0), 0, "x and y equal: the first, +x"}}) {
        const int got = ps::AdjointCache::side(c.n, c.wo);
        CHECK_MESSAGE(got == c.side, "AdjointCache::side(n " << str(c.n) << ", wo " << str(c.wo) << "): expected "
                                                             << c.side << " (" << c.what
                                                             << "; 2 axis + (1 if negative)), got " << got);
    }
    const int e = cache.entry(Vec3(0.1f, 1.1f, 7.9f), Vec3(0, 0, 1), Vec3(0, 0, -1));
    CHECK_MESSAGE(e == 52 * ps::kCacheSides + 5,
                  "entry = cell * 6 + side: expected " << 52 * ps::kCacheSides + 5 << ", got " << e);
}

TEST_CASE(
    "adjoint cache: the pre-pass samples what a path collects from each vertex on, over its throughput (Eq. 10.8) [1 pt]") {
    // x0 .. x4: a path of four hits (x2 a mirror: no entry) and the escape.
    std::vector<ps::PrePassVertex> path(5);
    const int entries[5] = {10, 20, -1, 30, -1};
    // Black channels of beta: blue at x1, red and green at x3 (each channel's guard once).
    const Color beta[5] = {Color(1.0f), Color(0.5f, 0.25f, 0.0f), Color(0.25f), Color(0.0f, 0.0f, 0.125f), Color(0.1f)};
    const Color added[5] = {Color(0.5f), Color(0.1f, 0.2f, 0.3f), Color(0.0f), Color(1.0f), Color(0.2f)};
    for (int k = 0; k < 5; ++k) path[size_t(k)] = {entries[k], beta[k], added[k]};
    std::vector<ps::CacheSample> out;
    out.push_back({7, Color(9.0f)});  // already there: must stay
    ps::continuationSamples(path, out);
    struct Want {
        int entry;
        Color value;
        const char* what;
    };
    const Want want[] = {{7, Color(9.0f), "the sample that was in the list before"},
                         {10, Color(1.8f, 1.9f, 2.0f), "x0: (added_0 + ... + added_4) / beta_0"},
                         {20, Color(2.6f, 5.6f, 0.0f), "x1: (added_1 + ... + added_4) / beta_1, 0 where beta_1 is 0"},
                         {30, Color(0.0f, 0.0f, 9.6f), "x3: (added_3 + added_4) / beta_3, 0 where beta_3 is 0"}};
    REQUIRE_MESSAGE(out.size() == 4,
                    "continuationSamples of a path with 3 vertices that have an entry (x0, x1, x3): "
                    "expected 3 samples appended to a list of 1, got a list of "
                        << out.size());
    for (int i = 0; i < 4; ++i) {
        const ps::CacheSample& s = out[size_t(i)];
        const Want& w = want[i];
        const bool ok = s.entry == w.entry && std::abs(s.value.r - w.value.r) <= 1e-6f * (1 + w.value.r) &&
                        std::abs(s.value.g - w.value.g) <= 1e-6f * (1 + w.value.g) &&
                        std::abs(s.value.b - w.value.b) <= 1e-6f * (1 + w.value.b);
        CHECK_MESSAGE(ok, "continuationSamples, sample " << i << ": expected entry " << w.entry << " value "
                                                         << str(w.value) << " (" << w.what << "), got entry " << s.entry
                                                         << " value " << str(s.value));
    }
}
