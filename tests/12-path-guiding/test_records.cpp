// Lesson 12, graded: what a camera sample teaches the field (Eq. 12.12, 12.13): the records of a
// hand-made tree of eight vertices — a light sample added at most vertices, emission found three
// times (MIS-weighted below its full value), a mirror whose bounce gives no record, a split into
// two branches, a sample the roulette ended, a black channel of a throughput, the escape — against
// values computed by hand from the tree.
#include "lesson12.h"

using namespace lesson12;

TEST_CASE(
    "radiance records: the radiance along each sampled direction, over the throughput and the pdf (Eq. 12.12, 12.13) [2 pts]") {
    std::vector<ps::GuideVertex> t(8);
    // x0: the camera ray's vertex, no sample led here; its light sample 0.3
    t[0].added = Color(0.3f);
    // x1: sampled from x0 (cell 7); emission found here 1.0 (0.25 after MIS), its light sample (0.5, 0.4, 0.3)
    t[1].from = 0, t[1].cell = 7, t[1].side = 3, t[1].wi = Vec3(0, 0, 1), t[1].pdf = 0.5f,
    t[1].throughput = Color(0.8f, 0.4f, 0.2f);
    t[1].emitted = Color(0.25f), t[1].emittedFull = Color(1.0f), t[1].added = Color(0.25f) + Color(0.5f, 0.4f, 0.3f);
    // x2: sampled from x1 (cell 2), a mirror: nothing added
    t[2].from = 1, t[2].cell = 2, t[2].wi = Vec3(1, 0, 0), t[2].pdf = 2.0f, t[2].throughput = Color(0.5f, 0.0f, 0.25f);
    // x3: reached from the mirror by a delta bounce (no record); emission 0.6 in full, 0.6 added (weight 1)
    t[3].from = 2, t[3].cell = -1, t[3].throughput = Color(0.5f, 0.0f, 0.25f);
    t[3].emitted = t[3].emittedFull = Color(0.6f, 0.4f, 0.2f), t[3].added = Color(0.6f, 0.4f, 0.2f) + Color(0.1f);
    // x4: sampled from x3 (cell 9), light sample 0.05
    t[4].from = 3, t[4].cell = 9, t[4].wi = Vec3(0, 1, 0), t[4].pdf = 0.25f, t[4].throughput = Color(0.2f, 0.05f, 0.1f);
    t[4].added = Color(0.05f);
    // x5: the second continuation of x1 (a split), sampled from x1 (cell 2), light sample 0.2
    t[5].from = 1, t[5].cell = 2, t[5].side = 5, t[5].wi = Vec3(0, 0, -1), t[5].pdf = 1.0f,
    t[5].throughput = Color(0.3f);
    t[5].added = Color(0.2f);
    // x6: sampled from x5 (cell 4), ended by the roulette before it reached anything
    t[6].from = 5, t[6].cell = 4, t[6].wi = Vec3(0, -1, 0), t[6].pdf = 0.5f, t[6].throughput = Color(0.1f);
    // x7: sampled from x5 again (cell 4): the escape, the background 0.08 in full, 0.02 after MIS
    t[7].from = 5, t[7].cell = 4, t[7].wi = Vec3(-1, 0, 0), t[7].pdf = 0.125f, t[7].throughput = Color(0.15f);
    t[7].emitted = Color(0.02f), t[7].emittedFull = Color(0.08f), t[7].added = Color(0.02f);

    // By hand: L = the sum of `added` over the vertex's branch - its emitted + its emittedFull,
    // divided by the throughput channel by channel, the mean of the channels, over the pdf.
    const auto rec = [](const Color& L, const Color& th, float pdf) {
        const double r = th.r > 0 ? double(L.r) / th.r : 0.0, g = th.g > 0 ? double(L.g) / th.g : 0.0,
                     b = th.b > 0 ? double(L.b) / th.b : 0.0;
        return (r + g + b) / 3.0 / pdf;
    };
    Color all(0.0f);
    for (int j = 1; j < 8; ++j) all += t[size_t(j)].added;
    struct Want {
        size_t j;
        double value;
        const char* note;
    };
    const std::vector<Want> want = {
        {1, rec(all - t[1].emitted + t[1].emittedFull, t[1].throughput, 0.5f),
         "x1: both branches after it, its emission in full, not x0's light sample"},
        {2, rec(t[2].added + t[3].added + t[4].added, t[2].throughput, 2.0f),
         "x2: its branch through the mirror, not x1's other branch; a black channel of the throughput gives 0"},
        {4, rec(t[4].added, t[4].throughput, 0.25f), "x4: only what x4 added"},
        {5, rec(t[5].added + t[6].added + t[7].added, t[5].throughput, 1.0f), "x5: the second branch of the split"},
        {6, 0.0, "x6: a sample the roulette ended records 0"},
        {7, rec(t[7].added - t[7].emitted + t[7].emittedFull, t[7].throughput, 0.125f),
         "x7: the escape's background in full"}};
    std::vector<ps::RadianceRecord> out(1);  // one record already there: the sample's are appended
    out[0].cell = 99;
    ps::radianceRecords(t, out);
    REQUIRE_MESSAGE(out.size() == 1 + want.size(),
                    "radianceRecords of a tree of 8 vertices, 6 sampled at a vertex with "
                    "a cell, appended to a list of 1: expected "
                        << 1 + want.size() << " records, got " << out.size());
    CHECK_MESSAGE(out[0].cell == 99,
                  "radianceRecords: the records must be appended, the list's first entry was changed");
    for (size_t k = 0; k < want.size(); ++k) {
        const ps::RadianceRecord& r = out[1 + k];
        const ps::GuideVertex& v = t[want[k].j];
        CHECK_MESSAGE((r.cell == v.cell && r.side == v.side && glm::length(r.wi - v.wi) == 0.0f),
                      "radianceRecords: record " << k << " expected cell " << v.cell << ", side " << v.side
                                                 << " and direction " << str(v.wi) << " (x" << want[k].j
                                                 << "'s), got cell " << r.cell << ", side " << r.side << " and "
                                                 << str(r.wi));
        CHECK_MESSAGE(std::abs(r.value - want[k].value) <= 1e-5 * want[k].value + 1e-7,
                      "radianceRecords: record " << k << " (" << want[k].note << ") expected value "
                                                 << num(want[k].value)
                                                 << " (the radiance over the throughput, over the pdf: Eq. 12.12, "
                                                    "12.13), got "
                                                 << num(r.value));
    }
}
