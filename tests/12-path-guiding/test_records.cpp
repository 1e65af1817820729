// Lesson 12, graded: what a camera path teaches the field (Eq. 12.12, 12.13): the records of a
// hand-made path of six vertices — a light sample at every vertex, emission found twice (once
// MIS-weighted below its full value), a mirror without a cell, a black channel of a throughput,
// the escape — against values computed by hand.
#include "lesson12.h"

using namespace lesson12;

TEST_CASE("radiance records: the radiance along each sampled direction, over the throughput and the pdf (Eq. 12.12, 12.13) [2 pts]") {
    std::vector<ps::GuideVertex> path(6);
    // x0: diffuse, cell 7, its light sample added 0.3
    path[0].cell = 7, path[0].wi = Vec3(0, 0, 1), path[0].pdf = 0.5f, path[0].throughput = Color(0.8f, 0.4f, 0.2f);
    path[0].added = Color(0.3f);
    // x1: cell 2; the emission found here is 1 (MIS weight 0.25: added 0.25 of it), its light sample 0.5
    path[1].cell = 2, path[1].wi = Vec3(1, 0, 0), path[1].pdf = 2.0f, path[1].throughput = Color(0.5f, 0.0f, 0.25f);
    path[1].emitted = Color(0.25f), path[1].emittedFull = Color(1.0f);
    path[1].added = Color(0.25f) + Color(0.5f, 0.4f, 0.3f);
    // x2: a mirror, no cell, nothing added
    path[2].cell = -1, path[2].throughput = Color(0.5f, 0.1f, 0.25f);
    // x3: cell 2 again; the emission found here (0.6 in full, 0.45 after MIS), its light sample 0.1
    path[3].cell = 2, path[3].wi = Vec3(0, 1, 0), path[3].pdf = 0.25f, path[3].throughput = Color(0.2f, 0.05f, 0.1f);
    path[3].emitted = Color(0.45f, 0.3f, 0.15f), path[3].emittedFull = Color(0.6f, 0.4f, 0.2f);
    path[3].added = path[3].emitted + Color(0.1f);
    // x4: cell 9, light sample 0.05
    path[4].cell = 9, path[4].wi = Vec3(0, 0, -1), path[4].pdf = 1.0f, path[4].throughput = Color(0.1f);
    path[4].added = Color(0.05f);
    // x5: the escape: the background, 0.02 after MIS, 0.08 in full
    path[5].cell = -1, path[5].emitted = Color(0.02f), path[5].emittedFull = Color(0.08f), path[5].added = Color(0.02f);

    // By hand: L_k = sum of added_j for j > k - emitted_{k+1} + emittedFull_{k+1}, divided by the
    // throughput channel by channel, the mean of the channels, divided by the pdf.
    const auto rec = [](const Color& L, const Color& t, float pdf) {
        const double r = t.r > 0 ? double(L.r) / t.r : 0.0, g = t.g > 0 ? double(L.g) / t.g : 0.0,
                     b = t.b > 0 ? double(L.b) / t.b : 0.0;
        return (r + g + b) / 3.0 / pdf;
    };
    const Color after0 = path[1].added + path[2].added + path[3].added + path[4].added + path[5].added;
    const Color L0 = after0 - path[1].emitted + path[1].emittedFull;
    const Color after1 = path[2].added + path[3].added + path[4].added + path[5].added;
    const Color L1 = after1;  // x2, the mirror, found no emission
    const Color after3 = path[4].added + path[5].added;
    const Color L3 = after3;
    const Color L4 = path[5].added - path[5].emitted + path[5].emittedFull;
    const std::vector<std::pair<int, double>> want = {{7, rec(L0, path[0].throughput, 0.5f)},
                                                      {2, rec(L1, path[1].throughput, 2.0f)},
                                                      {2, rec(L3, path[3].throughput, 0.25f)},
                                                      {9, rec(L4, path[4].throughput, 1.0f)}};
    std::vector<ps::RadianceRecord> out(1);  // one record already there: the path's are appended
    out[0].cell = 99;
    ps::radianceRecords(path, out);
    REQUIRE_MESSAGE(out.size() == 1 + want.size(), "radianceRecords of a path of 6 vertices, 4 with a cell, appended to "
                                                   "a list of 1: expected "
                                                       << 1 + want.size() << " records, got " << out.size());
    CHECK_MESSAGE(out[0].cell == 99, "radianceRecords: the records must be appended, the list's first entry was changed");
    const char* notes[] = {"x0: x1's emission counts in full; x0's own light sample is not along wi",
                           "x1: a black channel of the throughput gives 0 in that channel",
                           "x3: the vertices after it only", "x4: the escape's background in full"};
    for (size_t k = 0; k < want.size(); ++k) {
        const ps::RadianceRecord& r = out[1 + k];
        const ps::GuideVertex& v = path[k == 0 ? 0 : k == 1 ? 1 : k == 2 ? 3 : 4];
        CHECK_MESSAGE((r.cell == want[k].first && glm::length(r.wi - v.wi) == 0.0f),
                      "radianceRecords: record " << k << " expected cell " << want[k].first << " and direction "
                                                 << str(v.wi) << ", got cell " << r.cell << " and " << str(r.wi));
        CHECK_MESSAGE(std::abs(r.value - want[k].second) <= 1e-5 * want[k].second,
                      "radianceRecords: record " << k << " (" << notes[k] << ") expected value " << num(want[k].second)
                                                 << " (radiance over throughput, over pdf: Eq. 12.13), got "
                                                 << num(r.value));
    }
}
